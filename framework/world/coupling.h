// What crosses materials within a step (DESIGN.md, "Boundaries and coupling"): the arrays through
// which one solver pushes another solver's particles, or the bodies. The world owns them, sizes
// and zeroes them before the solvers run, and orders the solvers so that every array is written
// before it is read: each solver declares, in its registration, what it writes and reads.
//
//   boundary_force  N, per particle: what liquids and grains exert on rigid boundary particles
//                   (Akinci et al. 2012, eq. 11), summed per body by the body systems (step 4)
//   liquid_force    N, per particle: what other materials exert on liquid particles (the
//                   reaction of the drag and buoyancy on grains), applied by the fluid solvers
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/vec3.h"

namespace upf {

enum class CouplingArray : std::uint8_t { BoundaryForce, LiquidForce };
inline constexpr int kCouplingArrayCount = 2;

inline constexpr std::string_view coupling_array_name(CouplingArray a) {
  return a == CouplingArray::BoundaryForce ? "boundary_force" : "liquid_force";
}

// A solver's use of the coupling arrays, declared in its SolverInfo. Several writers of one
// array add into it (in the solvers' order); every writer runs before every reader.
struct CouplingUse {
  std::vector<CouplingArray> writes;
  // Needed: a scene where no solver writes one of these is refused.
  std::vector<CouplingArray> reads;
  // Applied when some solver of the scene writes it (a fluid applies grain forces if grains
  // exist); ordered like `reads`.
  std::vector<CouplingArray> reads_if_written;
};

// The arrays, valid within one step. An array is active when some solver writes it and some
// solver or body system reads it: then it holds one value per particle, zeroed at the start of
// every step. An inactive array stays empty, and its writers skip it.
class CouplingArrays {
 public:
  std::vector<Vec3>& operator[](CouplingArray a) { return arrays_[std::size_t(a)]; }
  const std::vector<Vec3>& operator[](CouplingArray a) const { return arrays_[std::size_t(a)]; }
  bool active(CouplingArray a) const { return active_[std::size_t(a)]; }

  // World: which arrays are active (fixed in World::prepare), then every step: size and zero.
  void activate(CouplingArray a) { active_[std::size_t(a)] = true; }
  void reset(std::size_t particles);

 private:
  std::array<std::vector<Vec3>, kCouplingArrayCount> arrays_;
  std::array<bool, kCouplingArrayCount> active_{};
};

// The order in which to step solvers so that writers come before readers: a topological order
// that keeps the given order wherever the declarations allow it. Throws InputError naming the
// solvers when one needs an array nobody writes, or when the declarations form a cycle.
struct DeclaredSolver {
  std::string name;
  CouplingUse use;
};
std::vector<std::size_t> coupling_order(const std::vector<DeclaredSolver>& solvers);

}  // namespace upf
