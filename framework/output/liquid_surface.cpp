// Liquid surface meshing with OpenVDB (method and references in liquid_surface.h). The only file
// of the project that includes OpenVDB headers: upf_framework links OpenVDB privately.
#include "framework/output/liquid_surface.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/task_arena.h>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "framework/output/anisotropic_kernels.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {

// The particle list interface ParticlesToLevelSet reads (see tools/ParticlesToLevelSet.h).
class PositionList {
 public:
  using PosType = openvdb::Vec3R;
  PositionList(const std::vector<Eigen::Vector3d>& positions, double radius)
      : positions_(positions), radius_(radius) {}
  std::size_t size() const { return positions_.size(); }
  void getPos(std::size_t n, openvdb::Vec3R& xyz) const {
    const Eigen::Vector3d& p = positions_[n];
    xyz = openvdb::Vec3R(p.x(), p.y(), p.z());
  }
  void getPosRad(std::size_t n, openvdb::Vec3R& xyz, openvdb::Real& radius) const {
    getPos(n, xyz);
    radius = radius_;
  }

 private:
  const std::vector<Eigen::Vector3d>& positions_;
  double radius_;
};

void check_input(const std::vector<Eigen::Vector3d>& positions, double h,
                 const LiquidSurfaceOptions& o) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("liquid_surface_mesh: " + what);
  };
  if (!(std::isfinite(h) && h > 0)) fail("the particle spacing must be finite and positive");
  if (!(std::isfinite(o.radius_factor) && o.radius_factor > 0.5))
    fail("radius_factor must be finite and greater than 0.5");
  if (!(std::isfinite(o.voxel_factor) && o.voxel_factor > 0))
    fail("voxel_factor must be finite and positive");
  if (o.radius_factor / o.voxel_factor < 1.5)
    fail("the sphere radius must span at least 1.5 voxels (radius_factor >= 1.5 voxel_factor)");
  if (o.smoothing_iterations < 0) fail("smoothing_iterations must not be negative");
  const AnisotropyParameters& a = o.anisotropy;
  if (!(std::isfinite(a.neighbourhood) && a.neighbourhood >= 1 && a.neighbourhood <= 10))
    fail("anisotropy.neighbourhood must be in [1, 10]");
  if (!(std::isfinite(a.kernel_radius) && a.kernel_radius >= 1 && a.kernel_radius <= 10))
    fail("anisotropy.kernel_radius must be in [1, 10]");
  if (!(std::isfinite(a.max_stretch) && a.max_stretch >= 1 && a.max_stretch <= 100))
    fail("anisotropy.max_stretch must be in [1, 100]");
  if (a.min_neighbours < 0) fail("anisotropy.min_neighbours must not be negative");
  if (!(std::isfinite(a.sparse_scale) && a.sparse_scale > 0 && a.sparse_scale <= 1))
    fail("anisotropy.sparse_scale must be in (0, 1]");
  if (!(std::isfinite(a.centre_smoothing) && a.centre_smoothing >= 0 && a.centre_smoothing <= 1))
    fail("anisotropy.centre_smoothing must be in [0, 1]");
  if (!(std::isfinite(a.level) && a.level > 0 && a.level < 1))
    fail("anisotropy.level must be in (0, 1)");
  if (o.threads < 0) fail("threads must not be negative");
  // Voxel coordinates are 32-bit integers; stay well inside them.
  const double limit = 1e8 * o.voxel_factor * h;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite() || positions[i].cwiseAbs().maxCoeff() > limit)
      fail("particle " + std::to_string(i) + " is not finite or too far out for the grid");
  }
}

// Signed volume of a closed triangle mesh by the divergence theorem: sum of a . (b x c) / 6.
double signed_volume(const MeshPiece& mesh) {
  double six_v = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    six_v += a.dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return six_v / 6;
}

