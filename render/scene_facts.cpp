#include "render/scene_facts.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/core/errors.h"
#include "framework/core/file_name.h"
#include "framework/run/run_manifest.h"
#include "framework/scene/json_input.h"

namespace upf::render {

namespace fs = std::filesystem;

fs::path scene_record(const fs::path& run_dir) {
  std::error_code ec;
  const fs::path record = run_dir / kSceneRecordFile;
  return fs::exists(record, ec) ? record : run_dir / "scene.json";
}

std::string run_directory_name(const fs::path& run_dir) {
  std::string name = fs::absolute(run_dir).lexically_normal().filename().string();
  if (name.empty())
    name = fs::absolute(run_dir).lexically_normal().parent_path().filename().string();
  return name;
}

SceneFacts read_scene_facts(const fs::path& json_file, std::string fallback_name) {
  SceneFacts facts;
  facts.name = file_name_problem(fallback_name) ? std::string("run") : std::move(fallback_name);
  std::ifstream in(json_file);
  if (!in) return facts;  // an older run: defaults
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.is_object())
    throw InputError(json_file.string(), "not a JSON object");
  if (auto n = doc.find("name");
      n != doc.end() && n->is_string() && !file_name_problem(n->get<std::string>()))
    facts.name = *n;
  if (auto s = doc.find("particle_spacing"); s != doc.end() && s->is_number() && *s > 0)
    facts.spacing = s->get<double>();
  if (auto g = doc.find("gravity"); g != doc.end() && g->is_array() && g->size() == 3) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (std::size_t a = 0; a < 3; ++a)
      if ((*g)[a].is_number()) v[Eigen::Index(a)] = (*g)[a].get<double>();
    if (v.norm() > 0) facts.up = -v.normalized();
  }
  if (auto o = doc.find("output"); o != doc.end() && o->is_object())
    if (auto f = o->find("fps"); f != o->end() && f->is_number() && *f > 0)
      facts.fps = f->get<double>();
  if (auto r = doc.find("render"); r != doc.end()) {
    std::vector<InputProblem> problems;
    JsonInput input(problems);
    read_render_settings(*r, "/render", input, facts.settings);
    if (!problems.empty()) {
      for (auto& p : problems) p.where = json_file.string() + ":" + p.where;
      throw InputError(std::move(problems));
    }
  }
  return facts;
}

}  // namespace upf::render
