#include "numpy_views.h"

namespace py = pybind11;

namespace upf::python {

namespace {
static_assert(sizeof(Vec3) == 3 * sizeof(Real), "Vec3 must be three packed Reals");
static_assert(sizeof(ParticleType) == 1, "ParticleType is one byte");

template <class T>
py::array scalar_view(const T* data, std::size_t n, py::handle owner, bool writable) {
  py::array a(py::dtype::of<T>(), {py::ssize_t(n)}, {py::ssize_t(sizeof(T))}, data, owner);
  if (!writable) a.attr("setflags")(py::arg("write") = false);
  return a;
}
}  // namespace

py::array vector_view(std::vector<Vec3>& values, py::handle owner, bool writable) {
  py::array a(py::dtype::of<Real>(), {py::ssize_t(values.size()), py::ssize_t(3)},
              {py::ssize_t(sizeof(Vec3)), py::ssize_t(sizeof(Real))},
              reinterpret_cast<const Real*>(values.data()), owner);
  if (!writable) a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::array index_view(const std::vector<std::uint32_t>& values, py::handle owner) {
  return scalar_view(values.data(), values.size(), owner, false);
}

std::vector<std::string> particle_array_names(const Particles& particles) {
  std::vector<std::string> names = {"position", "velocity", "mass", "type",
                                    "material", "id",       "body", "boundary_volume"};
  for (const auto& [name, field] : particles.scalar_fields()) names.push_back(name);
  for (const auto& [name, field] : particles.vector_fields()) names.push_back(name);
  return names;
}

py::array particle_array(Particles& p, const std::string& name, py::handle owner) {
  const bool w = writable_builtin(name);
  const std::size_t n = p.size();
  if (name == "position") return vector_view(p.position, owner, w);
  if (name == "velocity") return vector_view(p.velocity, owner, w);
  if (name == "mass") return scalar_view(p.mass.data(), n, owner, w);
  if (name == "type")
    return scalar_view(reinterpret_cast<const std::uint8_t*>(p.type.data()), n, owner, w);
  if (name == "material") return scalar_view(p.material.data(), n, owner, w);
  if (name == "id") return scalar_view(p.id.data(), n, owner, w);
  if (name == "body") return scalar_view(p.body.data(), n, owner, w);
  if (name == "boundary_volume") return scalar_view(p.boundary_volume.data(), n, owner, w);
  if (auto* v = p.find_vector(name)) return vector_view(*v, owner, true);
  if (const auto* s = p.find_scalar(name)) return scalar_view(s->data(), s->size(), owner, true);
  std::string known;
  for (const auto& k : particle_array_names(p)) known += (known.empty() ? "" : ", ") + k;
  throw py::key_error("no particle array named '" + name + "' (there are: " + known + ")");
}

}  // namespace upf::python