// The spheres method's level set (liquid_surface.h), before the optional smoothing.
openvdb::FloatGrid::Ptr sphere_union_level_set(const std::vector<Eigen::Vector3d>& positions,
                                               double h, const LiquidSurfaceOptions& options) {
  const double dx = options.voxel_factor * h;
  const double radius = options.radius_factor * h;
  // Half-width of the narrow band in voxels; OpenVDB's default (3) suffices, as the filters
  // keep the band around the moving surface.
  auto grid = openvdb::createLevelSet<openvdb::FloatGrid>(dx, openvdb::LEVEL_SET_HALF_WIDTH);

  // 1. Union of spheres. Each thread rasterises into its own grid and the grids are merged by
  // a CSG union (a minimum), so the result does not depend on how the work was split.
  {
    openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
    raster.rasterizeSpheres(PositionList(positions, radius));
    raster.finalize(/*prune=*/true);
  }

  // 2. Erode back to h/2 beyond the outer particle centres. The filter reads a copy of the
  // values and writes each voxel once: no order dependence either.
  // Over a lattice face the union of spheres is not flat: at lateral distance d from the nearest
  // centre it lies sqrt(R^2 - d^2) ~ R - d^2 / 2R above the centres' plane. Eroding by R - h/2
  // levels the ripples near their dips and left a lattice box 4 % short of N h^3 (measured); the
  // mean of d^2 over a lattice cell is h^2 / 6, so erode by the mean dip h^2 / 12R less.
  {
    openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
    const double erosion = radius - 0.5 * h - h * h / (12 * radius);
    filter.offset(static_cast<float>(erosion));  // positive: the surface moves inwards
  }
  return grid;
}

// The anisotropic method's level set (liquid_surface.h): the kernel sum phi sampled at the voxel
// centres as 1/2 - phi (negative inside, 1/2 far outside), then rebuilt as a signed distance
// narrow band around its zero level. Each voxel's value is one fixed-order sum, so the grid
// does not depend on how the voxels are shared out among threads.
openvdb::FloatGrid::Ptr anisotropic_level_set(const std::vector<Eigen::Vector3d>& positions,
                                              double h, const LiquidSurfaceOptions& options) {
  const double dx = options.voxel_factor * h;
  const std::vector<AnisotropicKernel> kernels =
      anisotropic_kernels(positions, h, options.anisotropy);
  const KernelField field(kernels, options.anisotropy.kernel_radius * h);
  const auto kIso = static_cast<float>(options.anisotropy.level);
  auto sampled = openvdb::FloatGrid::create(kIso);
  sampled->setTransform(openvdb::math::Transform::createLinearTransform(dx));
  openvdb::FloatTree& tree = sampled->tree();
  // Every leaf node (8^3 voxels) that a kernel's support reaches.
  constexpr int kLeaf = int(openvdb::FloatTree::LeafNodeType::DIM);
  for (const AnisotropicKernel& k : kernels) {
    const auto index = [&](double world) { return int(std::floor(world / dx)); };
    const auto leaf_origin = [](int i) { return i & ~(kLeaf - 1); };
    openvdb::Coord lo;
    openvdb::Coord hi;
    for (int a = 0; a < 3; ++a) {
      lo[a] = leaf_origin(index(k.centre[a] - k.extent[a]));
      hi[a] = leaf_origin(index(k.centre[a] + k.extent[a]) + 1);
    }
    for (int i = lo[0]; i <= hi[0]; i += kLeaf)
      for (int j = lo[1]; j <= hi[1]; j += kLeaf)
        for (int l = lo[2]; l <= hi[2]; l += kLeaf) tree.touchLeaf(openvdb::Coord(i, j, l));
  }
  openvdb::tree::LeafManager<openvdb::FloatTree> leaves(tree);
  leaves.foreach ([&](openvdb::FloatTree::LeafNodeType& leaf, std::size_t) {
    for (openvdb::Index n = 0; n < openvdb::FloatTree::LeafNodeType::SIZE; ++n) {
      const openvdb::Vec3d x = sampled->indexToWorld(leaf.offsetToGlobalCoord(n));
      const double phi = field(Eigen::Vector3d(x.x(), x.y(), x.z()));
      if (phi > 0)
        leaf.setValueOn(n, kIso - static_cast<float>(phi));
      else
        leaf.setValueOff(n, kIso);
    }
  });
  return openvdb::tools::levelSetRebuild(*sampled, /*isovalue=*/0.0F,
                                         float(openvdb::LEVEL_SET_HALF_WIDTH));
}

