#include "framework/scene/periodic_keys.h"

#include <cmath>
#include <sstream>

namespace upf {

namespace {

using nlohmann::json;

const char* const kAxes[3] = {"x", "y", "z"};

std::string number(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

// Whether [lo, hi] of `box` along `axis` is the period (to a billionth of it).
bool spans(const Box& box, int axis, double lo, double hi) {
  const double tolerance = 1e-9 * (hi - lo);
  return std::abs(box.min[axis] - lo) <= tolerance && std::abs(box.max[axis] - hi) <= tolerance;
}

void check_period(JsonInput& in, const std::string& path, double lo, double hi,
                  const WorldSettings& world) {
  const double period = hi - lo, support = double(world.support_radius());
  const double spacing = double(world.spacing);
  if (!(spacing > 0)) return;  // reported at /particle_spacing
  if (!(period > 2 * support)) {
    in.problem(path, "the period " + number(period) + " m must exceed two support radii (2 x " +
                         number(support) + " m): a particle would meet its own image");
    return;
  }
  const double cells = period / spacing;
  if (std::abs(cells - std::round(cells)) > 1e-6 * cells)
    in.problem(path, "the period " + number(period) + " m is " + number(cells) +
                         " particle spacings; the lattices tile across the faces only at a whole "
                         "number (" +
                         number(std::floor(cells) * spacing) + " or " +
                         number(std::ceil(cells) * spacing) + " m)");
}

}  // namespace

void check_periodic_scene(JsonInput& in, const PeriodicBounds& box, const SceneDescription& scene) {
  if (!box.any()) return;
  for (std::size_t c = 0; c < scene.containers.size(); ++c)
    for (int a = 0; a < 3; ++a)
      if (box.periodic[std::size_t(a)] && !spans(scene.containers[c].box, a, box.lo[a], box.hi[a]))
        in.problem("/containers/" + std::to_string(c),
                   std::string("along the periodic axis ") + kAxes[a] +
                       " a container spans the period exactly (min and max " + number(box.lo[a]) +
                       " and " + number(box.hi[a]) + "); it has no walls there");
  for (std::size_t b = 0; b < scene.fluid_blocks.size(); ++b)
    for (int a = 0; a < 3; ++a) {
      const Box& block = scene.fluid_blocks[b].box;
      const double tolerance = 1e-9 * (box.hi[a] - box.lo[a]);
      if (box.periodic[std::size_t(a)] &&
          (block.min[a] < box.lo[a] - tolerance || block.max[a] > box.hi[a] + tolerance))
        in.problem("/fluid_blocks/" + std::to_string(b),
                   std::string("lies outside the period along ") + kAxes[a] + " [" +
                       number(box.lo[a]) + ", " + number(box.hi[a]) +
                       "]: its particles would overlap their images");
    }
  for (const Material& m : scene.materials)
    if (m.type == ParticleType::Granular)
      in.problem("/materials/" + m.name,
                 "grains in a periodic domain are not supported yet (DEM's container walls are "
                 "planes that do not repeat); remove \"periodic\" or the grains");
  for (const SceneSectionEntry& s : scene.sections)
    if (s.key == "bodies")
      in.problem("/bodies",
                 "bodies in a periodic domain are not supported yet (a body's "
                 "particles would be wrapped one by one); remove \"periodic\" or the "
                 "bodies");
}

PeriodicBounds read_periodic(JsonInput& in, const json& doc, SceneDescription& scene) {
  PeriodicBounds bounds;
  auto it = doc.find("periodic");
  if (it == doc.end() || !in.expect_object(*it, "/periodic")) return bounds;
  in.check_keys(*it, "/periodic", {"x", "y", "z"});
  PeriodicBox& box = scene.world.periodic;
  for (int a = 0; a < 3; ++a) {
    auto range = it->find(kAxes[a]);
    if (range == it->end()) continue;
    const std::string path = JsonInput::child("/periodic", kAxes[a]);
    if (!range->is_array() || range->size() != 2 || !(*range)[0].is_number() ||
        !(*range)[1].is_number()) {
      in.problem(path, "expected [lo, hi] in metres, the interval along which the world repeats");
      continue;
    }
    const double lo = (*range)[0].get<double>(), hi = (*range)[1].get<double>();
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
      in.problem(path, "[" + number(lo) + ", " + number(hi) + "]: expected lo < hi");
      continue;
    }
    box.periodic[std::size_t(a)] = bounds.periodic[std::size_t(a)] = true;
    box.lo[a] = Real(lo);
    box.hi[a] = Real(hi);
    bounds.lo[a] = lo;
    bounds.hi[a] = hi;
    check_period(in, path, lo, hi, scene.world);
  }
  if (it->empty()) in.problem("/periodic", "names no axis; expected {\"x\": [lo, hi], ...}");
  return bounds;
}

}  // namespace upf
