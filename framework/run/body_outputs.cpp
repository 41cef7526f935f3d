#include "framework/run/body_outputs.h"

#include <cstdio>

#include "framework/core/state_stream.h"
#include "framework/output/mesh_vtp_writer.h"

namespace upf {

BodyOutputs::BodyOutputs(const std::filesystem::path& out_dir, const World& world,
                         bool write_meshes, bool resuming)
    : out_dir_(out_dir),
      world_(world),
      write_meshes_(write_meshes && !world.body_systems().empty()) {
  if (world.body_systems().empty()) return;
  csv_.emplace(out_dir / "bodies.csv",
               "time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,fx,fy,fz,tx,ty,tz,"
               "fx_mean,fy_mean,fz_mean,tx_mean,ty_mean,tz_mean\n",
               resuming);
  forces_csv_.emplace(out_dir / "body_forces.csv", "time,body,name,fx,fy,fz,tx,ty,tz\n", resuming);
}

namespace {
std::array<double, 6> force_and_torque(const BodyState& s) {
  return {s.fluid_force.x(),  s.fluid_force.y(),  s.fluid_force.z(),
          s.fluid_torque.x(), s.fluid_torque.y(), s.fluid_torque.z()};
}

std::vector<NamedBodyState> all_body_states(const World& world) {
  std::vector<NamedBodyState> bodies;
  for (const auto& system : world.body_systems())
    for (auto& b : system->body_states()) bodies.push_back(std::move(b));
  return bodies;
}
}  // namespace

void BodyOutputs::record_step(double time, double dt, bool row) {
  if (!csv_) return;
  const std::vector<NamedBodyState> bodies = all_body_states(world_);
  impulse_.resize(bodies.size(), std::array<double, 6>{});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto f = force_and_torque(bodies[b].state);
    for (int c = 0; c < 6; ++c) impulse_[b][std::size_t(c)] += dt * f[std::size_t(c)];
    if (row) {
      std::ostream& out = forces_csv_->out();
      out << time << ',' << b << ',' << bodies[b].name;
      for (double v : f) out << ',' << v;
      out << '\n';
    }
  }
  interval_ += dt;
}

std::vector<std::string> BodyOutputs::write_frame(int frame, double time) {
  const std::vector<NamedBodyState> bodies = all_body_states(world_);
  std::vector<std::string> files;
  if (write_meshes_) {
    std::vector<MeshPiece> pieces;
    for (const auto& system : world_.body_systems())
      for (auto& piece : system->surface_meshes()) pieces.push_back(std::move(piece));
    std::vector<double> speed, force;
    for (const auto& b : bodies) {
      speed.push_back(b.state.velocity.norm());
      force.push_back(b.state.fluid_force.norm());
    }
    char name[64];
    std::snprintf(name, sizeof name, "frames/bodies_%05d.vtp", frame);
    write_mesh_vtp(out_dir_ / name, pieces, {{"speed", speed}, {"fluid_force", force}});
    files.push_back(name);
  }
  if (csv_) {
    std::ostream& out = csv_->out();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const BodyState& s = bodies[b].state;
      out << time << ',' << b << ',' << bodies[b].name;
      for (double c :
           {s.position.x(), s.position.y(), s.position.z(), s.orientation.w(), s.orientation.x(),
            s.orientation.y(), s.orientation.z(), s.velocity.x(), s.velocity.y(), s.velocity.z(),
            s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z(),
            s.fluid_force.x(), s.fluid_force.y(), s.fluid_force.z(), s.fluid_torque.x(),
            s.fluid_torque.y(), s.fluid_torque.z()})
        out << ',' << c;
      // The mean over the steps since the last frame; the first frame has had no step.
      const auto last = force_and_torque(s);
      for (std::size_t c = 0; c < 6; ++c)
        out << ',' << (interval_ > 0 && b < impulse_.size() ? impulse_[b][c] / interval_ : last[c]);
      out << '\n';
    }
    csv_->flush();
    forces_csv_->flush();
  }
  impulse_.assign(impulse_.size(), std::array<double, 6>{});
  interval_ = 0;
  return files;
}

void BodyOutputs::save_state(StateWriter& out) {
  out.put(std::uint8_t(csv_ ? 1 : 0));
  if (!csv_) return;
  csv_->save_state(out);
  forces_csv_->save_state(out);
  out.put(std::uint64_t(impulse_.size()));
  for (const auto& sums : impulse_)
    for (double v : sums) out.put(v);
  out.put(interval_);
}

void BodyOutputs::restore_state(StateReader& in) {
  in.expect((in.get<std::uint8_t>() != 0) == csv_.has_value(), "whether the scene has bodies");
  if (!csv_) return;
  csv_->restore_state(in);
  forces_csv_->restore_state(in);
  const auto saved = std::size_t(in.get<std::uint64_t>());
  const std::size_t bodies = all_body_states(world_).size();
  in.expect(saved == 0 || saved == bodies, "the number of bodies");
  impulse_.resize(saved);
  for (auto& sums : impulse_)
    for (double& v : sums) v = in.get<double>();
  interval_ = in.get<double>();
}

}  // namespace upf
