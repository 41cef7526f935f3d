// upf.Simulation's compiled half: loading a scene, stepping (the GIL released while C++ steps),
// runs and comparisons, particle arrays as NumPy views, bodies, Python forces.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "bindings.h"
#include "framework/compare/compare_plan.h"
#include "framework/compare/compare_report.h"
#include "framework/compare/comparison.h"
#include "framework/core/errors.h"
#include "framework/output/vdb_frame_writers.h"
#include "framework/run/run_result_json.h"
#include "framework/scene/scene_reader.h"
#include "framework/scene/solver_override.h"
#include "numpy_views.h"
#include "python_force.h"
#include "registry_handle.h"
#include "simulation.h"
#include "type_names.h"

namespace py = pybind11;

namespace upf::python {

namespace {

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the scene file");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The `upf` program's limit (its --threads option): far more threads than cores only costs, and
// OpenMP cannot start 100,000 of them (the first step crashed).
constexpr int kMaxThreads = 1024;

void check_threads(int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw InputError("threads", std::to_string(threads) + " is outside 0 (OpenMP's default) to " +
                                    std::to_string(kMaxThreads));
}

// A simulation of `scene` read from `text` (kept as the run's upf_scene.json); `solver` replaces
// every liquid material's solver (upf run --solver).
std::unique_ptr<Simulation> make_simulation(SceneDescription scene, std::string text,
                                            const RegistryHandle& registry, int threads,
                                            const std::string& solver, const std::string& device,
                                            const std::string& source) {
  check_threads(threads);
  if (!solver.empty()) scene = with_solver(scene, *registry.registry, solver);
  // The argument overrides the scene's key, as `upf run --device` does.
  std::string where = source + ":/device";
  if (!device.empty()) {
    scene.device = device;
    where = "device";
  }
  return std::make_unique<Simulation>(std::move(scene), registry.registry, threads, std::move(text),
                                      std::move(where));
}

py::dict body_dict(const NamedBodyState& b) {
  auto vec = [](const Eigen::Vector3d& v) { return py::make_tuple(v.x(), v.y(), v.z()); };
  const Eigen::Quaterniond& q = b.state.orientation;
  py::dict d;
  d["name"] = b.name;
  d["position"] = vec(b.state.position);
  d["orientation"] = py::make_tuple(q.w(), q.x(), q.y(), q.z());
  d["velocity"] = vec(b.state.velocity);
  d["angular_velocity"] = vec(b.state.angular_velocity);
  d["fluid_force"] = vec(b.state.fluid_force);
  d["fluid_torque"] = vec(b.state.fluid_torque);
  return d;
}

py::object compare(const std::filesystem::path& scene_file, const std::vector<std::string>& solvers,
                   const std::filesystem::path& out, std::optional<double> end, int threads,
                   bool frames, const RegistryHandle& registry) {
  check_threads(threads);
  const Registry& r = *registry.registry;
  const SceneDescription scene = load_scene_file(scene_file, r);
  const auto plan =
      plan_comparison(scene, r, solvers.empty() ? solvers_for_scene(scene, r) : solvers);
  CompareOptions options;
  options.out_dir = out;
  options.vdb_writers = vdb_frame_writers();
  options.threads = threads;
  options.end_time = end;
  options.write_frames = frames;
  {
    py::gil_scoped_release release;
    const Comparison comparison = run_comparison(plan, r, options);
    const PlotOutcome plots = write_compare_report(comparison, out, UPF_PLOT_SCRIPT);
    (void)plots;  // report.json says which plots exist; the tables are there either way
  }
  return py::module_::import("json").attr("loads")(py::str(read_text(out / "report.json")));
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path, int threads, const std::string& solver,
             const RegistryHandle& registry, const std::string& device) {
            // load_scene_file names the file in every error, a missing one included.
            SceneDescription scene = load_scene_file(path, *registry.registry);
            return make_simulation(std::move(scene), read_text(path), registry, threads, solver,
                                   device, path.string());
          },
          py::arg("path"), py::arg("threads"), py::arg("solver"), py::arg("registry"),
          py::arg("device"))
      .def_static(
          "from_text",
          [](const std::string& text, const std::string& source, int threads,
             const std::string& solver, const RegistryHandle& registry, const std::string& device) {
            const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
            if (document.is_discarded())
              throw InputError(source, "not valid JSON (NaN and infinities have no JSON form)");
            SceneDescription scene = read_scene(document, *registry.registry, source);
            return make_simulation(std::move(scene), text, registry, threads, solver, device,
                                   source);
          },
          py::arg("text"), py::arg("source"), py::arg("threads"), py::arg("solver"),
          py::arg("registry"), py::arg("device"))
      .def_property_readonly("device", [](const Simulation& s) { return s.scene().device; })
      .def_property_readonly("name", [](const Simulation& s) { return s.scene().name; })
      .def_property_readonly("time", &Simulation::time)
      .def_property_readonly("step_count", &Simulation::step_count)
      .def_property_readonly("generation", &Simulation::generation)
      .def_property_readonly("fps", [](const Simulation& s) { return s.scene().output.fps; })
      .def_property_readonly("end_time",
                             [](const Simulation& s) { return s.scene().world.time.end; })
      .def_property_readonly("spacing", [](const Simulation& s) { return s.scene().world.spacing; })
      .def("step", &Simulation::step, py::call_guard<py::gil_scoped_release>())
      .def(
          "advance_to",
          [](Simulation& s, double t) {
            // Ctrl-C between steps ends a long advance with KeyboardInterrupt, the world whole.
            s.advance_to(t, [] {
              py::gil_scoped_acquire gil;
              if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            });
          },
          py::arg("time"), py::call_guard<py::gil_scoped_release>())
      .def(
          "run",
          [](Simulation& s, const std::filesystem::path& out, std::optional<double> end,
             bool frames, bool overwrite) {
            RunResult r;
            {
              py::gil_scoped_release release;
              r = s.run(out, end, frames, overwrite);
            }
            return json_to_python(run_result_json(r));
          },
          py::arg("out"), py::arg("end") = py::none(), py::arg("frames") = true,
          py::arg("overwrite") = false)
      .def(
          "array",
          [](py::object self, const std::string& name) {
            return particle_array(self.cast<Simulation&>().world().particles(), name, self);
          },
          py::arg("name"))
      .def("array_names", [](Simulation& s) { return particle_array_names(s.world().particles()); })
      .def("size", [](Simulation& s) { return s.world().particles().size(); })
      .def("prepare", [](Simulation& s) { s.world(); })
      .def("stage_names", [](Simulation& s) { return s.world().stage_names(); })
      .def("last_step",
           [](Simulation& s) {
             const StepReport& r = s.world().last_step();
             py::dict d;
             d["dt"] = r.dt;
             d["iterations"] = r.solver.iterations;
             d["avg_density_error"] = r.solver.avg_density_error;
             d["max_density_error"] = r.solver.max_density_error;
             // Implicit viscosity's conjugate gradient iterations; -1 without one.
             d["viscosity_iterations"] = r.solver.viscosity_iterations;
             d["stage_ms"] = r.stage_ms;
             return d;
           })
      .def("bodies",
           [](Simulation& s) {
             py::list out;
             for (const auto& system : s.world().body_systems())
               for (const NamedBodyState& b : system->body_states()) out.append(body_dict(b));
             return out;
           })
      .def(
          "set_body_velocity",
          [](Simulation& s, const std::string& name, const std::array<double, 3>& v,
             const std::array<double, 3>& w) {
            std::vector<std::string> names;
            for (const auto& system : s.world().body_systems()) {
              const auto states = system->body_states();
              for (std::size_t b = 0; b < states.size(); ++b) {
                names.push_back(states[b].name);
                if (states[b].name != name) continue;
                if (!system->set_velocity(b, {v[0], v[1], v[2]}, {w[0], w[1], w[2]}))
                  throw py::value_error("body '" + name +
                                        "' is static or kinematic: its motion is prescribed");
                return;
              }
            }
            std::string known;
            for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
            throw py::key_error("no body named '" + name +
                                "' (there are: " + (known.empty() ? "none" : known) + ")");
          },
          py::arg("name"), py::arg("velocity"), py::arg("angular_velocity"))
      .def(
          "add_force",
          [](Simulation& s, const std::string& name, py::object function,
             const std::vector<std::string>& types) {
            if (!py::hasattr(function, "__call__"))
              throw py::type_error("add_force('" + name + "'): the force must be callable");
            const TypeMask mask = type_mask(types, "add_force('" + name + "') types");
            CouplingUse use = PythonForce::coupling_use(mask, name);
            s.add_solver(std::make_unique<PythonForce>(name, std::move(function), mask),
                         std::move(use));
          },
          py::arg("name"), py::arg("function"), py::arg("types"))
      .def_property_readonly("failure", &Simulation::failure);

  m.def("compare", &compare, py::arg("scene"), py::arg("solvers"), py::arg("out"), py::arg("end"),
        py::arg("threads"), py::arg("frames"), py::arg("registry"));
}

}  // namespace upf::python
