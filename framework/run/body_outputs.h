// What a run writes about the world's bodies: bodies.csv, one row per body per frame (pose,
// velocities, the fluid force and torque of the last step and their means over the frame
// interval), body_forces.csv, a row per body every few steps (the fluid force and torque), and
// frames/bodies_NNNNN.vtp, the bodies' surfaces in their poses for the frame's .pvd entry. A
// body's fluid force chatters from step to step at fine spacings; the frame mean is what its
// motion feels. The body systems only report (BodySystem::body_states,
// surface_meshes); writing and resuming the files is the run's, like metrics.csv.
#pragma once

#include <array>
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
  // After each step of length `dt` ending at `time`: adds the step's force to the frame means,
  // and with `row` writes its row of body_forces.csv.
  void record_step(double time, double dt, bool row);
  // Whether write_frame writes frames/bodies_NNNNN.vtp.
  bool writes_meshes() const { return write_meshes_; }
  // The files written for frame `frame` (relative to the output directory), for the .pvd.
  std::vector<std::string> write_frame(int frame, double time);
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  std::filesystem::path out_dir_;
  const World& world_;
  bool write_meshes_;
  std::optional<ResumableLog> csv_;
  std::optional<ResumableLog> forces_csv_;
  // Since the last frame: the integral of each body's fluid force and torque over time
  // (fx, fy, fz, tx, ty, tz), and the time it spans.
  std::vector<std::array<double, 6>> impulse_;
  double interval_ = 0;
};

}  // namespace upf
