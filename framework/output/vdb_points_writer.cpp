#include "framework/output/vdb_points_writer.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointDataGrid.h>

#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {

namespace vp = openvdb::points;

using IndexGrid = openvdb::tools::PointIndexGrid;

// Appends attribute `name` of type T (codec Codec) and fills it from `values`, in the order of
// the points given to the index grid.
template <class T, class Codec = vp::NullCodec>
void add_attribute(vp::PointDataGrid& grid, const IndexGrid& index, const std::string& name,
                   const std::vector<T>& values) {
  vp::appendAttribute<T, Codec>(grid.tree(), name);
  const vp::PointAttributeVector<T> wrapper(values);
  vp::populateAttribute<vp::PointDataTree, IndexGrid::TreeType, vp::PointAttributeVector<T>>(
      grid.tree(), index.tree(), name, wrapper);
}

// A float attribute, halved under the truncate codec.
template <class T>
void add_real_attribute(vp::PointDataGrid& grid, const IndexGrid& index, const std::string& name,
                        const std::vector<T>& values, VdbPointsCodec codec) {
  if (codec == VdbPointsCodec::truncate)
    add_attribute<T, vp::TruncateCodec>(grid, index, name, values);
  else
    add_attribute<T>(grid, index, name, values);
}

vp::PointDataGrid::Ptr points_grid(const IndexGrid& index,
                                   const vp::PointAttributeVector<openvdb::Vec3f>& positions,
                                   const openvdb::math::Transform& transform,
                                   VdbPointsCodec codec) {
  switch (codec) {
    case VdbPointsCodec::truncate:
      return vp::createPointDataGrid<vp::TruncateCodec, vp::PointDataGrid>(index, positions,
                                                                           transform);
    case VdbPointsCodec::fixed_point:
      return vp::createPointDataGrid<vp::FixedPointCodec<false>, vp::PointDataGrid>(
          index, positions, transform);
    case VdbPointsCodec::none:
      break;
  }
  return vp::createPointDataGrid<vp::NullCodec, vp::PointDataGrid>(index, positions, transform);
}

openvdb::Vec3f to_vdb(const Vec3& v) {
  return {float(v.x), float(v.y), float(v.z)};
}

}  // namespace

const char* to_string(VdbPointsCodec codec) {
  switch (codec) {
    case VdbPointsCodec::truncate:
      return "truncate";
    case VdbPointsCodec::fixed_point:
      return "fixed_point";
    case VdbPointsCodec::none:
      break;
  }
  return "none";
}

double vdb_points_voxel_size(double spacing) {
  return std::exp2(std::round(std::log2(2 * spacing)));
}

void write_vdb_points(const std::filesystem::path& file, const Particles& particles,
                      const std::vector<std::string>& fields, double spacing,
                      VdbPointsCodec codec) {
  openvdb::initialize();  // idempotent and thread-safe: registers the grid and codec types
  const std::size_t n = particles.size();
  std::vector<openvdb::Vec3f> positions(n), velocities(n);
  std::vector<std::int32_t> types(n), materials(n);
  std::vector<std::int64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) {
    positions[i] = to_vdb(particles.position[i]);
    velocities[i] = to_vdb(particles.velocity[i]);
    types[i] = std::int32_t(particles.type[i]);
    materials[i] = std::int32_t(particles.material[i]);
    ids[i] = std::int64_t(particles.id[i]);
  }
  const auto transform =
      openvdb::math::Transform::createLinearTransform(vdb_points_voxel_size(spacing));
  const vp::PointAttributeVector<openvdb::Vec3f> position_wrapper(positions);
  const auto index = openvdb::tools::createPointIndexGrid<IndexGrid>(position_wrapper, *transform);
  const auto grid = points_grid(*index, position_wrapper, *transform, codec);
  grid->setName("points");
  add_real_attribute(*grid, *index, "v", velocities, codec);
  add_attribute(*grid, *index, "id", ids);
  add_attribute(*grid, *index, "type", types);
  add_attribute(*grid, *index, "material", materials);
  for (const std::string& name : fields) {
    if (const auto* s = particles.find_scalar(name)) {
      std::vector<float> values(s->begin(), s->end());
      add_real_attribute(*grid, *index, name, values, codec);
    } else if (const auto* v = particles.find_vector(name)) {
      std::vector<openvdb::Vec3f> values(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = to_vdb((*v)[i]);
      add_real_attribute(*grid, *index, name, values, codec);
    }
  }
  write_file_atomically(
      file, [&](std::ostream& out) { openvdb::io::Stream(out).write(openvdb::GridCPtrVec{grid}); });
}

}  // namespace upf
