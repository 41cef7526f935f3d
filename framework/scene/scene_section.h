// A top-level key of scene files owned by a plug-in: coupling/ reads "bodies" this way, so the
// framework reads and builds scenes without knowing what a mesh or a rigid body is.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace upf {

class JsonInput;
class World;
struct SceneDescription;

// What a section's reader checked and kept for its builder.
struct SceneSectionData {
  virtual ~SceneSectionData() = default;
  // Particles the section will add, for the memory estimate made before anything is built.
  virtual double estimated_particles() const { return 0; }
  // Whether the section brings something that moves (a scene needs one): its particles, or
  // liquid it pours in later (emitters).
  virtual bool moves() const { return estimated_particles() > 0; }
};

struct SceneSection {
  std::string key;  // the top-level key: "bodies"
  std::string summary;
  // Reads scene[key] (at JSON path `path`) once materials, spacing and containers are read.
  // Every problem goes to `input`; the result may then be null.
  std::function<std::shared_ptr<const SceneSectionData>(
      const nlohmann::json& node, const std::string& path, const SceneDescription& scene,
      JsonInput& input)>
      read;
  // Adds the section's particles and body systems to the world, after the fluid blocks.
  std::function<void(World& world, const SceneDescription& scene, const SceneSectionData& data)>
      build;
};

// A section as read from one scene.
struct SceneSectionEntry {
  std::string key;
  std::shared_ptr<const SceneSectionData> data;
};

}  // namespace upf
