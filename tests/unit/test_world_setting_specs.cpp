// The scene reader checks /time, /stability, /neighbours and /output against the world-setting
// specs, and the specs' defaults are the settings a scene gets without those keys: what `upf info`
// and the reference pages print is what the reader enforces.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "framework/scene/world_setting_specs.h"
#include "tests/physics/scene_helpers.h"

namespace upf {
namespace {

// The problems the reader reports at `where` for `doc`, joined; empty when there are none.
std::string problems_at(const nlohmann::json& doc, const std::string& where) {
  std::string found;
  try {
    read_scene(doc, testing::builtin_registry(), "test");
  } catch (const InputError& e) {
    for (const auto& p : e.problems())
      if (p.where == "test:" + where) found += p.message + "\n";
  }
  return found;
}

nlohmann::json small_scene() {
  auto doc = testing::load_sample_json("dam_break.json");
  doc["particle_spacing"] = 0.05;
  return doc;
}

// The range as the reader's messages write it: "(0, 1]" or "[0, 10] s".
std::string message_range(const ParamSpec& spec) {
  std::ostringstream range;
  range << (spec.exclusive_min ? "(" : "[") << spec.min_value << ", " << spec.max_value << "]";
  if (spec.unit != "1") range << " " << spec.unit;
  return range.str();
}

TEST(WorldSettingSpecs, ReaderRefusesOutOfRangeCflWithTheSpecRange) {
  const auto specs = time_setting_specs();
  const ParamSpec* cfl = find_spec(specs, "cfl");
  ASSERT_NE(cfl, nullptr);
  auto doc = small_scene();
  doc["time"]["cfl"] = 1.5;
  EXPECT_EQ(problems_at(doc, "/time/cfl"),
            "value 1.5 is out of range " + message_range(*cfl) + "\n");
  EXPECT_EQ(message_range(*cfl), "(0, 1]");
}

TEST(WorldSettingSpecs, ReaderEnforcesEverySpecRangeAndItsOpenLowerBound) {
  for (const auto& section : world_setting_sections()) {
    for (const auto& spec : section.params) {
      const std::string key = section.path.substr(1);
      const std::string where = section.path + "/" + spec.name;
      auto above = small_scene();
      above[key][spec.name] = 2 * spec.max_value;
      EXPECT_NE(problems_at(above, where).find("out of range " + message_range(spec)),
                std::string::npos)
          << where << ": " << problems_at(above, where);
      auto at_min = small_scene();
      at_min[key][spec.name] = spec.min_value;
      EXPECT_EQ(problems_at(at_min, where).empty(), !spec.exclusive_min) << where;
    }
  }
}

TEST(WorldSettingSpecs, ReaderRefusesKeysTheSpecsDoNotName) {
  auto doc = small_scene();
  doc["time"]["cfll"] = 0.3;
  EXPECT_NE(problems_at(doc, "/time/cfll").find("did you mean 'cfl'"), std::string::npos);
}

TEST(WorldSettingSpecs, DefaultsAreTheSettingsOfASceneWithoutThem) {
  const WorldSettings world;
  const OutputDesc output;
  const auto time = time_setting_specs();
  EXPECT_EQ(find_spec(time, "end")->default_value, world.time.end);
  EXPECT_EQ(find_spec(time, "dt_min")->default_value, world.time.dt_min);
  EXPECT_EQ(find_spec(time, "dt_max")->default_value, world.time.dt_max);
  EXPECT_EQ(find_spec(time, "cfl")->default_value, world.time.cfl);
  EXPECT_EQ(find_spec(time, "fixed_dt")->default_value, world.time.fixed_dt);
  EXPECT_EQ(stability_setting_specs().at(0).default_value, world.max_speed);
  EXPECT_EQ(neighbour_setting_specs().at(0).default_value, double(world.reorder_every));
  const auto out = output_setting_specs();
  EXPECT_EQ(find_spec(out, "fps")->default_value, output.fps);
  EXPECT_EQ(find_spec(out, "size_warning")->default_value, output.size_warning_gb);
  EXPECT_EQ(find_spec(out, "surface_voxel")->default_value, output.surface_voxel);
  EXPECT_EQ(find_spec(out, "surface_memory")->default_value, output.surface_memory_gb);
  EXPECT_EQ(find_spec(out, "probe_every")->default_value, double(output.probe_every));
  // One spec per number the reader reads: a new key gets a spec, or this count trips.
  EXPECT_EQ(time.size() + stability_setting_specs().size() + neighbour_setting_specs().size() +
                out.size(),
            12u);
}

}  // namespace
}  // namespace upf
