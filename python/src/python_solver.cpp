#include "python_solver.h"

#include <utility>

#include "framework/world/world.h"
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
  return solver.attr(method)(world_view, std::forward<Args>(args)...);
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
  return call_with_world(solver_, "max_time_step", const_cast<World&>(world)).cast<Real>();
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
  const py::dict d = solver_.attr("stats")();
  if (d.contains("iterations")) s.iterations = d["iterations"].cast<int>();
  if (d.contains("avg_density_error")) s.avg_density_error = d["avg_density_error"].cast<double>();
  if (d.contains("max_density_error")) s.max_density_error = d["max_density_error"].cast<double>();
  return s;
}

}  // namespace upf::python
