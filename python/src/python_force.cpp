#include "python_force.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <limits>
#include <utility>

#include "framework/core/errors.h"
#include "framework/world/world.h"
#include "python_callback.h"

namespace py = pybind11;

namespace upf::python {

namespace {
template <class Out, class T>
py::array_t<Out> gather(const std::vector<T>& values, const std::vector<std::uint32_t>& chosen) {
  py::array_t<Out> out(py::ssize_t(chosen.size()));
  Out* o = out.mutable_data();
  for (std::size_t k = 0; k < chosen.size(); ++k) o[k] = static_cast<Out>(values[chosen[k]]);
  return out;
}

py::array_t<Real> gather_vectors(const std::vector<Vec3>& values,
                                 const std::vector<std::uint32_t>& chosen) {
  py::array_t<Real> out({py::ssize_t(chosen.size()), py::ssize_t(3)});
  Real* o = out.mutable_data();
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const Vec3& v = values[chosen[k]];
    o[3 * k] = v.x;
    o[3 * k + 1] = v.y;
    o[3 * k + 2] = v.z;
  }
  return out;
}
}  // namespace

PythonForce::PythonForce(std::string name, py::object function, TypeMask types)
    : name_(std::move(name)), function_(std::move(function)), types_(types) {}

PythonForce::~PythonForce() {
  // The world may go away with or without the GIL held (a Simulation dropped by Python holds it).
  py::gil_scoped_acquire gil;
  function_ = py::object();
}

CouplingUse PythonForce::coupling_use(TypeMask types, const std::string& name) {
  CouplingUse use;
  if (in_mask(types, ParticleType::Liquid)) use.writes.push_back(CouplingArray::LiquidForce);
  if (in_mask(types, ParticleType::Rigid)) use.writes.push_back(CouplingArray::BoundaryForce);
  const TypeMask unsupported = types & ~(kLiquidMask | mask_of(ParticleType::Rigid));
  if (unsupported)
    throw InputError("add_force '" + name + "'",
                     "a Python force acts on liquid and rigid particles: granular (DEM) and frozen "
                     "particles read no external force");
  return use;
}

Real PythonForce::max_time_step(const World&) const {
  return std::numeric_limits<Real>::max();
}

void PythonForce::step(World& world, Real dt, StageRunner& run) {
  run(name_, [&] { apply(world, dt); });
}

void PythonForce::apply(World& world, Real dt) {
  Particles& p = world.particles();
  chosen_.clear();
  for (std::uint32_t i = 0; i < p.size(); ++i)
    if (in_mask(types_, p.type[i])) chosen_.push_back(i);
  if (chosen_.empty()) return;

  py::gil_scoped_acquire gil;
  py::module_ types = py::module_::import("types");
  py::object state =
      types.attr("SimpleNamespace")(py::arg("position") = gather_vectors(p.position, chosen_),
                                    py::arg("velocity") = gather_vectors(p.velocity, chosen_),
                                    py::arg("mass") = gather<Real>(p.mass, chosen_),
                                    py::arg("id") = gather<ParticleId>(p.id, chosen_),
                                    py::arg("material") = gather<MaterialId>(p.material, chosen_),
                                    py::arg("type") = gather<std::uint8_t>(p.type, chosen_),
                                    py::arg("time") = world.time(), py::arg("dt") = double(dt));
  py::object result = call_python([&] { return function_(state); });
  // ensure() gives a null array (no exception) for what NumPy cannot convert.
  const auto force = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(result);
  const py::ssize_t n = py::ssize_t(chosen_.size());
  const bool per_particle =
      force && force.ndim() == 2 && force.shape(0) == n && force.shape(1) == 3;
  const bool uniform = force && force.ndim() == 1 && force.shape(0) == 3;
  if (!per_particle && !uniform)
    throw py::value_error("force '" + name_ + "' must return an array of shape (" +
                          std::to_string(n) + ", 3), one force in N per particle, or (3,) for " +
                          "the same force on every particle; it returned " +
                          py::repr(result).cast<std::string>().substr(0, 80));
  const double* f = force.data();
  for (py::ssize_t k = 0; k < (per_particle ? 3 * n : 3); ++k)
    if (!std::isfinite(f[k]))
      throw py::value_error("force '" + name_ + "' returned a value that is not finite");

  CouplingArrays& c = world.coupling();
  for (std::size_t k = 0; k < chosen_.size(); ++k) {
    const std::uint32_t i = chosen_[k];
    const double* fk = per_particle ? f + 3 * k : f;
    const CouplingArray target = p.type[i] == ParticleType::Liquid ? CouplingArray::LiquidForce
                                                                   : CouplingArray::BoundaryForce;
    // Inactive when nothing reads it (no fluid solver, no bodies): then the force has no effect.
    if (!c.active(target)) continue;
    c[target][i] += Vec3{Real(fk[0]), Real(fk[1]), Real(fk[2])};
  }
}

}  // namespace upf::python
