// What a run writes about the world's bodies: bodies.csv, one row per body per frame (pose,
// velocities, fluid force and torque), and frames/bodies_NNNNN.vtp, the bodies' surfaces in
// their poses for the frame's .pvd entry. The body systems only report (BodySystem::body_states,
// surface_meshes); writing and resuming the files is the run's, like metrics.csv.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "framework/output/resumed_log.h"
#include "framework/world/world.h"

namespace upf {

class BodyOutputs {
 public:
  // Writes nothing for a world without body systems; surfaces only when `write_meshes`.
  // `resuming`: bodies.csv is left alone until restore_state.
  BodyOutputs(const std::filesystem::path& out_dir, const World& world, bool write_meshes,
              bool resuming);
  // The files written for frame `frame` (relative to the output directory), for the .pvd.
  std::vector<std::string> write_frame(int frame, double time);
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  std::filesystem::path out_dir_;
  const World& world_;
  bool write_meshes_;
  std::optional<ResumableLog> csv_;
};

}  // namespace upf
