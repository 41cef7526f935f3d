// `mpirun -n P upf ...`: `upf run` splits its scene over the ranks (with UPF_MPI) and writes the
// one-rank run's files; the other commands (and `upf run` built without MPI) refuse before
// anything is written, exit code 2, rank 0 naming the launcher's variable and what to do instead;
// one rank runs as it would alone. The launchers are told by the environment they set (Open MPI,
// PMI, srun), set here by hand, and by a real mpirun.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "apps/upf/mpi_launch.h"
#include "cli_support.h"
#include "framework/compare/python_runner.h"
#include "render/vtp_reader.h"

namespace upf::cli_test {
namespace {

class MpiLaunch : public Cli {};

[[maybe_unused]] std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(MpiLaunch, TheLaunchersVariablesGiveTheRankCount) {
  using Env = std::map<std::string, std::string>;
  auto ranks = [](const Env& env) {
    return upf::app::launched_ranks([&](const char* name) -> const char* {
      const auto it = env.find(name);
      return it == env.end() ? nullptr : it->second.c_str();
    });
  };
  EXPECT_EQ(ranks({}).size, 1);
  EXPECT_EQ(ranks({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "3"}}).size, 4);
  EXPECT_EQ(ranks({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "3"}}).rank, 3);
  EXPECT_EQ(ranks({{"PMI_SIZE", "2"}, {"PMI_RANK", "0"}}).variable, "PMI_SIZE");
  EXPECT_EQ(ranks({{"SLURM_STEP_NUM_TASKS", "8"}, {"SLURM_PROCID", "5"}}).size, 8);
  // An allocation's SLURM_NTASKS alone is not a launch: sbatch scripts start upf once.
  EXPECT_EQ(ranks({{"SLURM_NTASKS", "8"}}).size, 1);
  EXPECT_EQ(ranks({{"PMI_SIZE", "two"}, {"PMI_RANK", "0"}}).size, 1);
}

