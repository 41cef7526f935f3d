// How busy the machine is, read from the operating system: this process's CPU time and the busy
// time of the cores it may run on. ThreadShareWatch (thread_share_watch.h) turns two readings into
// the number of cores the rest of the machine leaves free.
#pragma once

#include <optional>

namespace upf {

struct MachineLoadReading {
  double wall_seconds = 0;          // a monotonic clock
  double own_cpu_seconds = 0;       // every thread of this process
  double machine_busy_seconds = 0;  // summed over the cores this process may run on
  int cores = 0;                    // how many cores this process may run on
};

// Seconds on the monotonic clock the readings use.
double monotonic_seconds();

// Now, or nothing where the system does not say (a kernel without /proc/stat): the caller then
// keeps its threads as they are.
std::optional<MachineLoadReading> read_machine_load();

// How many of `later.cores` cores the rest of the machine left free between two readings: the
// cores minus the busy time that was not this process's, over the wall time between them.
double free_cores_between(const MachineLoadReading& earlier, const MachineLoadReading& later);

}  // namespace upf
