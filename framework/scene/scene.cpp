#include "framework/scene/scene.h"

#include <algorithm>
#include <cmath>

namespace upf {

bool Box::contains(const Box& inner, double tolerance) const {
  return (inner.min.array() >= min.array() - tolerance).all() &&
         (inner.max.array() <= max.array() + tolerance).all();
}

namespace {
double fluid_cells(double extent, double spacing) {
  return std::max(0.0, std::floor(extent / spacing + 1e-6));
}
double wall_cells(double extent, double spacing) {
  return std::max(1.0, std::round(extent / spacing));
}
}  // namespace

Lattice fluid_lattice_size(const Box& box, double spacing) {
  Lattice n;
  for (int a = 0; a < 3; ++a) n[a] = std::int64_t(fluid_cells(box.max[a] - box.min[a], spacing));
  return n;
}

Lattice wall_lattice_size(const Box& box, double spacing) {
  Lattice n;
  for (int a = 0; a < 3; ++a) n[a] = std::int64_t(wall_cells(box.max[a] - box.min[a], spacing));
  return n;
}

double fluid_particle_estimate(const Box& box, double spacing) {
  double n = 1;
  for (int a = 0; a < 3; ++a) n *= fluid_cells(box.max[a] - box.min[a], spacing);
  return n;
}

double wall_particle_estimate(const Box& box, double spacing, int layers) {
  double inner = 1, outer = 1;
  for (int a = 0; a < 3; ++a) {
    const double n = wall_cells(box.max[a] - box.min[a], spacing);
    inner *= n;
    outer *= n + 2.0 * layers;
  }
  return outer - inner;
}

double SceneDescription::estimated_particles() const {
  double total = 0;
  const double h = world.spacing;
  for (const auto& c : containers) total += wall_particle_estimate(c.box, h, c.layers);
  for (const auto& b : fluid_blocks) total += fluid_particle_estimate(b.box, h);
  for (const auto& s : sections)
    if (s.data) total += s.data->estimated_particles();
  return total;
}

}  // namespace upf