TEST_F(MpiLaunch, CommandsThatRunOnOneRankRefuseBeforeWritingAndOneRankRuns) {
  const std::string scene = write(sample());
  const fs::path out = dir_ / "out";
  const Result compare =
      run_upf("compare " + scene + " --end 0.01 -q --out " + out.string(), "PMI_SIZE=3 PMI_RANK=0");
  EXPECT_EQ(compare.code, 2) << compare.output;
  EXPECT_NE(compare.output.find("mpirun -n 3 (PMI_SIZE=3)"), std::string::npos) << compare.output;
  EXPECT_NE(compare.output.find("--plan / --task K"), std::string::npos) << compare.output;
  const Result other =
      run_upf("compare " + scene + " --end 0.01 -q --out " + out.string(), "PMI_SIZE=3 PMI_RANK=2");
  EXPECT_EQ(other.code, 2);
  EXPECT_EQ(other.output.find("error"), std::string::npos) << "rank 0 speaks for all";
  EXPECT_FALSE(fs::exists(out));
  const std::string args = "run " + scene + " --end 0.01 -q --no-frames -o " + out.string();
#ifndef UPF_HAS_MPI
  const Result run = run_upf(args, "OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(run.code, 2) << run.output;
  EXPECT_NE(run.output.find("built without MPI"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
#endif
  const Result one = run_upf(args, "OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(one.code, 0) << one.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

#ifdef UPF_HAS_MPI
// A real Open MPI launch (as root it needs to be told it may). Ranks yield when idle: on a machine
// with fewer cores than ranks, polling ranks starve the working ones.
Result mpirun(int ranks, const std::string& args) {
  return run_shell(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 "
      "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -n " +
      std::to_string(ranks) + " " + std::string(UPF_EXECUTABLE) + " " + args);
}

// Every frame of run directory `a` is byte for byte the frame of that name in `b`; returns how
// many.
int expect_same_frames(const fs::path& a, const fs::path& b) {
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(a / "frames")) {
    ++frames;
    EXPECT_TRUE(contents(entry.path()) == contents(b / "frames" / entry.path().filename()))
        << entry.path().filename();
  }
  return frames;
}

// `mpirun -n P upf run` splits the scene over P ranks and writes, from rank 0, the files of the
// one-rank run: every frame, probes.csv and bodies.csv byte for byte. The one-rank run keeps its
// particles in id order (no reordering), which is the order the split run's frames gather them in.
TEST_F(MpiLaunch, MpirunSplitsARunIntoTheOneRankRunsFiles) {
  nlohmann::json doc = nlohmann::json::parse(
      contents(fs::path(UPF_SOURCE_DIR) / "samples" / "floating_objects.json"));
  doc["particle_spacing"] = 0.04;
  for (auto& body : doc["bodies"]) {
    const std::string file = body["mesh"]["file"];
    body["mesh"]["file"] =
        (fs::path(UPF_SOURCE_DIR) / "assets" / "meshes" / fs::path(file).filename()).string();
  }
  doc["neighbours"] = {{"reorder_every", 0}};
  const std::string scene = write(doc);
  const std::string options = " --end 0.1 --set /output/fps=50 -q -o ";
  const fs::path alone = dir_ / "alone";
  const Result one = run_upf("run " + scene + options + alone.string() + " -j 1");
  ASSERT_EQ(one.code, 0) << one.output;
  for (int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const fs::path split = dir_ / ("split" + std::to_string(ranks));
    const Result r = mpirun(ranks, "run " + scene + options + split.string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_GE(expect_same_frames(alone, split), 6);
    for (const char* file : {"probes.csv", "bodies.csv", "particles.pvd"})
      EXPECT_EQ(contents(alone / file), contents(split / file)) << file;
  }
}

// Grains too: the frames and the walls' force table of the one-rank run (the sample sand pile,
// shorter and narrower).
TEST_F(MpiLaunch, MpirunSplitsAGrainRunIntoTheOneRankRunsFiles) {
  nlohmann::json doc =
      nlohmann::json::parse(contents(fs::path(UPF_SOURCE_DIR) / "samples" / "sand_pile.json"));
  doc["containers"][0]["max"] = {0.3, 0.2, 0.04};
  doc["granular_blocks"][0]["max"] = {0.08, 0.12, 0.04};
  doc["neighbours"] = {{"reorder_every", 0}};
  const std::string scene = write(doc);
  const std::string options = " --end 0.1 --set /output/fps=50 -q -o ";
  const fs::path alone = dir_ / "alone", split = dir_ / "split";
  const Result one = run_upf("run " + scene + options + alone.string() + " -j 1");
  ASSERT_EQ(one.code, 0) << one.output;
  const Result r = mpirun(2, "run " + scene + options + split.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_GE(expect_same_frames(alone, split), 6);
  for (const char* file : {"probes.csv", "dem_linear_walls.csv", "particles.pvd"})
    EXPECT_EQ(contents(alone / file), contents(split / file)) << file;
}

// Bad input on a split run: every rank meets it, rank 0 reports it once, the job ends with 2 and
// nothing is written.
TEST_F(MpiLaunch, MpirunWithBadInputEndsEveryRankWithCodeTwo) {
  nlohmann::json doc = sample();
  doc["materials"]["water"]["solver"] = {{"name", "pcisph"}, {"stop_percentile", 50}};
  const std::string percentile = write(doc);
  const fs::path out = dir_ / "out";
  const Result r = mpirun(2, "run " + percentile + " --end 0.01 -q -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("stop_percentile 50"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// /output/pieces "per_rank": each rank writes its own particles of a frame, rank 0 the .pvtp that
// joins them, listed in particles.pvd. VTK's parallel reader (ParaView's) opens each as one data
// set holding the one-rank run's particles, value for value (check_pvtp_frames.py), and `upf
// render` draws the run.
TEST_F(MpiLaunch, MpirunWritesFramesAsOnePiecePerRank) {
  nlohmann::json doc = sample();
  doc["output"]["pieces"] = "per_rank";
  doc["probes"] = nlohmann::json::array();  // nothing else reads every particle: no gather
  const std::string scene = write(doc);
  const fs::path alone = dir_ / "alone", split = dir_ / "split";
  const std::string options = " --end 0.06 --set /output/fps=50 -q -o ";
  const Result one = run_upf("run " + scene + options + alone.string() + " -j 1");
  ASSERT_EQ(one.code, 0) << one.output;
  EXPECT_TRUE(fs::exists(alone / "frames" / "frame_00000.vtp")) << "one rank writes no pieces";
  const Result r = mpirun(3, "run " + scene + options + split.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* name : {"frame_00000", "frame_00003", "frozen"}) {
    EXPECT_TRUE(fs::exists(split / "frames" / (std::string(name) + ".pvtp"))) << name;
    for (int rank = 0; rank < 3; ++rank)
      EXPECT_TRUE(fs::exists(split / "frames" /
                             (std::string(name) + "_p000" + std::to_string(rank) + ".vtp")))
          << name << " rank " << rank;
  }
  EXPECT_FALSE(fs::exists(split / "frames" / "frame_00000.vtp"));

  const fs::path log = dir_ / "check_pvtp_frames.log";
  const auto check =
      upf::run_python_script(fs::path(UPF_SOURCE_DIR) / "tests" / "cli" / "check_pvtp_frames.py",
                             {split.string(), alone.string(), "3"}, log);
  if (check.missing_module) GTEST_SKIP() << "VTK's Python bindings are not installed";
  EXPECT_TRUE(check.ok) << check.error << "\n" << contents(log);
  EXPECT_NE(contents(log).find("4 time steps checked"), std::string::npos) << contents(log);

  const Result render =
      run_upf("render " + split.string() + " --frames 3:3 --size 160x90 --no-video -q");
  EXPECT_EQ(render.code, 0) << render.output;
  EXPECT_TRUE(fs::exists(split / "render" / "frame_00003.png"));

  // A later run into the folder removes what this one wrote, pictures included, from its
  // manifest (before: a 3-rank run's pieces stayed beside a 2-rank or one-rank run's files).
  const Result two = mpirun(2, "run " + scene + options + split.string());
  ASSERT_EQ(two.code, 0) << two.output;
  EXPECT_TRUE(fs::exists(split / "frames" / "frame_00003_p0001.vtp"));
  EXPECT_FALSE(fs::exists(split / "frames" / "frame_00003_p0002.vtp"));
  EXPECT_FALSE(fs::exists(split / "frames" / "frozen_p0002.vtp"));
  EXPECT_FALSE(fs::exists(split / "render" / "frame_00003.png"));
  const Result one_more = run_upf("run " + scene + options + split.string() + " -j 1");
  ASSERT_EQ(one_more.code, 0) << one_more.output;
  for (const auto& entry : fs::directory_iterator(split / "frames"))
    EXPECT_EQ(entry.path().extension(), ".vtp") << entry.path();  // no .pvtp, no stale piece
  EXPECT_FALSE(fs::exists(split / "frames" / "frame_00000_p0000.vtp"));
}

// A rank that dies mid-run (killed: no error of ours to report) ends the job: mpirun notices,
// ends the other ranks and exits non-zero, naming the rank. The frames written before are whole:
// each was written atomically (a temporary file renamed), and every .vtp left reads back.
TEST_F(MpiLaunch, ARankThatDiesEndsTheJobAndLeavesWholeFrames) {
  nlohmann::json doc = sample();
  doc["probes"] = nlohmann::json::array();
  const std::string scene = write(doc);
  const fs::path out = dir_ / "out";
  const std::string upf = UPF_EXECUTABLE;
  // Launch, wait for the third frame, kill one rank (a process whose command line starts with
  // upf itself, not mpirun's), then wait for mpirun.
  const Result r = run_shell(
      "{ OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 "
      "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -n 2 " +
      upf + " run " + scene + " --end 30 --set /output/fps=50 -q -o " + out.string() +
      " & job=$!; for i in $(seq 1200); do [ -e " + (out / "frames" / "frame_00002.vtp").string() +
      " ] && break; sleep 0.1; done; victim=$(pgrep -f \"^" + upf + " run " + scene +
      "\" | tail -n 1); echo killing $victim; kill -KILL $victim; wait $job; "
      "echo mpirun exited with $?; }");
  EXPECT_NE(r.output.find("killing "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("mpirun exited with 0"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("mpirun exited with 124"), std::string::npos) << "it hung\n" << r.output;
  EXPECT_NE(r.output.find("signal 9"), std::string::npos) << r.output;
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(out / "frames")) {
    if (entry.path().extension() != ".vtp") continue;
    ++frames;
    EXPECT_NO_THROW(render::read_vtp(entry.path())) << entry.path();
  }
  EXPECT_GE(frames, 3);
}

// A split run's checkpoint is a one-rank checkpoint: written at 4 ranks, resumed at 2, the run
// ends with the frames of one rank's run from start to end.
TEST_F(MpiLaunch, ACheckpointWrittenAtFourRanksResumesAtTwo) {
  nlohmann::json doc = sample();
  doc["neighbours"] = {{"reorder_every", 0}};
  const std::string scene = write(doc);
  const fs::path alone = dir_ / "alone", split = dir_ / "split";
  const std::string options = " --set /output/fps=50 -q";
  const Result one = run_upf("run " + scene + options + " --end 0.16 -j 1 -o " + alone.string());
  ASSERT_EQ(one.code, 0) << one.output;
  const Result first = mpirun(4, "run " + scene + options + " --end 0.08 -o " + split.string());
  ASSERT_EQ(first.code, 0) << first.output;
  const Result rest = mpirun(2, "run --resume " + split.string() + " --end 0.16 -q");
  ASSERT_EQ(rest.code, 0) << rest.output;
  EXPECT_GE(expect_same_frames(alone, split), 9);
  EXPECT_EQ(contents(alone / "probes.csv"), contents(split / "probes.csv"));
}
#endif

}  // namespace
}  // namespace upf::cli_test
