#include "framework/run/frame_writer.h"

#include <cstdio>
#include <tuple>

#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/output/atomic_file.h"
#include "framework/output/mesh_ply_obj_writer.h"
#include "framework/output/mesh_vtp_writer.h"
#include "framework/output/ply_points_writer.h"
#include "framework/output/vtp_writer.h"
#include "framework/output/z_up.h"
#include "framework/particles/particles_of_types.h"

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
                         std::size_t frozen_count, VdbFrameWriters vdb, bool resuming)
    : out_dir_(out_dir),
      fields_(std::move(fields)),
      vtp_(enabled && scene.output.vtp),
      ply_(enabled && scene.output.ply),
      surface_(enabled && scene.output.surface),
      surface_vdb_(enabled && scene.output.surface_vdb),
      vdb_points_(enabled && scene.output.vdb_points),
      vdb_compression_(scene.output.vdb_compression),
      surface_method_(scene.output.surface_method),
      surface_voxel_(scene.output.surface_voxel),
      compression_(scene.output.compress ? vtk_xml::Compression::zlib : vtk_xml::Compression::none),
      vtp_types_(scene.output.vtp_types),
      ply_types_(scene.output.ply_types),
      vdb_points_types_(scene.output.vdb_points_types),
      ply_z_up_(scene.output.ply_z_up),
      frozen_piece_(vtp_ && scene.output.frozen_once &&
                    in_mask(scene.output.vtp_types, ParticleType::Frozen) && frozen_count > 0),
      spacing_(scene.world.spacing),
      series_(out_dir / "particles.pvd"),
      world_(world),
      vdb_(std::move(vdb)),
      bodies_(out_dir, world, vtp_, resuming) {
  for (auto [needed, present, format] :
       {std::tuple{surface_, bool(vdb_.surface), "surface"},
        std::tuple{surface_vdb_, bool(vdb_.surface), "surface_vdb"},
        std::tuple{vdb_points_, bool(vdb_.points), "vdb_points"}})
    if (needed && !present)
      throw InputError(scene.source.string() + ":/output/formats",
                       "\"" + std::string(format) +
                           "\" needs OpenVDB: this program was built without upf_surface");
  if (vtp_ || ply_ || surface_ || surface_vdb_ || vdb_points_) ensure_directory(out_dir / "frames");
}

namespace {

constexpr const char* kFrozenFile = "frames/frozen.vtp";

// The types a frame file of a format holds: those asked for, less the frozen ones when they go
// into a piece of their own.
TypeMask frame_types(TypeMask asked, bool frozen_piece) {
  return frozen_piece ? TypeMask(asked & ~mask_of(ParticleType::Frozen)) : asked;
}

// Calls write(p) with `particles`, or with a copy holding only the types in `types` when some
// are left out.
template <class Write>
void with_types(const Particles& particles, TypeMask types, Write&& write) {
  if (all_of_types(particles, types))
    write(particles);
  else
    write(particles_of_types(particles, types));
}

}  // namespace

std::vector<std::string> FrameWriter::files_of_frame(const FramePieceNames& pieces) const {
  std::vector<std::string> files;
  const bool as_pieces = !pieces.particles.empty();
  if (vtp_ && !as_pieces) files.push_back(frame_file("frames/frame_%05d.vtp", frames_));
  if (frozen_piece_ && !as_pieces && !frozen_written_) files.push_back(kFrozenFile);
  if (ply_) files.push_back(frame_file("frames/frame_%05d.ply", frames_));
  if (bodies_.writes_meshes()) files.push_back(frame_file("frames/bodies_%05d.vtp", frames_));
  if (vdb_points_) files.push_back(frame_file("frames/points_%05d.vdb", frames_));
  if (surface_vdb_) files.push_back(frame_file("frames/surface_%05d.vdb", frames_));
  if (surface_) {
    files.push_back(frame_file("frames/surface_%05d.ply", frames_));
    files.push_back(frame_file("frames/surface_%05d.vtp", frames_));
  }
  return files;
}

