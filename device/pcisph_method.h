// PCISPH's pressure stage (Solenthaler & Pajarola 2009) in the device pipeline (fluid_pipeline.h):
// the positions of the particles it does not move predicted once, then the shared correction loop
// (pcisph_correction_loop.h) with a stopping error computed on the device: the average by an exact
// fixed-point sum, the maximum exactly, a percentile by a sort (StoppingError's values).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include <thrust/sort.h>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "device/fluid_setup.h"
#include "solvers/fluid/fluid_stages.h"
#include "solvers/pcisph/pcisph_correction_loop.h"

namespace upf::device {

namespace pcisph_detail {
// The compression of the k-th owned particle into out[k].
struct ListedCompressionStage {
  ParticleRange listed;
  CompressionValue value;
  Real* out;
  UPF_HD void operator()(std::size_t k) const { out[k] = value(listed[k]); }
};
}  // namespace pcisph_detail

template <class Backend>
class PcisphMethod {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  using Setup = PcisphSetup;
  explicit PcisphMethod(PcisphSetup setup) : setup_(std::move(setup)) {}

  void bind(DeviceParticles<Backend>& p) {
    rho_star_ = &p.scalar_array(setup_.predicted_density);
    x_star_ = &p.vector_array(setup_.predicted_position);
  }

  template <class Executor, class Step>
  void non_pressure(const Executor& exec, const Step& s) const {
    exec.run(s.owned, ClearPressureStage{s.pressure, s.pressure_acceleration});
  }

  template <class Executor, class Step>
  SolverStats pressure(const Executor& exec, const Step& s) {
    Vec3* x_star = raw<Vec3>(*x_star_);
    Real* rho_star = raw<Real>(*rho_star_);
    exec.run(all_particles(s.n), PredictUnownedStage{s.f, s.owns, s.dt, x_star});
    const PcisphLoopArrays arrays{s.f,
                                  s.owned,
                                  s.other_acceleration,
                                  s.fluid_gradient,
                                  s.boundary_gradient,
                                  s.pressure_acceleration,
                                  x_star,
                                  rho_star,
                                  s.pressure};
    return pcisph_correction_loop(
        exec, arrays, setup_.loop, s.dt,
        [&](const CompressionValue& value) { return stopping_error(exec, s.owned, value); });
  }

  std::size_t bytes() const { return bytes_of(compressions_); }

 private:
  template <class Executor>
  double stopping_error(const Executor& exec, ParticleRange owned, const CompressionValue& value) {
    const double percentile = setup_.stop_percentile;
    if (owned.size == 0) return 0.0;
    if (percentile <= 0) return exec.fixed_point_sum(owned, value) / double(owned.size);
    if (percentile >= 100) return double(exec.max_of(owned, value));
    compressions_.resize(owned.size);
    exec.run(all_particles(owned.size),
             pcisph_detail::ListedCompressionStage{owned, value, raw<Real>(compressions_)});
    thrust::sort(Backend::policy(), compressions_.begin(), compressions_.end());
    const auto rank =
        std::size_t(std::max(1.0, std::ceil(percentile / 100.0 * double(owned.size)))) - 1;
    return double(compressions_[rank]);
  }

  PcisphSetup setup_;
  vector<Real> compressions_;
  vector<Real>* rho_star_ = nullptr;
  vector<Vec3>* x_star_ = nullptr;
};

}  // namespace upf::device
