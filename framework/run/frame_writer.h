// A run's frames: frames/frame_NNNNN.vtp (and .ply point clouds, liquid surface meshes) at every
// frame time, the frozen particles once (frames/frozen.vtp), the bodies' files
// (body_outputs.h), and particles.pvd, the series ParaView opens.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "framework/core/mesh_piece.h"
#include "framework/output/pvd_series.h"
#include "framework/output/vtk_appended_data.h"
#include "framework/run/body_outputs.h"
#include "framework/run/frame_pieces.h"
#include "framework/scene/scene.h"
#include "framework/world/world.h"

namespace upf {

// Surfaces the liquid for the "surface" and "surface_vdb" output formats: (particles, spacing,
// threads, level set file, mesh?, method, voxel) -> the closed mesh when asked for, and the
// surface's level set written to the file when one is named; method and voxel (in spacings):
// OutputDesc::surface_method and surface_voxel. upf_surface
// (framework/output/liquid_surface.h, OpenVDB) provides one; it is a library of its own so that
// programs which never mesh surfaces do not load OpenVDB and the threads its logging library starts
// at load time (which make fork() unsafe under ASan).
using SurfaceMesher = std::function<MeshPiece(
    const Particles&, double, int, const std::filesystem::path&, bool, const std::string&, double)>;

// Writes the "vdb_points" frame: (file, particles, fields, spacing, compression) -> an OpenVDB
// point data grid (framework/output/vdb_points_writer.h), from upf_surface for the same reason.
using VdbPointsWriter =
    std::function<void(const std::filesystem::path&, const Particles&,
                       const std::vector<std::string>&, double, const std::string&)>;

// The frame writers that need OpenVDB, as programs that load upf_surface give them
// (framework/output/vdb_frame_writers.h); empty ones refuse the formats that need them.
struct VdbFrameWriters {
  SurfaceMesher surface;   // "surface" and "surface_vdb"
  VdbPointsWriter points;  // "vdb_points"
};

class FrameWriter {
 public:
  // `enabled` false writes no frame files (bodies.csv still). A scene asking for surfaces
  // or VDB points without the writer in `vdb` is an InputError at /output/formats. `resuming`: the
  // logs wait for restore_state. `frozen_count`: the world's frozen particles over every rank
  // (World::count, a collective on a split world, so the caller's: only rank 0 writes frames).
  FrameWriter(const std::filesystem::path& out_dir, const SceneDescription& scene,
              std::vector<std::string> fields, bool enabled, const World& world,
              std::size_t frozen_count, VdbFrameWriters vdb, bool resuming);

  // After each step of length `dt` ending at `time` (body_outputs.h); `row`: a row of
  // body_forces.csv now.
  void record_step(double time, double dt, bool row) { bodies_.record_step(time, dt, row); }
  // Writes the frame of `particles` at `time`: the world's state, or its last good state.
  // `pieces`: the .vtp frame (and the frozen piece) went out as pieces per rank (frame_pieces.h):
  // the series lists those files instead.
  void write(const Particles& particles, double time, const FramePieceNames& pieces = {});
  // The files the next write() makes (relative to the output directory), for the run's
  // manifest to record first; `pieces`: as write() gets them (the pieces are the caller's).
  std::vector<std::string> files_of_frame(const FramePieceNames& pieces) const;
  // Whether write() reads `particles` beyond what went out as pieces (PLY, surfaces).
  bool reads_particles_beside_pieces() const {
    return ply_ || surface_ || surface_vdb_ || vdb_points_;
  }
  // The bytes write() puts on disk per frame for `particles` uncompressed (particle files only:
  // not the surface meshes, whose size depends on the flow, nor the bodies' small files), and
  // those written once (the frozen piece): the size estimate of a run.
  std::uint64_t bytes_per_frame(const Particles& particles) const;
  std::uint64_t bytes_once(const Particles& particles) const;
  bool compressed() const { return compression_ == vtk_xml::Compression::zlib; }
  int frames() const { return frames_; }
  void save_state(StateWriter& out);
  void restore_state(StateReader& in);

 private:
  // frames/surface_NNNNN.ply for renderers and .vtp for ParaView ("surface"; returns the .vtp's
  // name) and frames/surface_NNNNN.vdb ("surface_vdb"), from one surfacing; "" without a mesh.
  std::string write_surface(const Particles& particles) const;

  std::filesystem::path out_dir_;
  std::vector<std::string> fields_;
  bool vtp_;      // .vtp frames and the .pvd
  bool ply_;      // .ply point clouds
  bool surface_;  // liquid surface meshes: .ply, and .vtp in the .pvd
  bool surface_vdb_;  // the liquid surface's level set (frames/surface_NNNNN.vdb)
  bool vdb_points_;   // OpenVDB point data grids (frames/points_NNNNN.vdb)
  std::string vdb_compression_;
  std::string surface_method_;
  double surface_voxel_;
  vtk_xml::Compression compression_;
  TypeMask vtp_types_;  // the types in the .vtp frame files (frozen ones apart, see below)
  TypeMask ply_types_;
  TypeMask vdb_points_types_;
  bool ply_z_up_;                // PLY files turned Z-up for Blender (z_up.h)
  bool frozen_piece_;            // the frozen particles go once into frames/frozen.vtp
  bool frozen_written_ = false;  // by this process (a resumed run writes the same bytes again)
  double spacing_;
  PvdSeries series_;
  const World& world_;
  VdbFrameWriters vdb_;
  BodyOutputs bodies_;
  int frames_ = 0;
};

}  // namespace upf
