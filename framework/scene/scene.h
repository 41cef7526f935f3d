// A scene as read from its JSON file: everything needed to build a World and run it. Reading
// (scene_reader) checks every value; building (scene_builder) can then trust it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/materials/material.h"
#include "framework/params/param_spec.h"
#include "framework/scene/scene_section.h"
#include "framework/world/world_settings.h"

namespace upf {

struct Box {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  bool contains(const Box& inner, double tolerance) const;
};

struct ContainerDesc {
  std::string material;
  Box box;  // the inner (fluid) side of the walls
  int layers = 2;
};

struct FluidBlockDesc {
  std::string material;
  Box box;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  // "shape": the whole box, or the ball (ellipsoid) inscribed in it: drops.
  bool ball = false;
};

enum class ProbeKind { Extent, Height, Pressure };

// How a height or pressure probe turns the particles it sees into one number.
//   Top     height: the highest particle centre plus half a spacing (a free surface)
//   Volume  height: the liquid volume per unit area under a 2D kernel (a wave gauge; spray and
//           droplets above the surface count only by their volume)
//   Mean    pressure: the plain mean over a sphere
//   Kernel  pressure: the Shepard-normalised SPH interpolation at the centre, so a sensor on a
//           wall reads the fluid's pressure extrapolated to the wall
enum class ProbeMethod { Top, Volume, Mean, Kernel };

struct ProbeDesc {
  std::string name;
  ProbeKind kind = ProbeKind::Extent;
  int axis = 0;               // extent: measured axis; height: the up axis
  bool max_side = true;       // extent: largest (true) or smallest coordinate
  std::optional<Box> region;  // extent: only liquid inside this box counts
  bool surface = false;       // extent: the particles' surface (centre + half a spacing outwards)
  Eigen::Vector2d at = Eigen::Vector2d::Zero();      // height: the two other coordinates, in order
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // pressure: sphere centre
  double radius = 0;                      // height: column radius; pressure: sphere radius
  ProbeMethod method = ProbeMethod::Top;  // height: Top or Volume; pressure: Mean or Kernel
};

struct OutputDesc {
  double fps = 30;
  // Exported fields to write in each frame, checked against the fields the solvers create when
  // the run starts (the reader checks the syntax only). Absent: every exported field, by name.
  std::optional<std::vector<std::string>> fields;
  // Frame formats ("formats"): VTK .vtp frames listed in particles.pvd, and PLY point clouds
  // (frames/frame_NNNNN.ply, not in the .pvd) for Blender and MeshLab.
  bool vtp = true;
  bool ply = false;
  // "surface": a triangle mesh of the liquid's surface per frame (frames/surface_NNNNN.ply, and
  // frames/surface_NNNNN.vtp as a further part of each time step in particles.pvd).
  bool surface = false;
  // "vdb_points": an OpenVDB point data grid per frame (frames/points_NNNNN.vdb) for Houdini and
  // OpenVDB tools, its attributes stored as "vdb_compression" says: "none", "truncate" (16-bit
  // halfs) or "fixed_point" (16-bit positions in their voxel); docs/scene-format.md.
  bool vdb_points = false;
  // "surface_vdb": the liquid surface's narrow-band level set per frame
  // (frames/surface_NNNNN.vdb, an OpenVDB float grid named "surface"), from the same surfacing
  // as "surface" (liquid_surface.h): Blender's Volume to Mesh, Houdini's VDB tools.
  bool surface_vdb = false;
  std::string vdb_compression = "none";
  // How "surface" and "surface_vdb" find the surface: "anisotropic" (Yu & Turk 2013 kernels,
  // smooth) or "spheres" (the eroded union of spheres); framework/output/liquid_surface.h.
  std::string surface_method = "anisotropic";
  // "surface_voxel": the surface's voxel in particle spacings; "surface_memory": the bound on the
  // memory its grids may take, checked before the first step (framework/run/surface_memory.h).
  double surface_voxel = 0.5;
  double surface_memory_gb = 4;
  // "compression": "zlib" compresses the .vtp arrays (VTK's vtkZLibDataCompressor layout),
  // "none" writes them as they are in memory.
  bool compress = true;
  // "frozen": "once" writes the frozen particles, which never move, once into
  // frames/frozen.vtp, a part of every time step in particles.pvd, and leaves them out of the
  // frame files; "every_frame" keeps them in every frame.
  bool frozen_once = true;
  // "pieces": on a run split over MPI ranks (docs/mpi.md), "per_rank" has every rank write its
  // own particles of each .vtp frame (frames/frame_NNNNN_pRRRR.vtp), joined by
  // frames/frame_NNNNN.pvtp, so no rank gathers a frame; "gathered" has rank 0 write the
  // one-rank run's files. One rank writes the same files either way.
  bool pieces_per_rank = false;
  // "types": which particle types each format writes ({"vtp": [...], "ply": [...]}); all four
  // unless the scene says.
  TypeMask vtp_types = kAllTypes;
  TypeMask ply_types = kAllTypes;
  TypeMask vdb_points_types = kAllTypes;
  // "ply_up": "z" turns the PLY files (points and surfaces) Z-up for Blender (z_up.h); "y"
  // writes them in the scene's axes, as the .vtp files always are.
  bool ply_z_up = false;
  // "size_warning": `upf run` warns before the first step when its frames would take more
  // bytes than this (GB, 10^9 bytes).
  double size_warning_gb = 20;
  // "probe_every": probes.csv gets a row every this many steps (and at every frame); 0 samples
  // the probes at frames only.
  int probe_every = 1;
};

struct SceneDescription {
  std::string name;
  std::filesystem::path source;
  std::string device = "cpu";  // where `upf run` steps it unless --device says (docs/device.md)
  WorldSettings world;
  std::vector<Material> materials;  // solver params already merged with defaults
  std::vector<ContainerDesc> containers;
  std::vector<FluidBlockDesc> fluid_blocks;
  std::vector<ProbeDesc> probes;
  OutputDesc output;
  std::vector<SceneSectionEntry> sections;  // plug-in keys ("bodies"), in registry order

  // While reading: materials the file declares whose definition had problems (reported at
  // their own paths), so that references to them add no second, false "no material" error.
  std::vector<std::string> rejected_materials;
  bool rejected(const std::string& material) const {
    return std::find(rejected_materials.begin(), rejected_materials.end(), material) !=
           rejected_materials.end();
  }

  // The declared material of that name, or null.
  const Material* material(const std::string& material_name) const {
    for (const auto& m : materials)
      if (m.name == material_name) return &m;
    return nullptr;
  }

  // In double: a huge box at a tiny spacing must give a huge number, not an overflow.
  double estimated_particles() const;
};

using Lattice = Eigen::Matrix<std::int64_t, 3, 1>;

// Lattice sizes shared by the memory estimate and the builder, so they agree exactly.
// Call only after the estimate has shown the counts are sane.
Lattice fluid_lattice_size(const Box& box, double spacing);
Lattice wall_lattice_size(const Box& box, double spacing);  // inner cells per axis
double fluid_particle_estimate(const Box& box, double spacing);
double wall_particle_estimate(const Box& box, double spacing, int layers);

}  // namespace upf
