// Fewer threads while the machine is busy (docs/solvers.md, "On a busy machine"). A static
// OpenMP schedule waits at every barrier for its slowest thread, so one thread that shares its
// core with another process holds every thread to its pace: beside one busy process, two threads
// ran the demo 3 times slower than on an idle machine, one thread 1.9 times. The watch measures,
// over every half second of wall time, how many cores the rest of the machine left free, and
// the run then uses that many threads (at least 1, at most the count asked for), coming back up
// when the cores free again. Results are the same bits for any thread count (cpu_executor.h), so
// this changes the speed only.
#pragma once

#include <functional>
#include <optional>

#include "framework/run/machine_load.h"
#include "framework/world/world.h"

namespace upf {

// The threads to run beside a machine that leaves `free_cores` free: a thread per free core,
// where a core three quarters free counts (its other user sleeps most of the time), and at least
// one.
int threads_for_free_cores(double free_cores, int most_threads);

// Where the watch gets its readings: the system's, or a test's.
struct MachineLoadSource {
  std::function<std::optional<MachineLoadReading>()> read = read_machine_load;
  std::function<double()> wall_seconds = monotonic_seconds;  // the readings' clock
};

class ThreadShareWatch {
 public:
  explicit ThreadShareWatch(int most_threads, double window_seconds = 0.5,
                            MachineLoadSource source = {});

  // Called between steps with the count in use: the count for the steps that follow. It reads
  // the machine only once a window has passed since its last reading, so most calls cost a clock
  // read.
  int threads_after_step(int current);

 private:
  int most_threads_;
  double window_seconds_;
  MachineLoadSource source_;
  std::optional<MachineLoadReading> last_;
};

// Gives a world back the thread count it had when the keeper was made, however the scope ends.
class ThreadCountKeeper {
 public:
  explicit ThreadCountKeeper(World& world) : world_(world), threads_(world.executor().threads()) {}
  ~ThreadCountKeeper() { world_.set_threads(threads_); }
  ThreadCountKeeper(const ThreadCountKeeper&) = delete;
  ThreadCountKeeper& operator=(const ThreadCountKeeper&) = delete;

 private:
  World& world_;
  int threads_;
};

}  // namespace upf
