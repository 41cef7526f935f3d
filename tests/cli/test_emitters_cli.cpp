// Emitters and sinks from the command line (issue 40, docs/emitters.md): bad input is exit
// code 2 naming the JSON path before anything is written; a pour resumed from a checkpoint
// (after a stop, or after SIGKILL mid-pour) writes the same bytes as one never stopped, and so
// does a run split over MPI ranks.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The cells of column `name` of a CSV text, in row order (empty when there is no such column).
std::vector<std::string> csv_column(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  int index = -1;
  for (int k = 0; std::getline(header, cell, ','); ++k)
    if (cell == name) index = k;
  std::vector<std::string> cells;
  if (index < 0) return cells;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (int k = 0; std::getline(row, cell, ','); ++k)
      if (k == index) cells.push_back(cell);
  }
  return cells;
}

// Every frame file of run `a` is byte for byte run `b`'s; returns how many were compared.
int expect_same_frames(const fs::path& a, const fs::path& b) {
  int frames = 0;
  for (const auto& e : fs::directory_iterator(a / "frames")) {
    EXPECT_EQ(contents(e.path()), contents(b / "frames" / e.path().filename()))
        << e.path().filename();
    ++frames;
  }
  return frames;
}

class EmittersCli : public Cli {
 protected:
  // A small tank with a round tap above an empty floor.
  nlohmann::json pour() const {
    return {{"name", "pour"},
            {"particle_spacing", 0.04},
            {"materials",
             {{"water", {{"type", "liquid"}, {"density", 1000}}}, {"walls", {{"type", "frozen"}}}}},
            {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.4, 0.6, 0.4}}}}},
            {"emitters",
             {{{"material", "water"},
               {"radius", 0.06},
               {"center", {0.2, 0.5, 0.2}},
               {"direction", {0, -1, 0}},
               {"speed", 1.5}}}},
            {"sinks", {{{"min", {0.3, -1, -1}}, {"max", {1, 0.1, 1}}}}},
            {"time", {{"end", 0.4}}},
            {"output", {{"fps", 20}}}};
  }
};

