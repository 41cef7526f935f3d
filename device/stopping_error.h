// StoppingError (compression_stats.h) on the device pipeline: the same value for every
// percentile choice. The average by an exact fixed-point sum, the largest exactly, a percentile
// by a sort of the owned particles' compressions (nearest rank, the value nth_element picks).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <thrust/sort.h>

#include "device/device_primitives.h"
#include "solvers/fluid/fluid_stages.h"

namespace upf::device {

namespace stopping_detail {
// The compression of the k-th owned particle into out[k].
struct ListedCompressionStage {
  ParticleRange listed;
  CompressionValue value;
  Real* out;
  UPF_HD void operator()(std::size_t k) const { out[k] = value(listed[k]); }
};
}  // namespace stopping_detail

template <class Backend>
class DeviceStoppingError {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  explicit DeviceStoppingError(double percentile = 0) : percentile_(percentile) {}

  double operator()(ParticleRange owned, const CompressionValue& value) {
    const DeviceExecutor<Backend> exec;
    if (owned.size == 0) return 0.0;
    if (percentile_ <= 0) return exec.fixed_point_sum(owned, value) / double(owned.size);
    if (percentile_ >= 100) return double(exec.max_of(owned, value));
    compressions_.resize(owned.size);
    exec.run(all_particles(owned.size),
             stopping_detail::ListedCompressionStage{owned, value, raw<Real>(compressions_)});
    thrust::sort(Backend::policy(), compressions_.begin(), compressions_.end());
    const auto rank =
        std::size_t(std::max(1.0, std::ceil(percentile_ / 100.0 * double(owned.size)))) - 1;
    return double(compressions_[rank]);
  }

  std::size_t bytes() const { return bytes_of(compressions_); }

 private:
  double percentile_;
  vector<Real> compressions_;
};

}  // namespace upf::device
