// Ctrl-C for long runs: while an InterruptSignal lives, SIGINT and SIGTERM do not kill the
// program but raise a flag that the run polls after every step; the run then writes a
// checkpoint and its summary and stops (exit code 130). A second Ctrl-C while the flag is up
// falls back to the default action, so a stuck program can still be killed.
#pragma once

namespace upf::app {

class InterruptSignal {
 public:
  InterruptSignal();
  ~InterruptSignal();
  InterruptSignal(const InterruptSignal&) = delete;
  InterruptSignal& operator=(const InterruptSignal&) = delete;

  bool requested() const;
};

}  // namespace upf::app
