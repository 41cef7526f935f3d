// The registry in Python: what solvers there are, with their parameter specs, and Python solvers
// registered by name beside the built-ins (python_solver.h).
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <utility>

#include "apps/upf/app_registry.h"
#include "bindings.h"
#include "framework/core/errors.h"
#include "python_solver.h"
#include "registry_handle.h"
#include "type_names.h"

namespace py = pybind11;

namespace upf::python {

namespace {

py::dict spec_dict(const ParamSpec& s) {
  py::dict d;
  d["name"] = s.name;
  d["unit"] = s.unit;
  d["default"] = s.default_value;
  d["min"] = s.min_value;
  d["max"] = s.max_value;
  d["exclusive_min"] = s.exclusive_min;
  d["integer"] = s.integer;
  d["description"] = s.description;
  return d;
}

ParamSpec spec_from(const py::dict& d) {
  ParamSpec s;
  s.name = d["name"].cast<std::string>();
  s.unit = d.contains("unit") ? d["unit"].cast<std::string>() : "1";
  s.default_value = d.contains("default") ? d["default"].cast<double>() : 0.0;
  s.min_value = d.contains("min") ? d["min"].cast<double>() : -1e300;
  s.max_value = d.contains("max") ? d["max"].cast<double>() : 1e300;
  s.description = d.contains("description") ? d["description"].cast<std::string>() : "";
  s.integer = d.contains("integer") && d["integer"].cast<bool>();
  s.exclusive_min = d.contains("exclusive_min") && d["exclusive_min"].cast<bool>();
  return s;
}

std::vector<CouplingArray> coupling_arrays(const std::vector<std::string>& names,
                                           const std::string& argument) {
  std::vector<CouplingArray> out;
  for (const std::string& n : names) {
    bool found = false;
    for (int a = 0; a < kCouplingArrayCount; ++a)
      if (coupling_array_name(static_cast<CouplingArray>(a)) == n) {
        out.push_back(static_cast<CouplingArray>(a));
        found = true;
      }
    if (!found)
      throw py::value_error(argument + ": unknown coupling array '" + n +
                            "' (allowed: boundary_force, liquid_force)");
  }
  return out;
}

// A Python callable shared by copies of a std::function: copying never touches Python reference
// counts (copies may happen without the GIL), and the last owner lets go with the GIL held.
struct SharedCallable {
  py::object function;
  explicit SharedCallable(py::object f) : function(std::move(f)) {}
  ~SharedCallable() {
    py::gil_scoped_acquire gil;
    function = py::object();
  }
  SharedCallable(const SharedCallable&) = delete;
  SharedCallable& operator=(const SharedCallable&) = delete;
};

void add_python_solver(RegistryHandle& handle, const std::string& name, py::object factory,
                       const std::string& type, const std::vector<py::dict>& params,
                       const std::string& summary, const std::string& reference,
                       const std::vector<std::string>& writes,
                       const std::vector<std::string>& reads,
                       const std::vector<std::string>& reads_if_written) {
  if (handle.registry->find_solver(name))
    throw py::value_error("a solver named '" + name + "' is registered already");
  if (!py::hasattr(factory, "__call__"))
    throw py::type_error("add_solver('" + name + "'): factory must be callable");
  SolverInfo info;
  info.name = name;
  const auto t = parse_particle_type(type);
  if (!t)
    throw py::value_error("add_solver('" + name + "'): unknown particle type '" + type +
                          "' (allowed: liquid, rigid, granular, frozen)");
  info.type = *t;
  info.summary = summary;
  info.reference = reference;
  for (const py::dict& d : params) info.params.push_back(spec_from(d));
  info.coupling = {coupling_arrays(writes, "writes"), coupling_arrays(reads, "reads"),
                   coupling_arrays(reads_if_written, "reads_if_written")};
  auto shared = std::make_shared<SharedCallable>(std::move(factory));
  info.create = [shared, name](const ParamValues& values,
                               std::vector<MaterialId> materials) -> std::unique_ptr<Solver> {
    py::gil_scoped_acquire gil;
    py::object solver = shared->function(values.all(), materials);
    for (const char* method : {"prepare", "max_time_step", "step", "stats"})
      if (!py::hasattr(solver, method))
        throw InputError("solver '" + name + "'",
                         std::string("the factory's solver has no method ") + method +
                             "() (derive it from upf.Solver)");
    return std::make_unique<PythonSolver>(name, std::move(solver));
  };
  handle.registry->add_solver(std::move(info));
}

}  // namespace

void bind_registry(py::module_& m) {
  py::class_<RegistryHandle>(m, "Registry",
                             "The solvers, material kinds and scene sections scenes may name: the "
                             "built-ins, the extensions compiled in, and Python solvers.")
      .def(py::init(
          [] { return RegistryHandle{std::make_shared<Registry>(app::make_app_registry())}; }))
      .def(
          "solvers",
          [](const RegistryHandle& h) {
            py::list out;
            for (const SolverInfo& s : h.registry->solvers()) {
              py::dict d;
              d["name"] = s.name;
              d["type"] = std::string(to_string(s.type));
              d["summary"] = s.summary;
              d["reference"] = s.reference;
              py::list params;
              for (const ParamSpec& p : s.params) params.append(spec_dict(p));
              d["params"] = params;
              out.append(d);
            }
            return out;
          },
          "Every solver: name, particle type, summary, reference and parameter specs.")
      .def("add_solver", &add_python_solver, py::arg("name"), py::arg("factory"),
           py::arg("type") = "liquid", py::arg("params") = std::vector<py::dict>{},
           py::arg("summary") = "", py::arg("reference") = "",
           py::arg("writes") = std::vector<std::string>{},
           py::arg("reads") = std::vector<std::string>{},
           py::arg("reads_if_written") = std::vector<std::string>{});
}

}  // namespace upf::python
