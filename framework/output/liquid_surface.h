// A triangle mesh of the liquid's surface, built from the liquid particles' positions: what a
// renderer needs where the particles themselves are only points.
//
// The surface is the zero level of a narrow-band level set in a sparse VDB grid (Museth 2013,
// "VDB: High-resolution sparse volumes with dynamic topology", ACM TOG 32(3)), built with
// OpenVDB's tools in one of two ways:
//   anisotropic (default): the level 1/2 of a sum of anisotropic kernels, one per particle,
//      flattened along the surface where the particle's neighbours lie in a layer (Yu & Turk
//      2013, "Reconstructing surfaces of particle-based fluids using anisotropic kernels", ACM
//      TOG 32(1); anisotropic_kernels.h). The sum is sampled at the voxel centres and rebuilt as
//      a signed distance band (tools::levelSetRebuild). A flat surface shows no bump per
//      particle, thin sheets stay sheets, isolated particles stay drops.
//   spheres: the union of spheres around the particles (Zhu & Bridson 2005, "Animating sand as a
//      fluid", SIGGRAPH, Sec. 6): tools::ParticlesToLevelSet rasterises a sphere of radius
//      R = radius_factor * h around every particle, and tools::LevelSetFilter::offset erodes it
//      by R - h/2 (less h^2 / 12R, the mean dip of the union of spheres between lattice
//      neighbours; see the .cpp), so a flat surface ends h/2 beyond the outermost particle
//      centres. Each particle shows as a bump of up to 0.13 h on a flat surface.
// Both put a resting lattice block's face h/2 beyond its outer centres, as each particle stands
// for a cube of side h (N particles enclose N h^3, the liquid volume mass / rho0). Then
// optionally a few mean-curvature smoothing passes (LevelSetFilter::meanCurvature), and
// tools::volumeToMesh with adaptivity 0 extracts the zero level as triangles and quads; each
// quad becomes two triangles.
// The triangles are wound counter-clockwise seen from outside (the enclosed volume by the
// divergence theorem is positive), and the mesh is closed. The result depends only on the input
// (no globals; the number of threads does not change it).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/output/anisotropic_kernels.h"
#include "framework/output/mesh_vtp_writer.h"
#include "framework/particles/particles.h"

namespace upf {

enum class SurfaceMethod { anisotropic, spheres };

// Lengths are in units of the particle spacing h. The defaults were chosen by measuring the
// enclosed volume against N h^3 and the flatness of a resting surface
// (tests/unit/test_liquid_surface.cpp, docs/rendering.md).
struct LiquidSurfaceOptions {
  SurfaceMethod method = SurfaceMethod::anisotropic;
  // The anisotropic method's kernels (anisotropic_kernels.h).
  AnisotropyParameters anisotropy;
  // The spheres method: sphere radius R / h. Larger closes wider gaps between particles (spray
  // merges into sheets) but rounds edges and corners more; the erosion R - h/2 brings the flat
  // surface back.
  double radius_factor = 2.0;
  // Voxel size / h. Smaller gives a finer mesh (about 1 / voxel_factor^2 times as many
  // triangles) and costs about 1 / voxel_factor^3 times the time and memory. R must span at
  // least 1.5 voxels (OpenVDB skips smaller spheres).
  double voxel_factor = 0.5;
  // Mean-curvature smoothing passes after the erosion; 0 keeps the eroded union of spheres.
  // Each pass shrinks thin and small features (a ball of 3h radius lost 5 % in two passes).
  int smoothing_iterations = 0;
  // Threads for OpenVDB (TBB); 0: TBB's default (all cores). The mesh does not depend on it.
  int threads = 0;
};

// The surface of the union of `positions` (world coordinates, metres) for particle spacing `h`
// (> 0). Empty `positions` gives an empty mesh. Throws std::invalid_argument for h <= 0 or not
// finite, options out of range (radius_factor <= 0.5, voxel_factor <= 0, R < 1.5 voxels,
// negative smoothing_iterations or threads) or a non-finite position.
MeshPiece liquid_surface_mesh(const std::vector<Eigen::Vector3d>& positions, double h,
                              const LiquidSurfaceOptions& options = {});

// The same for the Liquid particles of `particles` (other types are ignored).
MeshPiece liquid_surface_mesh(const Particles& particles, double h,
                              const LiquidSurfaceOptions& options = {});

// What one surfacing gives: the mesh, and the level set of steps 1-3 written to
// `level_set_file` when it is not empty. That file holds one OpenVDB FloatGrid named "surface",
// of class level set: the signed distance to the surface in metres, negative inside, in a
// narrow band of 3 voxels on each side (the background value, 3 voxels, elsewhere), at world
// voxel size voxel_factor * h (h/2 by default), its zero level the mesh's surface.
struct LiquidSurfaceOutputs {
  bool mesh = true;
  std::filesystem::path level_set_file;
};

// The surface of `positions` (as liquid_surface_mesh) and the outputs asked for; the mesh is
// empty when `outputs.mesh` is false. Throws what liquid_surface_mesh throws, and OutputError
// when the level set file cannot be written.
MeshPiece liquid_surface(const std::vector<Eigen::Vector3d>& positions, double h,
                         const LiquidSurfaceOptions& options, const LiquidSurfaceOutputs& outputs);

// The surfacing runs use for the "surface" and "surface_vdb" formats (VdbFrameWriters), with the
// default options of `method` ("anisotropic" or "spheres", the scene's /output/surface_method)
// at `voxel_factor` (/output/surface_voxel) and the run's thread count: the mesh when `mesh`, the
// level set into `level_set_file` when it is not empty.
MeshPiece run_surface_mesher(const Particles& particles, double h, int threads,
                             const std::filesystem::path& level_set_file, bool mesh,
                             const std::string& method, double voxel_factor);

}  // namespace upf
