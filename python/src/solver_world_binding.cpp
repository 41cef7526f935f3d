// Python's view of the world inside a Python solver's call (solver_world.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>

#include "bindings.h"
#include "framework/core/errors.h"
#include "numpy_views.h"
#include "solver_world.h"
#include "type_names.h"

namespace py = pybind11;

namespace upf::python {

World& SolverWorld::world() const {
  if (!world_)
    throw std::runtime_error("this world handle was valid only during the solver's " + call_ +
                             "() call: the world may have reordered its arrays since");
  return *world_;
}

namespace {
py::dict material_dict(const Material& m) {
  py::dict d;
  d["name"] = m.name;
  d["kind"] = m.kind;
  d["type"] = std::string(to_string(m.type));
  d["solver"] = m.solver;
  d["params"] = m.params.all();
  d["solver_params"] = m.solver_params.all();
  return d;
}
}  // namespace

void bind_solver_world(py::module_& m) {
  py::class_<SolverWorld>(m, "SolverWorld",
                          "The world as a Python solver sees it during one call (prepare, "
                          "max_time_step, step).")
      .def_property_readonly("valid", &SolverWorld::valid)
      .def_property_readonly("time", [](const SolverWorld& w) { return w.world().time(); })
      .def_property_readonly("size",
                             [](const SolverWorld& w) { return w.world().particles().size(); })
      .def_property_readonly("spacing",
                             [](const SolverWorld& w) { return w.world().settings().spacing; })
      .def_property_readonly(
          "support_radius",
          [](const SolverWorld& w) { return w.world().settings().support_radius(); })
      .def_property_readonly("gravity",
                             [](const SolverWorld& w) {
                               const Vec3 g = w.world().settings().gravity;
                               return py::make_tuple(g.x, g.y, g.z);
                             })
      .def_property_readonly("materials",
                             [](const SolverWorld& w) {
                               py::list out;
                               for (const Material& mat : w.world().materials().all())
                                 out.append(material_dict(mat));
                               return out;
                             })
      .def_property_readonly(
          "array_names",
          [](const SolverWorld& w) { return particle_array_names(w.world().particles()); })
      .def(
          "array",
          [](py::object self, const std::string& name) {
            return particle_array(self.cast<SolverWorld&>().world().particles(), name, self);
          },
          py::arg("name"), "A particle array or field by name, without a copy.")
      .def(
          "declare_scalar",
          [](SolverWorld& w, const std::string& name, Real init, bool exported) {
            w.world().particles().declare_scalar(name, init, exported);
          },
          py::arg("name"), py::arg("init") = Real(0), py::arg("exported") = false,
          "Creates a per-particle scalar field (in prepare); exported fields go into frames.")
      .def(
          "declare_vector",
          [](SolverWorld& w, const std::string& name, bool exported, bool positions) {
            Particles& p = w.world().particles();
            if (positions) p.declare_position_vector(name);
            p.declare_vector(name, Vec3{}, exported);
          },
          py::arg("name"), py::arg("exported") = false, py::arg("positions") = false,
          "Creates a per-particle 3-vector field (in prepare), zero to start with; positions=True "
          "for a field of positions (a predicted position), which a periodic domain's images "
          "hold shifted by the period.")
      .def(
          "request_neighbours",
          [](SolverWorld& w, const std::vector<std::string>& query,
             const std::vector<std::string>& target, Real radius) {
            return w.world().request_neighbours(type_mask(query, "query"),
                                                type_mask(target, "target"), radius);
          },
          py::arg("query"), py::arg("target"), py::arg("radius") = Real(0),
          "Asks (in prepare) for neighbour lists from the query types to the target types, "
          "rebuilt every step; returns the handle for neighbours().")
      .def(
          "neighbours",
          [](py::object self, int handle) {
            World& world = self.cast<SolverWorld&>().world();
            if (handle < 0) throw py::index_error("no neighbour list " + std::to_string(handle));
            const NeighbourList* list = nullptr;
            try {
              list = &world.neighbours(handle);
            } catch (const std::out_of_range&) {
              throw py::index_error("no neighbour list " + std::to_string(handle) +
                                    ": request_neighbours() in prepare() gives the handles");
            }
            return py::make_tuple(index_view(list->offsets, self), index_view(list->indices, self));
          },
          py::arg("handle"),
          "(offsets, indices): the neighbours of particle i are indices[offsets[i]:offsets[i+1]].")
      .def(
          "coupling",
          [](py::object self, const std::string& name) -> py::object {
            World& world = self.cast<SolverWorld&>().world();
            for (int a = 0; a < kCouplingArrayCount; ++a) {
              const auto array = static_cast<CouplingArray>(a);
              if (coupling_array_name(array) != name) continue;
              if (!world.coupling().active(array)) return py::none();
              return vector_view(world.coupling()[array], self, true);
            }
            throw py::key_error("no coupling array '" + name +
                                "' (there are: boundary_force, liquid_force)");
          },
          py::arg("name"),
          "A coupling array (boundary_force, liquid_force) in N per particle, or None when "
          "nothing in this scene reads it.");
}

}  // namespace upf::python
