// What pictures need from a scene file (or a run's copy of it, RUN_DIR/upf_scene.json): its name,
// particle spacing, vertical (opposite to gravity), frame rate and "render" section. Shared by
// `upf render` and `upf view`.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

#include "render/render_settings.h"

namespace upf::render {

struct SceneFacts {
  std::string name;
  std::optional<double> spacing;
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  std::optional<double> fps;
  RenderSettings settings;
};

// Reads `json_file`; a missing file gives the defaults named `fallback_name`, and so does a name
// that cannot be a file name (file_name.h: the name names the video). Throws InputError
// for a file that is not a JSON object or has a bad "render" section.
SceneFacts read_scene_facts(const std::filesystem::path& json_file, std::string fallback_name);

// The run's record of its scene: RUN_DIR/upf_scene.json, or scene.json in runs made before it
// had a name of its own.
std::filesystem::path scene_record(const std::filesystem::path& run_dir);

// A run's name when it has no scene record: its directory's name.
std::string run_directory_name(const std::filesystem::path& run_dir);

}  // namespace upf::render
