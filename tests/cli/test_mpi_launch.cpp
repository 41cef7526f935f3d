// `mpirun -n P upf ...`: upf does not split a scene over ranks yet (issue 23), so a run started as
// several ranks refuses before anything is written, exit code 2, rank 0 naming the launcher's
// variable and what to do instead; one rank runs as it would alone. The launchers are told by the
// environment they set (Open MPI, PMI, srun), set here by hand; a real mpirun, when the machine
// has one, too.
#include <cstdlib>

#include "apps/upf/mpi_launch.h"
#include "cli_support.h"

namespace upf::cli_test {
namespace {

class MpiLaunch : public Cli {};

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

TEST_F(MpiLaunch, SeveralRanksRefuseBeforeWritingAndOneRankRuns) {
  const std::string scene = write(sample());
  const fs::path out = dir_ / "out";
  const std::string args = "run " + scene + " --end 0.01 -q --no-frames -o " + out.string();
  const Result first = run_upf(args, "OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(first.code, 2) << first.output;
  EXPECT_NE(first.output.find("mpirun -n 3 (OMPI_COMM_WORLD_SIZE=3)"), std::string::npos)
      << first.output;
  EXPECT_NE(first.output.find("--plan / --task K"), std::string::npos) << first.output;
  const Result other = run_upf(args, "OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=2");
  EXPECT_EQ(other.code, 2);
  EXPECT_EQ(other.output.find("error"), std::string::npos) << "rank 0 speaks for all";
  EXPECT_FALSE(fs::exists(out));
  const Result compare =
      run_upf("compare " + scene + " --end 0.01 -q --out " + out.string(), "PMI_SIZE=2 PMI_RANK=0");
  EXPECT_EQ(compare.code, 2) << compare.output;
  EXPECT_FALSE(fs::exists(out));
  const Result one = run_upf(args, "OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(one.code, 0) << one.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

// A real Open MPI launch, where the machine has mpirun (as root it needs to be told it may).
TEST_F(MpiLaunch, MpirunWithTwoRanksIsRefused) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun here";
  const fs::path out = dir_ / "out";
  const Result r = run_shell(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 "
      "timeout 60 mpirun --oversubscribe -n 2 " +
      std::string(UPF_EXECUTABLE) + " run " + write(sample()) + " --end 0.01 -q -o " +
      out.string());
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("upf runs a scene on one rank"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace upf::cli_test
