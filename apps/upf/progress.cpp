#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <string>

namespace upf::app {

ProgressReporter::ProgressReporter(std::FILE* stream)
    : stream_(stream), terminal_(isatty(fileno(stream)) != 0) {}

void ProgressReporter::update(const RunProgress& p) {
  const double interval = terminal_ ? 0.2 : 5.0;
  if (p.wall_seconds - last_print_ < interval && p.time < p.end_time) return;
  last_print_ = p.wall_seconds;
  const double fraction = p.end_time > 0 ? std::clamp(p.time / p.end_time, 0.0, 1.0) : 1.0;
  const double steps_per_s =
      p.wall_seconds > 0 ? double(p.steps_this_process) / p.wall_seconds : 0.0;
  const double done = p.time - p.start_time;  // simulated by this process
  const double eta = done > 0 ? p.wall_seconds * std::max(0.0, p.end_time - p.time) / done : 0.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(std::size_t(filled), '#');
    bar.resize(kWidth, '-');
    std::fprintf(stream_, "\r[%s] t = %.3f / %.3f s  %6.1f steps/s  ETA %5.0f s ", bar.c_str(),
                 p.time, p.end_time, steps_per_s, eta);
  } else {
    std::fprintf(stream_, "t = %.3f / %.3f s (%3.0f%%), %llu steps, %.1f steps/s, ETA %.0f s\n",
                 p.time, p.end_time, 100.0 * fraction, static_cast<unsigned long long>(p.steps),
                 steps_per_s, eta);
  }
  std::fflush(stream_);
  printed_ = true;
}

void ProgressReporter::finish() {
  if (terminal_ && printed_) std::fprintf(stream_, "\n");
}

}  // namespace upf::app
