// Bodies in scene files through the `upf` program: broken meshes are bad input (exit code 2,
// the file named), and a run with bodies writes bodies.csv and the body meshes into the frames.
#include <fstream>
#include <sstream>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

const std::string kMeshes = std::string(UPF_SOURCE_DIR) + "/tests/data/meshes/";
const std::string kAssets = std::string(UPF_SOURCE_DIR) + "/assets/meshes/";

class Bodies : public Cli {
 protected:
  // The small dam break with one body of `material` made from `mesh`.
  nlohmann::json with_body(const std::string& mesh, const std::string& material = "wood") const {
    nlohmann::json doc = sample();
    doc["materials"]["wood"] = {{"type", "rigid"}, {"density", 500}};
    doc["bodies"] = {{{"name", "crate"},
                      {"material", material},
                      {"mesh", {{"file", mesh}, {"scale", 0.2}, {"position", {1.2, 0.5, 0.2}}}}}};
    return doc;
  }
};

// The shipped body and granular samples load, and every mesh in them is found, measured and
// sampled.
TEST(BodySamples, ValidateCleanly) {
  for (const char* name : {"floating_objects.json", "mesh_splash.json", "dam_break_obstacles.json",
                           "granular_column.json", "sand_pile.json", "silo_discharge.json",
                           "sand_into_water.json", "spheric_test2.json"}) {
    const Result r = run_upf("validate " + std::string(UPF_SOURCE_DIR) + "/samples/" + name);
    EXPECT_EQ(r.code, 0) << name << ": " << r.output;
    EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
  }
}

TEST_F(Bodies, MissingMeshFileIsBadInputNamingTheFile) {
  expect_rejected(with_body(kMeshes + "no_such_mesh.obj"), {"/bodies/0/mesh", "no_such_mesh.obj"});
}

TEST_F(Bodies, UnsupportedFormatIsBadInputNamingTheFile) {
  expect_rejected(with_body(kMeshes + "not_a_mesh.txt"), {"/bodies/0/mesh", "not_a_mesh.txt"});
}

TEST_F(Bodies, EmptyMeshIsBadInputNamingTheFile) {
  expect_rejected(with_body(kMeshes + "empty.obj"), {"/bodies/0/mesh", "empty.obj"});
}

TEST_F(Bodies, OpenMeshForARigidBodyIsBadInputNamingTheFile) {
  expect_rejected(with_body(kMeshes + "open_box.obj"),
                  {"/bodies/0/mesh", "open_box.obj", "closed"});
}

TEST_F(Bodies, OpenMeshIsAcceptedAsAStaticObstacle) {
  // A frozen obstacle needs no volume: an open surface (a ramp, a half-pipe) is fine.
  const Result r = run_upf("validate " + write(with_body(kMeshes + "open_box.obj", "walls")));
  EXPECT_EQ(r.code, 0) << r.output;
}

TEST_F(Bodies, LiquidMaterialForABodyIsBadInput) {
  expect_rejected(with_body(kAssets + "unit_box.obj", "water"), {"/bodies/0/material", "liquid"});
}

TEST_F(Bodies, BodyOutsideEveryContainerIsBadInput) {
  nlohmann::json doc = with_body(kAssets + "unit_box.obj");
  doc["bodies"][0]["mesh"]["position"] = {5, 5, 5};
  expect_rejected(doc, {"/bodies/0/mesh", "not inside any container"});
}

TEST_F(Bodies, RunWritesBodiesCsvAndBodyMeshesInThePvdSeries) {
  const std::string out = (dir_ / "out").string();
  const Result r =
      run_upf("run " + write(with_body(kAssets + "unit_box.obj")) + " --end 0.05 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream csv(out + "/bodies.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,fx,fy,fz,tx,ty,tz,"
            "fx_mean,fy_mean,fz_mean,tx_mean,ty_mean,tz_mean");
  int rows = 0;
  while (std::getline(csv, row)) ++rows;
  EXPECT_GE(rows, 2);
  std::stringstream pvd;
  pvd << std::ifstream(out + "/particles.pvd").rdbuf();
  EXPECT_NE(pvd.str().find("frames/bodies_00000.vtp"), std::string::npos) << pvd.str();
  EXPECT_NE(pvd.str().find("part=\"1\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/frames/bodies_00001.vtp"));
}

// The numbers of a CSV row.
std::vector<double> csv_numbers(const std::string& row, std::size_t skip_after_first) {
  std::vector<double> values;
  std::stringstream in(row);
  std::string cell;
  for (std::size_t column = 0; std::getline(in, cell, ','); ++column)
    if (column == 0 || column > skip_after_first) values.push_back(std::stod(cell));
  return values;
}

