// ThreadShareWatch (framework/run/thread_share_watch.h): a run on a busy machine uses one thread
// per core that the other processes leave free. The reference for the counts is CFS's fair share:
// n runnable threads on c cores each get c / n of a core.
#include <gtest/gtest.h>

#include <deque>

#include "framework/run/thread_share_watch.h"

namespace upf {
namespace {

MachineLoadReading reading(double wall, double own_cpu, double busy, int cores = 2) {
  return {wall, own_cpu, busy, cores};
}

TEST(ThreadShareWatch, OneThreadPerFreeCore) {
  EXPECT_EQ(threads_for_free_cores(2.0, 2), 2);
  EXPECT_EQ(threads_for_free_cores(1.9, 2), 2);  // background noise keeps both threads
  // Two threads beside one busy process on 2 cores: the three share them, each 2/3 of a core.
  EXPECT_EQ(threads_for_free_cores(2.0 - 2.0 / 3.0, 2), 1);
  EXPECT_EQ(threads_for_free_cores(1.0, 2), 1);
  EXPECT_EQ(threads_for_free_cores(0.0, 2), 1);  // never none
  EXPECT_EQ(threads_for_free_cores(4.0, 2), 2);  // never more than asked for
  // Four threads beside one busy process on 4 cores: 4/5 of a core each, 3.2 cores free.
  EXPECT_EQ(threads_for_free_cores(3.2, 4), 3);
}

TEST(ThreadShareWatch, FreeCoresAreTheCoresLessTheOtherProcessesBusyTime) {
  // 1 s: the machine's 2 cores were busy 2 s, 4/3 s of it this process's.
  EXPECT_NEAR(free_cores_between(reading(10, 5, 100), reading(11, 5 + 4.0 / 3.0, 102)),
              2.0 - 2.0 / 3.0, 1e-12);
  // An idle machine with this process asleep.
  EXPECT_DOUBLE_EQ(free_cores_between(reading(10, 5, 100), reading(11, 5, 100)), 2.0);
  // Tick rounding may make the busy time less than this process's own: never above the cores.
  EXPECT_DOUBLE_EQ(free_cores_between(reading(10, 5, 100), reading(11, 7, 101.9)), 2.0);
}

// A machine scripted as a queue of readings, and its clock.
struct ScriptedMachine {
  std::deque<std::optional<MachineLoadReading>> readings;
  double now = 0;
  int reads = 0;
  MachineLoadSource source() {
    return {[this]() {
              ++reads;
              auto r = readings.front();
              readings.pop_front();
              return r;
            },
            [this] { return now; }};
  }
};

TEST(ThreadShareWatch, DropsAThreadWhileAnotherProcessTakesACoreAndComesBack) {
  ScriptedMachine m;
  m.readings = {reading(0, 0, 0),
                // 0.5 s beside a busy process: 2/3 of a core each.
                reading(0.5, 2.0 / 3.0, 1.0),
                // 0.5 s on one thread beside it: one core each.
                reading(1.0, 2.0 / 3.0 + 0.5, 2.0),
                // It stopped: this process alone.
                reading(1.5, 2.0 / 3.0 + 1.0, 2.5)};
  ThreadShareWatch watch(2, 0.5, m.source());
  EXPECT_EQ(m.reads, 1);
  m.now = 0.3;
  EXPECT_EQ(watch.threads_after_step(2), 2);  // within the window: no reading
  EXPECT_EQ(m.reads, 1);
  m.now = 0.5;
  EXPECT_EQ(watch.threads_after_step(2), 1);
  m.now = 1.0;
  EXPECT_EQ(watch.threads_after_step(1), 1);
  m.now = 1.5;
  EXPECT_EQ(watch.threads_after_step(1), 2);
  EXPECT_EQ(m.reads, 4);
}

TEST(ThreadShareWatch, KeepsTheCountWhereTheSystemDoesNotSayOrOneThreadWasAskedFor) {
  ScriptedMachine silent;
  silent.readings = {std::nullopt};
  ThreadShareWatch unknown(2, 0.5, silent.source());
  silent.now = 5;
  EXPECT_EQ(unknown.threads_after_step(2), 2);
  EXPECT_EQ(silent.reads, 1);

  ScriptedMachine m;
  ThreadShareWatch one(1, 0.5, m.source());
  m.now = 5;
  EXPECT_EQ(one.threads_after_step(1), 1);
  EXPECT_EQ(m.reads, 0);
}

// A run that dropped threads gives the world back with the count it came with: the Python module
// steps it on after Simulation.run.
TEST(ThreadShareWatch, TheWorldLeavesARunWithItsThreads) {
  World world(WorldSettings{}, 2);
  {
    const ThreadCountKeeper keep(world);
    world.set_threads(1);
    EXPECT_EQ(world.executor().threads(), 1);
  }
  EXPECT_EQ(world.executor().threads(), 2);
}

TEST(ThreadShareWatch, ReadsThisMachine) {
  const auto first = read_machine_load();
  ASSERT_TRUE(first.has_value()) << "Linux has /proc/stat";
  EXPECT_GE(first->cores, 1);
  EXPECT_GT(first->own_cpu_seconds, 0);
  EXPECT_NEAR(first->wall_seconds, monotonic_seconds(), 1.0);
  volatile double spin = 0;
  while (monotonic_seconds() < first->wall_seconds + 0.05) spin = spin + 1;
  const auto later = read_machine_load();
  ASSERT_TRUE(later.has_value());
  EXPECT_GT(later->own_cpu_seconds, first->own_cpu_seconds);
  EXPECT_GE(later->machine_busy_seconds, first->machine_busy_seconds);
  const double free = free_cores_between(*first, *later);
  EXPECT_GE(free, 0.0);
  EXPECT_LE(free, double(later->cores));
}

}  // namespace
}  // namespace upf
