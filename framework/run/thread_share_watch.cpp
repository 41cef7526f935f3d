#include "framework/run/thread_share_watch.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace upf {

int threads_for_free_cores(double free_cores, int most_threads) {
  const int cores = int(std::floor(free_cores + 0.25));
  return std::clamp(cores, 1, std::max(1, most_threads));
}

ThreadShareWatch::ThreadShareWatch(int most_threads, double window_seconds,
                                   MachineLoadSource source)
    : most_threads_(most_threads), window_seconds_(window_seconds), source_(std::move(source)) {
  if (most_threads_ > 1) last_ = source_.read();
}

int ThreadShareWatch::threads_after_step(int current) {
  if (!last_) return current;  // one thread asked for, or the system does not say
  if (source_.wall_seconds() - last_->wall_seconds < window_seconds_) return current;
  const std::optional<MachineLoadReading> reading = source_.read();
  if (!reading) return current;
  if (reading->wall_seconds - last_->wall_seconds < window_seconds_) return current;
  const int threads = threads_for_free_cores(free_cores_between(*last_, *reading), most_threads_);
  last_ = reading;
  return threads;
}

}  // namespace upf
