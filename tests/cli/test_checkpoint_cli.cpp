// Checkpoint and resume from the command line (issue: long runs that survive): a run killed with
// SIGKILL and resumed writes the same bytes as a run never interrupted; Ctrl-C writes a
// checkpoint and says how to resume; damaged or foreign checkpoints are clear errors.
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::vector<char> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& p, const std::vector<char>& b) {
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(b.data(), std::streamsize(b.size()));
}

class Checkpoint : public Cli {
 protected:
  // All four particle types, coarse: liquid, grains, two floating Bullet boxes, frozen walls.
  // Grains of 15 mm rather than 6 mm: a tenth of the DEM work (fewer grains, longer contact
  // time), and the bytes a resumed run must reproduce are just as many.
  std::string coupled_scene() {
    std::ifstream in(fs::path(UPF_SOURCE_DIR) / "samples" / "sand_into_water.json");
    auto doc = nlohmann::json::parse(in);
    doc["particle_spacing"] = 0.04;
    doc["materials"]["sand"]["radius"] = 0.015;
    doc["time"]["end"] = 0.3;
    // Relative mesh paths resolve against the scene file: keep it next to the sample.
    const fs::path path = fs::path(UPF_SOURCE_DIR) / "samples" /
                          ("test_checkpoint_" + std::to_string(::getpid()) + ".json");
    std::ofstream(path) << doc.dump(2);
    scene_ = path;
    return path.string();
  }
  void TearDown() override {
    if (!scene_.empty()) fs::remove(scene_);
    Cli::TearDown();
  }
  // Every frame file and body table of run `a` is byte for byte the one of run `b`.
  static void expect_same_outputs(const fs::path& a, const fs::path& b) {
    int files = 0;
    for (const auto& e : fs::directory_iterator(a / "frames")) {
      const fs::path other = b / "frames" / e.path().filename();
      ASSERT_TRUE(fs::exists(other)) << other;
      EXPECT_EQ(bytes_of(e.path()), bytes_of(other)) << e.path().filename();
      ++files;
    }
    EXPECT_GT(files, 10);
    for (const char* f :
         {"particles.pvd", "bodies.csv", "body_forces.csv", "probes.csv", "dem_linear_walls.csv"})
      EXPECT_EQ(bytes_of(a / f), bytes_of(b / f)) << f;
  }
  fs::path scene_;
};

