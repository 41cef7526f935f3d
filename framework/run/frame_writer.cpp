#include "framework/run/frame_writer.h"

#include <cstdio>

#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/output/atomic_file.h"
#include "framework/output/mesh_ply_obj_writer.h"
#include "framework/output/mesh_vtp_writer.h"
#include "framework/output/ply_points_writer.h"
#include "framework/output/vtp_writer.h"

namespace upf {

namespace {
std::string frame_file(const char* pattern, int frame) {
  char name[64];
  std::snprintf(name, sizeof name, pattern, frame);
  return name;
}
}  // namespace

FrameWriter::FrameWriter(const std::filesystem::path& out_dir, const SceneDescription& scene,
                         std::vector<std::string> fields, bool enabled, const World& world,
                         SurfaceMesher surface_mesher, bool resuming)
    : out_dir_(out_dir),
      fields_(std::move(fields)),
      vtp_(enabled && scene.output.vtp),
      ply_(enabled && scene.output.ply),
      surface_(enabled && scene.output.surface),
      spacing_(scene.world.spacing),
      series_(out_dir / "particles.pvd"),
      world_(world),
      surface_mesher_(std::move(surface_mesher)),
      bodies_(out_dir, world, vtp_, resuming) {
  if (surface_ && !surface_mesher_)
    throw InputError(scene.source.string() + ":/output/formats",
                     "\"surface\" needs a surface mesher: this program was built without "
                     "upf_surface (OpenVDB)");
  if (vtp_ || ply_ || surface_) ensure_directory(out_dir / "frames");
}

void FrameWriter::write(const Particles& particles, double time) {
  std::vector<std::string> files;
  if (vtp_) {
    files.push_back(frame_file("frames/frame_%05d.vtp", frames_));
    write_vtp(out_dir_ / files.back(), particles, fields_);
  }
  if (ply_)  // for Blender and MeshLab; ParaView has the .vtp, so not in the .pvd
    write_ply_points(out_dir_ / frame_file("frames/frame_%05d.ply", frames_), particles, fields_);
  for (auto& f : bodies_.write_frame(frames_, time)) files.push_back(std::move(f));
  if (surface_) files.push_back(write_surface(particles));  // the last part at every step
  if (vtp_ || surface_) series_.add(time, files);
  ++frames_;
}

std::string FrameWriter::write_surface(const Particles& particles) const {
  const MeshPiece mesh = surface_mesher_(particles, spacing_, world_.executor().threads());
  write_mesh_ply(out_dir_ / frame_file("frames/surface_%05d.ply", frames_), mesh);
  const std::string vtp = frame_file("frames/surface_%05d.vtp", frames_);
  write_mesh_vtp(out_dir_ / vtp, {mesh}, {});
  return vtp;
}

void FrameWriter::save_state(StateWriter& out) {
  out.put(std::int32_t(frames_));
  series_.save_state(out);
  bodies_.save_state(out);
}

void FrameWriter::restore_state(StateReader& in) {
  frames_ = in.get<std::int32_t>();
  series_.restore_state(in);
  bodies_.restore_state(in);
}

}  // namespace upf