TEST_F(EmittersCli, BadEmittersAndSinksAreNamedByTheirJsonPath) {
  auto with = [&](auto change) {
    nlohmann::json doc = pour();
    change(doc);
    return doc;
  };
  expect_rejected(with([](auto& d) {
                    d["emitters"][0]["center"] = {0.2, 0.5, 0.41};
                  }),
                  {":/emitters/0/center", "not inside any container"});
  expect_rejected(with([](auto& d) {
                    d["emitters"][0]["center"] = {0.35, 0.5, 0.2};
                    d["emitters"][0]["direction"] = {1, 0, 0};
                  }),
                  {":/emitters/0/direction", "points into a wall"});
  expect_rejected(with([](auto& d) {
                    d["fluid_blocks"] = {
                        {{"material", "water"}, {"min", {0, 0, 0}}, {"max", {0.4, 0.48, 0.4}}}};
                  }),
                  {":/emitters/0", "overlap the liquid of fluid block 0"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["radius"] = 0; }), {":/emitters/0/radius"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["speed"] = -1; }), {":/emitters/0/speed"});
  expect_rejected(with([](auto& d) {
                    d["emitters"][0]["speed"] = {{0, 0}, {1, 0}};
                  }),
                  {":/emitters/0/speed", "never emit"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["material"] = "walls"; }),
                  {":/emitters/0/material", "must be liquid"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["material"] = "honey"; }),
                  {":/emitters/0/material", "unknown material 'honey'"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["shape"] = "star"; }),
                  {":/emitters/0/shape", "unknown shape"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["point"] = {0, 0, 0};
                  }),
                  {":/sinks/0", "a box"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["max"] = {0.2, 0.1, 1};
                  }),
                  {":/sinks/0/max", "must exceed min"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["max_particles"] = 60; }),
                  {":/emitters/0/max_particles", "adds 144 particles, more than max_particles 60"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["max_particles"] = 3; }),
                  {":/emitters/0/max_particles", "less than one layer", "(9 particles)"});
  expect_rejected(with([](auto& d) {
                    d["emitters"][0]["max_particles"] = 60;
                    d["emitters"][0]["at_limit"] = "stop";
                  }),
                  {":/emitters/0/at_limit", "unknown at_limit 'stop'"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["at_limit"] = "close"; }),
                  {":/emitters/0/at_limit", "needs max_particles"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["profile"] = "turbulent"; }),
                  {":/emitters/0/profile", "unknown profile 'turbulent'", "open_channel"});
  expect_rejected(with([](auto& d) { d["emitters"][0]["profile"] = "open_channel"; }),
                  {":/emitters/0/profile", "gravity across the flow"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0] = {{"point", {0, 0.1, 0}},
                                     {"normal", {0, -1, 0}},
                                     {"outflow", {{"direction", {0, -1, 0}}}}};
                  }),
                  {":/sinks/0/outflow", "needs a box sink"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["outflow"] = {{"direction", {1, 1, 0}}};
                  }),
                  {":/sinks/0/outflow/direction", "along a world axis"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["outflow"] = {{"direction", {1, 0, 0}}, {"velocity", -2}};
                  }),
                  {":/sinks/0/outflow/velocity"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["outflow"] = {{"direction", {1, 0, 0}}, {"velocity", "free"}};
                  }),
                  {":/sinks/0/outflow/velocity", "extrapolated"});
  expect_rejected(with([](auto& d) {
                    d["sinks"][0]["outflow"] = {{"direction", {1, 0, 0}}, {"buffer", 0}};
                  }),
                  {":/sinks/0/outflow/buffer"});
  expect_rejected(with([](auto& d) { d["sinks"][0]["reuse"] = "tap"; }),
                  {":/sinks/0/reuse", "no emitter is named 'tap'"});
  expect_rejected(with([](auto& d) { d["sinks"][0]["reuse"] = "emitter 0"; }),
                  {":/sinks/0/reuse", "does not reuse particles"});
  // Nothing was written by any of them.
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(EmittersCli, AResumedPourWritesTheBytesOfOneNeverStopped) {
  const std::string scene = write(pour());
  const fs::path whole = dir_ / "whole", parts = dir_ / "parts";
  ASSERT_EQ(run_upf("run " + scene + " -o " + whole.string() + " -q").code, 0);
  ASSERT_EQ(
      run_upf("run " + scene + " -o " + parts.string() + " --end 0.2 --checkpoint-every 0.1sim -q")
          .code,
      0);
  const Result resumed = run_upf("run --resume " + parts.string() + " --end 0.4 -q");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_GE(expect_same_frames(whole, parts), 9);
  EXPECT_EQ(contents(whole / "metrics.csv").substr(0, 200),
            contents(parts / "metrics.csv").substr(0, 200));
  EXPECT_NE(contents(whole / "metrics.csv").find("mass_in_kg,mass_out_kg"), std::string::npos);
}

