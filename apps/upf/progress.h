// Progress of a run on the terminal: a one-line bar (simulated time, steps per second, ETA) when
// stderr is a terminal, plain lines every few seconds otherwise (logs, CI).
#pragma once

#include <cstdio>

#include "framework/run/simulation_run.h"

namespace upf::app {

class ProgressReporter {
 public:
  explicit ProgressReporter(std::FILE* stream);
  void update(const RunProgress& p);
  void finish();

 private:
  std::FILE* stream_;
  bool terminal_;
  double last_print_ = -1;
  bool printed_ = false;
};

}  // namespace upf::app