TEST_F(Checkpoint, KilledRunResumesToTheSameBytes) {
  const std::string scene = coupled_scene();
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const std::string opts = " --checkpoint-every 0.05sim -q -j2 -o ";
  const Result a = run_upf("run " + scene + opts + whole.string());
  ASSERT_EQ(a.code, 0) << a.output;
  ASSERT_TRUE(fs::exists(whole / "checkpoint.upfck"));

  // SIGKILL as soon as the first checkpoint is on disk: no chance to clean up.
  const std::string ck = (killed / "checkpoint.upfck").string();
  const std::string script = "sh -c '" + std::string(UPF_EXECUTABLE) + " run " + scene + opts +
                             killed.string() + " & pid=$!; while [ ! -f " + ck +
                             " ]; do sleep 0.02; done; kill -9 $pid; wait $pid; echo killed'";
  ASSERT_EQ(std::system(script.c_str()), 0);
  // Killed mid-way: a finished run would have written its summary.
  ASSERT_FALSE(fs::exists(killed / "summary.json"));

  // The resumed run goes on from the checkpoint: it leaves the first frame as it was.
  const fs::path first = killed / "frames" / "frame_00000.vtp";
  const auto first_written = fs::last_write_time(first);
  const Result resumed = run_upf("run --resume " + killed.string() + " -q -j1");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_EQ(fs::last_write_time(first), first_written);
  expect_same_outputs(whole, killed);
  const auto summary = nlohmann::json::parse(std::ifstream(killed / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 0.3, 1e-9);
}

TEST_F(Checkpoint, InterruptWritesACheckpointAndSaysHowToResume) {
  const std::string scene = coupled_scene();
  const fs::path out = dir_ / "run";
  const std::string frame = (out / "frames" / "frame_00002.vtp").string();
  const std::string script = "sh -c '" + std::string(UPF_EXECUTABLE) + " run " + scene +
                             " -q -j2 -o " + out.string() + " 2>" + (dir_ / "err").string() +
                             " & pid=$!; while [ ! -f " + frame +
                             " ]; do sleep 0.02; done; kill -INT $pid; wait $pid; exit $?'";
  const int status = std::system(script.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream err(dir_ / "err");
  const std::string message((std::istreambuf_iterator<char>(err)),
                            std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("resume with: upf run --resume " + out.string()), std::string::npos)
      << message;
  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_LT(summary["simulated_time_s"].get<double>(), 0.3);

  // --end on resume takes the run further than the scene's 0.3 s.
  const Result resumed = run_upf("run --resume " + out.string() + " --end 0.32 -q");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  const auto done = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(done["status"], "completed");
  EXPECT_NEAR(done["simulated_time_s"].get<double>(), 0.32, 1e-9);
}

TEST_F(Checkpoint, DamagedForeignOrMissingCheckpointsAreClearErrors) {
  const fs::path out = dir_ / "run";
  const Result r = run_upf("run " + write(sample()) +
                           " --end 0.02 --checkpoint-every 0.01sim -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path ck = out / "checkpoint.upfck";
  const std::vector<char> good = bytes_of(ck);
  ASSERT_GT(good.size(), 1000u);
  auto expect_error = [&](const std::vector<char>& bytes, const std::string& needle) {
    write_bytes(ck, bytes);
    const Result bad = run_upf("run --resume " + out.string());
    EXPECT_EQ(bad.code, 2) << bad.output;
    EXPECT_NE(bad.output.find(needle), std::string::npos) << needle << "\n" << bad.output;
    EXPECT_NE(bad.output.find(ck.string()), std::string::npos) << bad.output;
  };
  std::vector<char> flipped = good;
  flipped[flipped.size() / 2] ^= 0x5A;
  expect_error(flipped, "checksum mismatch");
  expect_error(std::vector<char>(good.begin(), good.begin() + std::ptrdiff_t(good.size() / 3)),
               "truncated");
  std::vector<char> other_format = good;
  other_format[8] = 99;  // the format number follows the 8 magic bytes
  expect_error(other_format, "checkpoint format 99");
  expect_error(std::vector<char>{'{', '}'}, "not a upf checkpoint");
  fs::remove(ck);
  const Result none = run_upf("run --resume " + out.string());
  EXPECT_EQ(none.code, 2) << none.output;
  EXPECT_NE(none.output.find("no checkpoint"), std::string::npos) << none.output;
}

// A checkpoint that cannot be written (here: a directory where its temporary file must go, as a
// full disk fails the write) stops the run with exit code 1 naming the file; the checkpoint
// before it stays whole and resumable, and the frames already written stay.
TEST_F(Checkpoint, UnwritableCheckpointKeepsThePreviousOneAndTheFrames) {
  const fs::path out = dir_ / "run";
  const std::string scene = write(sample());
  ASSERT_EQ(
      run_upf("run " + scene + " --end 0.02 --checkpoint-every 0.01sim -q -o " + out.string()).code,
      0);
  const fs::path ck = out / "checkpoint.upfck";
  const std::vector<char> before = bytes_of(ck);
  fs::create_directory(out / "checkpoint.upfck.tmp");
  const Result r = run_upf("run --resume " + out.string() + " --end 0.04 -q");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find(ck.string()), std::string::npos) << r.output;
  EXPECT_EQ(bytes_of(ck), before);
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.vtp"));
  fs::remove(out / "checkpoint.upfck.tmp");
  const Result again = run_upf("run --resume " + out.string() + " --end 0.04 -q");
  EXPECT_EQ(again.code, 0) << again.output;
}

TEST_F(Checkpoint, BadDurationIsRejectedBeforeRunning) {
  const Result r =
      run_upf("run " + write(sample()) + " --checkpoint-every 5 -o " + (dir_ / "run").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--checkpoint-every"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("5m"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "run" / "metrics.csv"));
}

}  // namespace
}  // namespace upf::cli_test
