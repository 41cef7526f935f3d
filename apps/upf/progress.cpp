#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace upf::app {

namespace {
// Seconds for the progress line: whole seconds while they are few, else 3 significant digits
// (%g), so an ETA from a tiny step or a huge end stays short instead of printing 300 digits.
std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, s < 1e6 ? "%.0f" : "%.3g", s);
  return text;
}
// Simulated times: 3 decimals, unless far from 1 s either way.
std::string sim_time(double t) {
  char text[32];
  const double a = std::abs(t);
  std::snprintf(text, sizeof text, a == 0 || (a >= 1e-3 && a < 1e6) ? "%.3f" : "%.3g", t);
  return text;
}
}  // namespace

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
    std::fprintf(stream_, "\r[%s] t = %s / %s s  %6.1f steps/s  ETA %5s s  %d %s ", bar.c_str(),
                 sim_time(p.time).c_str(), sim_time(p.end_time).c_str(), steps_per_s,
                 seconds(eta).c_str(), p.threads, p.threads == 1 ? "thread " : "threads");
  } else {
    std::fprintf(stream_, "t = %s / %s s (%3.0f%%), %llu steps, %.1f steps/s, ETA %s s, %d %s\n",
                 sim_time(p.time).c_str(), sim_time(p.end_time).c_str(), 100.0 * fraction,
                 static_cast<unsigned long long>(p.steps), steps_per_s, seconds(eta).c_str(),
                 p.threads, p.threads == 1 ? "thread" : "threads");
  }
  std::fflush(stream_);
  printed_ = true;
}

void ProgressReporter::finish() {
  if (terminal_ && printed_) std::fprintf(stream_, "\n");
}

}  // namespace upf::app
