// A force written in Python on chosen particle types, as one more solver of the world's contract.
// It writes the coupling arrays that the movers of those types read (framework/world/coupling.h):
// on liquids CouplingArray::LiquidForce, which every fluid solver applies as a += F / m; on rigid
// boundary particles CouplingArray::BoundaryForce, which the body systems sum into each body's
// force and torque. The world orders it before its readers, so the force of a step acts in that
// step. The function receives the chosen particles' arrays at once (NumPy, vectorised) and
// returns one force per particle, in newtons.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/solver/solver.h"
#include "framework/world/coupling.h"

namespace upf::python {

class PythonForce final : public Solver {
 public:
  PythonForce(std::string name, pybind11::object function, TypeMask types);
  ~PythonForce() override;
  PythonForce(const PythonForce&) = delete;
  PythonForce& operator=(const PythonForce&) = delete;

  // The coupling arrays a force on `types` writes; InputError for types nothing could read it on.
  static CouplingUse coupling_use(TypeMask types, const std::string& name);

  std::string_view name() const override { return name_; }
  void prepare(World&) override {}
  Real max_time_step(const World&) const override;
  std::vector<std::string> stages() const override { return {name_}; }
  void step(World& world, Real dt, StageRunner& run) override;
  SolverStats stats() const override { return {}; }

 private:
  void apply(World& world, Real dt);

  std::string name_;
  pybind11::object function_;
  TypeMask types_;
  std::vector<std::uint32_t> chosen_;  // reused between steps
};

}  // namespace upf::python
