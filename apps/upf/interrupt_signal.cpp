#include "interrupt_signal.h"

#include <csignal>

namespace upf::app {

namespace {
// A signal handler can reach nothing but static storage: this flag is the one piece of global
// state in upf, and only this file touches it.
volatile std::sig_atomic_t interrupt_flag = 0;

extern "C" void on_interrupt(int signal_number) {
  if (interrupt_flag != 0) {
    // Second signal: stop waiting for the step to end.
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
    return;
  }
  interrupt_flag = 1;
}
}  // namespace

InterruptSignal::InterruptSignal() {
  interrupt_flag = 0;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

InterruptSignal::~InterruptSignal() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

bool InterruptSignal::requested() const {
  return interrupt_flag != 0;
}

}  // namespace upf::app
