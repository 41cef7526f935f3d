// What `upf view` shows: the saved frames of a run (RUN_DIR/particles.pvd), or a scene file
// stepped live in a World. Both give a render::FrameData for the ray tracer. No GL here.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/world.h"
#include "render/frame_picture.h"
#include "render/render_settings.h"
#include "render/run_frames.h"
#include "render/scene_facts.h"

namespace upf::viewer {

using ViewFacts = render::SceneFacts;

// A finished run's frames, one at a time.
class RunFrames {
 public:
  // Throws InputError when RUN_DIR has no readable particles.pvd or its first frame is damaged.
  explicit RunFrames(const std::filesystem::path& run_dir);
  const ViewFacts& facts() const { return facts_; }
  int count() const { return int(frames_.size()); }
  int index() const { return index_; }
  void show(int k);  // reads frame k (clamped)
  const render::FrameData& frame() const { return frame_; }

 private:
  ViewFacts facts_;
  std::vector<render::RunFrame> frames_;
  int index_ = 0;
  render::FrameData frame_;
};

// A scene stepped live. Parameter edits go to edited(); restart() builds the world again from it.
class LiveScene {
 public:
  // Throws InputError for a missing or invalid scene file.
  LiveScene(const std::filesystem::path& scene_file, const Registry& registry, int threads);
  const ViewFacts& facts() const { return facts_; }
  SceneDescription& edited() { return edited_; }
  const Registry& registry() const { return registry_; }
  // Builds the world from edited() at time 0. A failure is kept in error().
  void restart();
  // Steps until `sim_seconds` have passed or `wall_seconds` of work were done (at least one
  // step). An instability stops it: false, with the message in error().
  bool advance(double sim_seconds, double wall_seconds);
  const World* world() const { return world_.get(); }
  const render::FrameData& frame() const { return frame_; }
  const std::string& error() const { return error_; }

 private:
  void convert();

  const Registry& registry_;
  int threads_;
  ViewFacts facts_;
  SceneDescription edited_;
  std::unique_ptr<World> world_;
  render::FrameData frame_;
  std::string error_;
};

}  // namespace upf::viewer
