#include "python_solver.h"

#include <cmath>
#include <utility>

#include "framework/world/world.h"
#include "python_callback.h"
#include "solver_world.h"

namespace py = pybind11;

namespace upf::python {

namespace {
// solver.<method>(world, args...), `world` an upf.solver.World over a handle that is revoked when
// the call returns.
template <class... Args>
py::object call_with_world(const py::object& solver, const char* method, World& world,
                           Args&&... args) {
  py::object handle = py::cast(SolverWorld(world, method));
  auto& revocable = handle.cast<SolverWorld&>();
  struct Revoke {
    SolverWorld& w;
    ~Revoke() { w.revoke(); }
  } revoke{revocable};
  const py::object world_view = py::module_::import("upf.solver").attr("World")(handle);
  return call_python([&] { return solver.attr(method)(world_view, std::forward<Args>(args)...); });
}

// What a method returned, for messages: its repr (cut short) and its type.
std::string shown(const py::handle& value) {
  return py::repr(value).cast<std::string>().substr(0, 80) + " (" +
         py::str(py::type::of(value).attr("__name__")).cast<std::string>() + ")";
}

// `value` as T, or a TypeError naming the solver, the method and the type it should have been:
// pybind11's own cast error names none of them.
template <class T>
T returned(const py::handle& value, const std::string& solver, const std::string& what,
           const char* expected) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error("solver '" + solver + "': " + what + " must be " + expected +
                         "; it returned " + shown(value));
  }
}
}  // namespace

PythonSolver::PythonSolver(std::string name, py::object solver)
    : name_(std::move(name)), solver_(std::move(solver)) {}

PythonSolver::~PythonSolver() {
  py::gil_scoped_acquire gil;
  solver_ = py::object();
}

void PythonSolver::prepare(World& world) {
  py::gil_scoped_acquire gil;
  call_with_world(solver_, "prepare", world);
}

Real PythonSolver::max_time_step(const World& world) const {
  py::gil_scoped_acquire gil;
  // The handle is the same kind as step's; the method is asked only for a number.
  const py::object dt = call_with_world(solver_, "max_time_step", const_cast<World&>(world));
  const double s = returned<double>(dt, name_, "max_time_step()",
                                    "a number: the largest stable step in seconds (math.inf for "
                                    "no limit)");
  if (std::isnan(s) || s <= 0)
    throw py::value_error("solver '" + name_ +
                          "': max_time_step() must return a step in seconds above 0 (math.inf "
                          "for no limit); it returned " +
                          shown(dt));
  return Real(s);
}

void PythonSolver::step(World& world, Real dt, StageRunner& run) {
  run(name_, [&] {
    py::gil_scoped_acquire gil;
    call_with_world(solver_, "step", world, double(dt));
  });
}

SolverStats PythonSolver::stats() const {
  py::gil_scoped_acquire gil;
  SolverStats s;
  const py::object result = call_python([&] { return solver_.attr("stats")(); });
  const std::string what = "stats()";
  if (!py::isinstance<py::dict>(result))
    throw py::type_error("solver '" + name_ + "': " + what +
                         " must return a dict (iterations, avg_density_error, "
                         "max_density_error); it returned " +
                         shown(result));
  const py::dict d = result;
  auto entry = [&](const char* key) { return what + "['" + key + "']"; };
  if (d.contains("iterations"))
    s.iterations = returned<int>(d["iterations"], name_, entry("iterations"), "an int");
  if (d.contains("avg_density_error"))
    s.avg_density_error =
        returned<double>(d["avg_density_error"], name_, entry("avg_density_error"), "a number");
  if (d.contains("max_density_error"))
    s.max_density_error =
        returned<double>(d["max_density_error"], name_, entry("max_density_error"), "a number");
  return s;
}

}  // namespace upf::python
