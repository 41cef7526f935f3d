// The executor primitives of the device pipeline, for any backend (device_backend_*.h): running
// a particle stage over a range, and the reductions of CpuExecutor with the same results to the
// bit (max, exact fixed-point sums, the smallest id). Every stage is the same struct the CPU
// executor runs (particle_stage.h); only the loop around it differs. C++17: nvcc compiles it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <thrust/copy.h>
#include <thrust/for_each.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform_reduce.h>

#include "framework/core/fixed_point_term.h"
#include "framework/core/vec3.h"
#include "framework/executors/particle_range.h"

namespace upf::device {

template <class T, class Vector>
T* raw(Vector& v) {
  return thrust::raw_pointer_cast(v.data());
}
template <class T, class Vector>
const T* raw(const Vector& v) {
  return thrust::raw_pointer_cast(v.data());
}

// A host vector into a backend's vector, resized to fit; and back.
template <class DeviceVector, class T>
void copy_to_device(DeviceVector& to, const std::vector<T>& from) {
  to.resize(from.size());
  thrust::copy(from.begin(), from.end(), to.begin());
}
template <class T, class DeviceVector>
void copy_to_host(std::vector<T>& to, const DeviceVector& from) {
  to.resize(from.size());
  thrust::copy(from.begin(), from.end(), to.begin());
}

// Device memory a buffer holds.
template <class Vector>
std::size_t bytes_of(const Vector& v) {
  return v.capacity() * sizeof(typename Vector::value_type);
}

// stage(range[k]) for the k-th listed particle.
template <class Stage>
struct RangeLoop {
  Stage stage;
  ParticleRange range;
  UPF_HD void operator()(std::size_t k) const { stage(range[k]); }
};

template <class Backend, class Stage>
void run(ParticleRange range, const Stage& stage) {
  if (range.size == 0) return;
  thrust::for_each(Backend::policy(), thrust::counting_iterator<std::size_t>(0),
                   thrust::counting_iterator<std::size_t>(range.size),
                   RangeLoop<Stage>{stage, range});
}

// f(k) for k in [0, n): the pipeline's own index loops (cells, sort slots, lists).
template <class Backend, class Function>
void for_each_index(std::size_t n, const Function& f) {
  if (n == 0) return;
  thrust::for_each(Backend::policy(), thrust::counting_iterator<std::size_t>(0),
                   thrust::counting_iterator<std::size_t>(n), f);
}

struct MaxOf {
  template <class T>
  UPF_HD T operator()(const T& a, const T& b) const {
    return a < b ? b : a;
  }
};
struct MinOf {
  template <class T>
  UPF_HD T operator()(const T& a, const T& b) const {
    return b < a ? b : a;
  }
};
struct Plus {
  template <class T>
  UPF_HD T operator()(const T& a, const T& b) const {
    return a + b;
  }
};

template <class Value>
struct RangeValueAsReal {
  Value value;
  ParticleRange range;
  UPF_HD Real operator()(std::size_t k) const { return Real(value(range[k])); }
};

// The largest value(i) over `range`, and `floor` when that is larger: CpuExecutor::max_of.
template <class Backend, class Value>
Real max_of(ParticleRange range, const Value& value, Real floor = 0) {
  if (range.size == 0) return floor;
  return thrust::transform_reduce(Backend::policy(), thrust::counting_iterator<std::size_t>(0),
                                  thrust::counting_iterator<std::size_t>(range.size),
                                  RangeValueAsReal<Value>{value, range}, floor, MaxOf{});
}

template <class Value>
struct RangeValueAsFixedPoint {
  Value value;
  ParticleRange range;
  double scale;
  double limit;
  UPF_HD std::int64_t operator()(std::size_t k) const {
    return fixed_point_term(double(value(range[k])), scale, limit);
  }
};

// CpuExecutor::fixed_point_sum: exact, so the order of additions (a tree here) does not matter.
template <class Backend, class Value>
double fixed_point_sum(ParticleRange range, const Value& value, int fraction_bits = 32) {
  const double scale = std::ldexp(1.0, fraction_bits);
  if (range.size == 0) return 0.0;
  const std::int64_t total = thrust::transform_reduce(
      Backend::policy(), thrust::counting_iterator<std::size_t>(0),
      thrust::counting_iterator<std::size_t>(range.size),
      RangeValueAsFixedPoint<Value>{value, range, scale, fixed_point_term_limit(range.size)},
      std::int64_t(0), Plus{});
  return double(total) / scale;
}

// (id << 32 | index) of particle i when holds(i), else all ones: the minimum names the particle
// with the smallest id, as CpuExecutor::first_by_id.
template <class Predicate>
struct IdKeyWhere {
  Predicate holds;
  const std::uint32_t* id;
  UPF_HD std::uint64_t operator()(std::size_t i) const {
    return holds(std::uint32_t(i)) ? (std::uint64_t(id[i]) << 32) | std::uint64_t(i)
                                   : ~std::uint64_t(0);
  }
};

template <class Backend, class Predicate>
std::size_t first_by_id(std::size_t n, const std::uint32_t* id, const Predicate& holds) {
  if (n == 0) return 0;
  const std::uint64_t best =
      thrust::transform_reduce(Backend::policy(), thrust::counting_iterator<std::size_t>(0),
                               thrust::counting_iterator<std::size_t>(n),
                               IdKeyWhere<Predicate>{holds, id}, ~std::uint64_t(0), MinOf{});
  return best == ~std::uint64_t(0) ? n : std::size_t(best & 0xffffffffu);
}

// The ghosts a device pipeline holds (its periodic images, device_images.h), refreshed after
// every shared stage as CpuExecutor::run refreshes a domain's through its rank collectives.
class DeviceGhosts {
 public:
  virtual void refresh_ghosts() const = 0;

 protected:
  ~DeviceGhosts() = default;
};

// The primitives above as an executor object with CpuExecutor's interface, so orchestration
// written once for both (pcisph_correction_loop.h) runs on a backend unchanged.
template <class Backend>
struct DeviceExecutor {
  const DeviceGhosts* ghosts = nullptr;  // null: no ghosts

  template <class Stage>
  void run(ParticleRange range, const Stage& stage) const {
    device::run<Backend>(range, stage);
    if (ghosts) ghosts->refresh_ghosts();
  }
  // Without the ghost refresh (CpuExecutor::run_unshared).
  template <class Stage>
  void run_unshared(ParticleRange range, const Stage& stage) const {
    device::run<Backend>(range, stage);
  }
  template <class Value>
  Real max_of(ParticleRange range, const Value& value, Real floor = 0) const {
    return device::max_of<Backend>(range, value, floor);
  }
  template <class Value>
  double fixed_point_sum(ParticleRange range, const Value& value, int fraction_bits = 32) const {
    return device::fixed_point_sum<Backend>(range, value, fraction_bits);
  }
  // One device holds every particle (CpuExecutor::total).
  std::size_t total(std::size_t local) const { return local; }
};

}  // namespace upf::device
