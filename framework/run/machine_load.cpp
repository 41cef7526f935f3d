#include "framework/run/machine_load.h"

#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace upf {
namespace {

double seconds_of(clockid_t clock) {
  timespec t{};
  if (clock_gettime(clock, &t) != 0) return -1;
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

}  // namespace

double monotonic_seconds() {
  return seconds_of(CLOCK_MONOTONIC);
}

std::optional<MachineLoadReading> read_machine_load() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return std::nullopt;
  const long ticks_per_second = sysconf(_SC_CLK_TCK);
  std::ifstream stat("/proc/stat");
  if (!stat || ticks_per_second <= 0) return std::nullopt;
  MachineLoadReading r;
  r.wall_seconds = seconds_of(CLOCK_MONOTONIC);
  r.own_cpu_seconds = seconds_of(CLOCK_PROCESS_CPUTIME_ID);
  if (r.wall_seconds < 0 || r.own_cpu_seconds < 0) return std::nullopt;
  // Lines "cpuN user nice system idle iowait irq softirq steal guest guest_nice", in ticks; the
  // guest times are already inside user and nice.
  std::uint64_t busy = 0;
  std::string line;
  while (std::getline(stat, line)) {
    if (line.rfind("cpu", 0) != 0 || line.size() < 4 || line[3] < '0' || line[3] > '9') continue;
    std::istringstream fields(line.substr(3));
    int cpu = -1;
    std::uint64_t user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0,
                  steal = 0;
    fields >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
    if (!fields || cpu < 0 || cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &allowed)) continue;
    busy += user + nice + system + irq + softirq + steal;
    ++r.cores;
  }
  if (r.cores == 0) return std::nullopt;
  r.machine_busy_seconds = double(busy) / double(ticks_per_second);
  return r;
}

double free_cores_between(const MachineLoadReading& earlier, const MachineLoadReading& later) {
  const double wall = later.wall_seconds - earlier.wall_seconds;
  if (wall <= 0) return later.cores;
  const double others = (later.machine_busy_seconds - earlier.machine_busy_seconds) -
                        (later.own_cpu_seconds - earlier.own_cpu_seconds);
  return std::clamp(later.cores - others / wall, 0.0, double(later.cores));
}

}  // namespace upf
