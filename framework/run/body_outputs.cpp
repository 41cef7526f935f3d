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
               "time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,fx,fy,fz,tx,ty,tz\n", resuming);
}

std::vector<std::string> BodyOutputs::write_frame(int frame, double time) {
  std::vector<NamedBodyState> bodies;
  for (const auto& system : world_.body_systems())
    for (auto& b : system->body_states()) bodies.push_back(std::move(b));
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
      out << '\n';
    }
    csv_->flush();
  }
  return files;
}

void BodyOutputs::save_state(StateWriter& out) {
  out.put(std::uint8_t(csv_ ? 1 : 0));
  if (csv_) csv_->save_state(out);
}

void BodyOutputs::restore_state(StateReader& in) {
  in.expect((in.get<std::uint8_t>() != 0) == csv_.has_value(), "whether the scene has bodies");
  if (csv_) csv_->restore_state(in);
}

}  // namespace upf