// Steps 1 to 3 (liquid_surface.h): the narrow-band level set whose zero level is the surface; an
// empty one (all background) for no particles.
openvdb::FloatGrid::Ptr level_set_of(const std::vector<Eigen::Vector3d>& positions, double h,
                                     const LiquidSurfaceOptions& options) {
  openvdb::initialize();  // idempotent and thread-safe: registers OpenVDB's grid types
  openvdb::FloatGrid::Ptr grid;
  if (positions.empty())
    grid = openvdb::createLevelSet<openvdb::FloatGrid>(options.voxel_factor * h,
                                                       openvdb::LEVEL_SET_HALF_WIDTH);
  else if (options.method == SurfaceMethod::spheres)
    grid = sphere_union_level_set(positions, h, options);
  else
    grid = anisotropic_level_set(positions, h, options);
  grid->setName("surface");
  // Optional mean-curvature smoothing; each pass reads a copy of the values and writes each
  // voxel once.
  if (options.smoothing_iterations > 0 && !positions.empty()) {
    openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
    for (int i = 0; i < options.smoothing_iterations; ++i) filter.meanCurvature();
  }
  return grid;
}

// Step 4: the zero level set as triangles.
MeshPiece mesh_of(const openvdb::FloatGrid& grid) {
  MeshPiece mesh;
  mesh.name = "liquid surface";
  if (grid.empty()) return mesh;
  // 4. Zero level set as polygons.
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, /*isovalue=*/0.0,
                               /*adaptivity=*/0.0);
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("liquid_surface_mesh: too many vertices for 32-bit indices");

  mesh.vertices.reserve(points.size());
  for (const auto& p : points)
    mesh.vertices.emplace_back(double(p.x()), double(p.y()), double(p.z()));
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    // Split along the shorter diagonal (better-shaped triangles); either keeps the mesh closed.
    const auto& v = mesh.vertices;
    if ((v[q[0]] - v[q[2]]).squaredNorm() <= (v[q[1]] - v[q[3]]).squaredNorm()) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[1], q[3]});
      mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }

  // Outward normals: a closed surface wound counter-clockwise from outside encloses a positive
  // volume. volumeToMesh winds all polygons the same way, so one test decides for all.
  if (signed_volume(mesh) < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

MeshPiece surface_outputs(const std::vector<Eigen::Vector3d>& positions, double h,
                          const LiquidSurfaceOptions& options,
                          const LiquidSurfaceOutputs& outputs) {
  const openvdb::FloatGrid::Ptr grid = level_set_of(positions, h, options);
  if (!outputs.level_set_file.empty())
    write_file_atomically(outputs.level_set_file, [&](std::ostream& out) {
      openvdb::io::Stream(out).write(openvdb::GridCPtrVec{grid});
    });
  return outputs.mesh ? mesh_of(*grid) : MeshPiece{};
}

std::vector<Eigen::Vector3d> liquid_positions(const Particles& particles) {
  std::vector<Eigen::Vector3d> liquid;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.type[i] == ParticleType::Liquid) {
      const Vec3& p = particles.position[i];
      liquid.emplace_back(double(p.x), double(p.y), double(p.z));
    }
  return liquid;
}

}  // namespace

MeshPiece liquid_surface(const std::vector<Eigen::Vector3d>& positions, double h,
                         const LiquidSurfaceOptions& options, const LiquidSurfaceOutputs& outputs) {
  check_input(positions, h, options);
  if (options.threads > 0) {
    MeshPiece mesh;
    tbb::task_arena(options.threads).execute([&] {
      mesh = surface_outputs(positions, h, options, outputs);
    });
    return mesh;
  }
  return surface_outputs(positions, h, options, outputs);
}

MeshPiece liquid_surface_mesh(const std::vector<Eigen::Vector3d>& positions, double h,
                              const LiquidSurfaceOptions& options) {
  return liquid_surface(positions, h, options, {});
}

MeshPiece liquid_surface_mesh(const Particles& particles, double h,
                              const LiquidSurfaceOptions& options) {
  return liquid_surface_mesh(liquid_positions(particles), h, options);
}

MeshPiece run_surface_mesher(const Particles& particles, double h, int threads,
                             const std::filesystem::path& level_set_file, bool mesh,
                             const std::string& method, double voxel_factor) {
  LiquidSurfaceOptions options;
  options.threads = threads;
  options.voxel_factor = voxel_factor;
  if (method == "spheres") options.method = SurfaceMethod::spheres;
  return liquid_surface(liquid_positions(particles), h, options, {mesh, level_set_file});
}

}  // namespace upf