void FrameWriter::write(const Particles& particles, double time, const FramePieceNames& pieces) {
  std::vector<std::string> files;
  if (vtp_ && !pieces.particles.empty()) {
    files.push_back(pieces.particles);
    if (!pieces.frozen.empty()) files.push_back(pieces.frozen);
  } else if (vtp_) {
    files.push_back(frame_file("frames/frame_%05d.vtp", frames_));
    with_types(particles, frame_types(vtp_types_, frozen_piece_), [&](const Particles& p) {
      write_vtp(out_dir_ / files.back(), p, fields_, compression_);
    });
  }
  if (frozen_piece_ && pieces.particles.empty()) {
    // Frozen particles never move: their positions at the first frame are those at every frame.
    if (!frozen_written_) {
      write_vtp(out_dir_ / kFrozenFile,
                particles_of_types(particles, mask_of(ParticleType::Frozen)), fields_,
                compression_);
      frozen_written_ = true;
    }
    files.push_back(kFrozenFile);
  }
  if (ply_) {  // for Blender and MeshLab; ParaView has the .vtp, so not in the .pvd
    const auto path = out_dir_ / frame_file("frames/frame_%05d.ply", frames_);
    if (ply_z_up_) {
      Particles turned = particles_of_types(particles, ply_types_);
      turn_to_z_up(turned);
      write_ply_points(path, turned, fields_);
    } else {
      with_types(particles, ply_types_,
                 [&](const Particles& p) { write_ply_points(path, p, fields_); });
    }
  }
  if (vdb_points_) {  // for Houdini (Convert VDB Points) and OpenVDB tools; not in the .pvd
    const auto path = out_dir_ / frame_file("frames/points_%05d.vdb", frames_);
    with_types(particles, vdb_points_types_, [&](const Particles& p) {
      vdb_.points(path, p, fields_, spacing_, vdb_compression_);
    });
  }
  for (auto& f : bodies_.write_frame(frames_, time)) files.push_back(std::move(f));
  if (surface_ || surface_vdb_) {
    std::string vtp = write_surface(particles);
    if (!vtp.empty()) files.push_back(std::move(vtp));  // the last part at every step
  }
  if (vtp_ || surface_) series_.add(time, files);
  ++frames_;
}

std::uint64_t FrameWriter::bytes_per_frame(const Particles& particles) const {
  std::uint64_t bytes = 0;
  if (vtp_)
    with_types(particles, frame_types(vtp_types_, frozen_piece_),
               [&](const Particles& p) { bytes += vtp_data_bytes(p, fields_); });
  if (ply_)
    with_types(particles, ply_types_,
               [&](const Particles& p) { bytes += ply_points_bytes(p, fields_); });
  if (vdb_points_)  // about 40 bytes a point (P, v, id, type, material) and 4 per field value
    with_types(particles, vdb_points_types_, [&](const Particles& p) {
      std::uint64_t per_point = 40;
      for (const auto& name : fields_)
        per_point += p.find_scalar(name) ? 4 : p.find_vector(name) ? 12 : 0;
      bytes += per_point * p.size();
    });
  return bytes;
}

std::uint64_t FrameWriter::bytes_once(const Particles& particles) const {
  return frozen_piece_
             ? vtp_data_bytes(particles_of_types(particles, mask_of(ParticleType::Frozen)), fields_)
             : 0;
}

std::string FrameWriter::write_surface(const Particles& particles) const {
  const std::filesystem::path level_set =
      surface_vdb_ ? out_dir_ / frame_file("frames/surface_%05d.vdb", frames_)
                   : std::filesystem::path();
  const MeshPiece mesh = vdb_.surface(particles, spacing_, world_.executor().threads(), level_set,
                                      surface_, surface_method_, surface_voxel_);
  if (!surface_) return {};
  const auto ply = out_dir_ / frame_file("frames/surface_%05d.ply", frames_);
  if (ply_z_up_) {
    MeshPiece turned = mesh;
    turn_to_z_up(turned);
    write_mesh_ply(ply, turned);
  } else {
    write_mesh_ply(ply, mesh);
  }
  const std::string vtp = frame_file("frames/surface_%05d.vtp", frames_);
  write_mesh_vtp(out_dir_ / vtp, {mesh}, {}, compression_);
  return vtp;
}

void FrameWriter::save_state(StateWriter& out) {
  out.put(std::int32_t(frames_));
  series_.save_state(out);
  bodies_.save_state(out);
}

void FrameWriter::restore_state(StateReader& in) {
  frames_ = in.get<std::int32_t>();
  // The run being resumed wrote the frozen piece; its bytes stay (this world's particle order,
  // and so the piece's, may differ from the first frame's).
  frozen_written_ = std::filesystem::exists(out_dir_ / kFrozenFile);
  series_.restore_state(in);
  bodies_.restore_state(in);
}

}  // namespace upf