// SIGKILL mid-pour, as soon as the first checkpoint is on disk (0.1 s of 1.5 in, the tap
// pouring and the drain taking), then --resume: every frame and table is the uninterrupted run's,
// byte for byte (as Checkpoint.KilledRunResumesToTheSameBytes for a scene without sources).
TEST_F(EmittersCli, APourKilledMidWayResumesToTheBytesOfOneNeverStopped) {
  nlohmann::json doc = pour();
  doc["time"]["end"] = 1.5;  // wall time to spare after the first checkpoint: the kill lands
  const std::string scene = write(doc);
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const std::string opts = " --checkpoint-every 0.1sim -q -j2 -o ";
  ASSERT_EQ(run_upf("run " + scene + opts + whole.string()).code, 0);
  const std::string ck = (killed / "checkpoint.upfck").string();
  const std::string script = "sh -c '" + std::string(UPF_EXECUTABLE) + " run " + scene + opts +
                             killed.string() + " & pid=$!; while [ ! -f " + ck +
                             " ]; do sleep 0.02; done; kill -9 $pid; wait $pid; echo killed'";
  ASSERT_EQ(std::system(script.c_str()), 0);
  ASSERT_FALSE(fs::exists(killed / "summary.json")) << "killed mid-way, not finished";
  const Result resumed = run_upf("run --resume " + killed.string() + " -q -j1");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_GE(expect_same_frames(whole, killed), 30);
  EXPECT_EQ(contents(whole / "particles.pvd"), contents(killed / "particles.pvd"));
  // metrics.csv's timings differ from run to run; its steps, times and masses do not.
  for (const char* name : {"t", "dt", "n_liquid", "mass_in_kg", "mass_out_kg"})
    EXPECT_EQ(csv_column(contents(whole / "metrics.csv"), name),
              csv_column(contents(killed / "metrics.csv"), name))
        << name;
  const auto summary = nlohmann::json::parse(contents(killed / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
}

// A particle budget: "close" stops the emitter at the last whole layer within it and the run
// goes on; "error" passed only by a longer run than the scene's (--end) stops that run at the
// layer that would pass it, exit code 2 naming the scene's key, with the frames so far kept.
TEST_F(EmittersCli, AParticleBudgetClosesTheEmitterOrStopsTheRunAsAsked) {
  nlohmann::json doc = pour();
  doc.erase("sinks");
  doc["emitters"][0]["max_particles"] = 60;  // 6 layers of 9
  doc["emitters"][0]["at_limit"] = "close";
  const fs::path closed = dir_ / "closed";
  const Result c = run_upf("run " + write(doc) + " -q -o " + closed.string());
  ASSERT_EQ(c.code, 0) << c.output;
  const nlohmann::json summary = nlohmann::json::parse(contents(closed / "summary.json"));
  EXPECT_EQ(summary["particles"]["liquid"], 54) << summary.dump();

  doc["emitters"][0].erase("at_limit");  // "error"
  doc["time"]["end"] = 0.1;              // 36 particles by then: within the budget
  const fs::path stopped = dir_ / "stopped";
  const std::string scene = write(doc);
  ASSERT_EQ(run_upf("run " + scene + " -q -o " + stopped.string()).code, 0);
  const Result r = run_upf("run --resume " + stopped.string() + " --end 0.4 -q");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(":/emitters/0/max_particles: emitter 'emitter 0' reached its "
                          "max_particles (54 particles, 6 layers) at t = 0.16"),
            std::string::npos)
      << r.output;
  int frames = 0;
  for (const auto& e : fs::directory_iterator(stopped / "frames")) frames += e.is_regular_file();
  EXPECT_GE(frames, 4) << "the frames up to the stop are kept";
}

#ifdef UPF_HAS_MPI
// `mpirun -n 2 upf run` of a pour with a drain writes the one-rank run's frames byte for byte
// (the one-rank run keeps its particles in id order, as the split run's frames gather them).
TEST_F(EmittersCli, ASplitPourWritesTheOneRankRunsFrames) {
  nlohmann::json doc = pour();
  doc["neighbours"] = {{"reorder_every", 0}};
  const std::string scene = write(doc);
  const fs::path alone = dir_ / "alone", split = dir_ / "split";
  ASSERT_EQ(run_upf("run " + scene + " -q -j 1 -o " + alone.string()).code, 0);
  const Result r = run_shell(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 "
      "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -n 2 " +
      std::string(UPF_EXECUTABLE) + " run " + scene + " -q -o " + split.string());
  ASSERT_EQ(r.code, 0) << r.output;
  int frames = 0;
  for (const auto& e : fs::directory_iterator(alone / "frames")) {
    EXPECT_TRUE(contents(e.path()) == contents(split / "frames" / e.path().filename()))
        << e.path().filename();
    ++frames;
  }
  EXPECT_GE(frames, 9);
}
#endif

}  // namespace
}  // namespace upf::cli_test
