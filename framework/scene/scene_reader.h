// Reads and validates a scene file. Every problem is reported with its JSON path (and the file),
// all at once, as one InputError (exit code 2).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"

namespace upf {

// Reads `path`: missing file, JSON syntax error (with line and column) or invalid content throw
// InputError naming the file.
SceneDescription load_scene_file(const std::filesystem::path& path, const Registry& registry);

// The file's JSON, not yet checked as a scene: InputError for a missing file or a syntax error
// (with line and column). For callers that change the document first (scene_overrides.h).
nlohmann::json read_scene_json(const std::filesystem::path& path);

// Validates an already parsed document; `source` names it in messages.
SceneDescription read_scene(const nlohmann::json& document, const Registry& registry,
                            const std::string& source);

// Bytes of memory the estimate charges per particle (arrays, neighbour lists, snapshot).
inline constexpr double kEstimatedBytesPerParticle = 1024;

}  // namespace upf