// body_forces.csv has the fluid force of every step; bodies.csv's frame means are their
// integral over the frame interval divided by its length (the rectangle rule over the steps,
// each step's force held for its dt), and its last-step force is the last row before the frame.
TEST_F(Bodies, BodyForcesEveryStepAverageToTheFrameMean) {
  const std::string out = (dir_ / "out").string();
  nlohmann::json doc = with_body(kAssets + "unit_box.obj");
  doc["output"]["fps"] = 40;
  doc["bodies"][0]["mesh"]["position"] = {0.3, 0.4, 0.2};  // in the water column
  const Result r = run_upf("run " + write(doc) + " --end 0.1 --no-frames -q --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream steps(out + "/body_forces.csv"), frames(out + "/bodies.csv");
  std::string row;
  std::getline(steps, row);
  EXPECT_EQ(row, "time,body,name,fx,fy,fz,tx,ty,tz");
  std::vector<std::vector<double>> step_rows;  // t, fx..tz
  while (std::getline(steps, row)) step_rows.push_back(csv_numbers(row, 2));
  std::getline(frames, row);
  std::vector<std::vector<double>> frame_rows;  // t, x..tz, fx_mean..tz_mean
  while (std::getline(frames, row)) frame_rows.push_back(csv_numbers(row, 2));
  ASSERT_EQ(frame_rows.size(), 5u);  // t = 0, 0.025, ..., 0.1
  ASSERT_GT(step_rows.size(), 20u);
  double previous_frame = 0, previous_step = 0;
  std::size_t s = 0;
  int nonzero = 0;
  for (std::size_t f = 1; f < frame_rows.size(); ++f) {
    const double t = frame_rows[f][0];
    std::vector<double> integral(6, 0.0), last(6, 0.0);
    for (; s < step_rows.size() && step_rows[s][0] <= t + 1e-9; ++s) {
      const double dt = step_rows[s][0] - previous_step;
      previous_step = step_rows[s][0];
      for (int c = 0; c < 6; ++c) integral[c] += dt * step_rows[s][1 + c];
      last.assign(step_rows[s].begin() + 1, step_rows[s].end());
    }
    for (int c = 0; c < 6; ++c) {
      const double mean = integral[c] / (t - previous_frame);
      // The CSVs carry 9 significant digits.
      EXPECT_NEAR(frame_rows[f][20 + c], mean, 1e-6 * (std::abs(mean) + 1e-3))
          << "frame at " << t << ", component " << c;
      EXPECT_NEAR(frame_rows[f][14 + c], last[c], 1e-6 * (std::abs(last[c]) + 1e-3));
      nonzero += frame_rows[f][20 + c] != 0;
    }
    previous_frame = t;
  }
  EXPECT_GT(nonzero, 4);  // the box is in water: the means are forces, not zeros
}

}  // namespace
}  // namespace upf::cli_test

namespace upf::cli_test {
namespace {

// Found by tests/fuzz/fuzz_scene.cpp: a granular block whose min lies 1e20 m beyond its max made
// the grain count overflow its integer (undefined behaviour) before the check could reject it.
TEST_F(Cli, InvertedHugeGranularBlockIsBadInput) {
  std::ifstream in(fs::path(UPF_SOURCE_DIR) / "samples" / "sand_pile.json");
  auto doc = nlohmann::json::parse(in);
  doc["granular_blocks"][0]["min"][0] = 1e20;
  expect_rejected(doc, {"/granular_blocks/0/max", "thinner than one grain diameter"});
}

// A random packing's settings: a known packing name, a fraction in (0, 0.3], and no random-only
// keys on a lattice block; each refused with its path.
TEST_F(Cli, GranularPackingSettingsAreChecked) {
  std::ifstream in(fs::path(UPF_SOURCE_DIR) / "samples" / "sand_pile.json");
  const auto sand = nlohmann::json::parse(in);
  auto doc = sand;
  doc["granular_blocks"][0]["packing"] = "randm";
  expect_rejected(doc, {"/granular_blocks/0/packing", "unknown packing 'randm'"});
  doc = sand;
  doc["granular_blocks"][0]["packing"] = "random";
  doc["granular_blocks"][0]["solid_fraction"] = 0.5;
  expect_rejected(doc, {"/granular_blocks/0/solid_fraction"});
  doc = sand;
  doc["granular_blocks"][0]["seed"] = 3;
  expect_rejected(doc, {"/granular_blocks/0", "belong to \"packing\": \"random\""});
  doc = sand;
  doc["granular_blocks"][0]["packing"] = "random";
  const Result r = run_upf("validate " + write(doc));
  EXPECT_EQ(r.code, 0) << r.output;
}

}  // namespace
}  // namespace upf::cli_test
