#include "coupling/sampling/sample_set.h"

namespace upf {

void SampleSet::add(const Eigen::Vector3d& p, std::uint32_t t) {
  grid_.insert(p);
  samples_.positions.push_back(p);
  samples_.normals.push_back(triangle_area_vector(mesh_, t).normalized());
  samples_.triangles.push_back(t);
}

}  // namespace upf
