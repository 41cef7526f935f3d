// What a per-particle stage is (DESIGN.md, "Stages, executors and backends"): a small struct that
// holds plain views (raw pointers, sizes, kernels, CSR neighbour views) by value and has
//   UPF_HD void operator()(std::uint32_t i) const,
// which writes only particle i's outputs. Nothing in it refers to host objects, so the same struct
// can be copied to a device or run on another rank's arrays; executors refuse anything else.
//
// A per-particle value (for reductions) is the same kind of struct whose operator() returns the
// particle's contribution.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "framework/executors/particle_range.h"

namespace upf {

template <class Stage>
concept ParticleStage =
    std::is_trivially_copyable_v<Stage> && std::invocable<const Stage&, std::uint32_t>;

template <class Value>
concept ParticleValue = std::is_trivially_copyable_v<Value> && requires(const Value& v) {
  { v(std::uint32_t{}) } -> std::convertible_to<double>;
};

template <class Predicate>
concept ParticlePredicate = std::is_trivially_copyable_v<Predicate> &&
    requires(const Predicate& p) {
  { p(std::uint32_t{}) } -> std::convertible_to<bool>;
};

}  // namespace upf
