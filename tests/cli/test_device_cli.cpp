// `upf run --device`: the device pipeline's CPU instantiation writes the same files, byte for
// byte, as the CPU executor (docs/device.md); a device that cannot run refuses before anything is
// written, with exit code 2 and the reason.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every frame of run `a` has a byte-identical twin in run `b`; returns how many there are.
int expect_same_frames(const fs::path& a, const fs::path& b) {
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(a / "frames")) {
    const fs::path other = b / "frames" / entry.path().filename();
    EXPECT_TRUE(fs::exists(other)) << other;
    EXPECT_TRUE(contents(entry.path()) == contents(other)) << entry.path().filename();
    ++frames;
  }
  return frames;
}

class DeviceCli : public Cli {
 protected:
  // `upf run scene` with `options` into cpu_dir(), then with --device omp into omp_dir(); false
  // (and a failure) when either run fails.
  bool run_on_cpu_and_omp(const std::string& scene, const std::string& options) {
    const Result a = run_upf("run " + scene + options + " --out " + cpu_dir().string());
    EXPECT_EQ(a.code, 0) << a.output;
    const Result b =
        run_upf("run " + scene + options + " --device omp --out " + omp_dir().string());
    EXPECT_EQ(b.code, 0) << b.output;
    return a.code == 0 && b.code == 0;
  }
  std::string sample_scene(const std::string& name) {
    std::ifstream in(fs::path(UPF_SOURCE_DIR) / "samples" / name);
    return write(nlohmann::json::parse(in));
  }
  // Set up by Cli::SetUp.
  fs::path cpu_dir() const { return dir_ / "cpu"; }
  fs::path omp_dir() const { return dir_ / "omp"; }
};

TEST_F(DeviceCli, OmpWritesTheCpuRunsFramesProbesAndMetricsByteForByte) {
  const std::string scene = write(sample());
  const fs::path cpu = dir_ / "cpu", omp = dir_ / "omp";
  const Result a = run_upf("run " + scene + " -q -j 2 --end 0.15 --out " + cpu.string());
  ASSERT_EQ(a.code, 0) << a.output;
  const Result b =
      run_upf("run " + scene + " -q -j 2 --end 0.15 --device omp --out " + omp.string());
  ASSERT_EQ(b.code, 0) << b.output;
  EXPECT_GE(expect_same_frames(cpu, omp), 5);
  EXPECT_EQ(contents(cpu / "probes.csv"), contents(omp / "probes.csv"));
  // metrics.csv: the same columns up to the timings, which differ run to run.
  std::ifstream ma(cpu / "metrics.csv"), mb(omp / "metrics.csv");
  std::string la, lb;
  int rows = 0;
  while (std::getline(ma, la) && std::getline(mb, lb)) {
    const auto cut = [](const std::string& s) {
      std::size_t at = 0;
      for (int k = 0; k < 11 && at != std::string::npos; ++k) at = s.find(',', at + 1);
      return s.substr(0, at);
    };
    EXPECT_EQ(cut(la), cut(lb));
    ++rows;
  }
  EXPECT_GT(rows, 50);
}

// Grains: the frames (with the contact load field) and the table of the walls' forces
// (dem_linear_walls.csv) are the CPU run's, byte for byte.
TEST_F(DeviceCli, OmpWritesTheCpuRunsGrainFramesAndWallForces) {
  ASSERT_TRUE(run_on_cpu_and_omp(sample_scene("sand_pile.json"),
                                 " -q -j 1 --end 0.1 --set /output/fps=100"));
  const fs::path cpu = cpu_dir(), omp = omp_dir();
  EXPECT_GE(expect_same_frames(cpu, omp), 10);
  EXPECT_NE(contents(cpu / "frames" / "frame_00010.vtp").find("dem.contact_load"),
            std::string::npos);
  const std::string walls = contents(cpu / "dem_linear_walls.csv");
  EXPECT_EQ(walls.rfind("t,x_min_normal,x_max_normal,y_min_normal,y_max_normal,z_min_normal,"
                        "z_max_normal,shear_x,shear_y,shear_z\n",
                        0),
            0u)
      << walls.substr(0, 200);
  EXPECT_GT(std::count(walls.begin(), walls.end(), '\n'), 20);
  EXPECT_EQ(walls, contents(omp / "dem_linear_walls.csv"));
}

// A periodic scene (docs/periodic.md): its images live on the device during each step, and the
// frames (in id order) and probes are the CPU run's, byte for byte.
TEST_F(DeviceCli, OmpWritesThePeriodicDamBreaksFramesAndProbesByteForByte) {
  ASSERT_TRUE(run_on_cpu_and_omp(sample_scene("periodic_dam_break.json"),
                                 " -q -j 2 --end 0.3 --set /particle_spacing=0.04"));
  EXPECT_GE(expect_same_frames(cpu_dir(), omp_dir()), 9);
  EXPECT_EQ(contents(cpu_dir() / "probes.csv"), contents(omp_dir() / "probes.csv"));
}

// The scene's "device" key picks the device when --device does not; its errors name the key.
TEST_F(DeviceCli, TheScenesDeviceKeyIsUsedAndCheckedUnlessTheOptionOverridesIt) {
  auto doc = sample();
  doc["device"] = "omp";
  const std::string scene = write(doc);
  const Result ran = run_upf("run " + scene + " -q --end 0.05 --out " + (dir_ / "key").string());
  EXPECT_EQ(ran.code, 0) << ran.output;
  doc["device"] = "quantum";
  const std::string bad = write(doc, "bad.json");
  // validate checks the key as run does.
  const Result validated = run_upf("validate " + bad);
  EXPECT_EQ(validated.code, 2) << validated.output;
  EXPECT_NE(validated.output.find("bad.json:/device"), std::string::npos) << validated.output;
  EXPECT_NE(validated.output.find("allowed: cpu"), std::string::npos) << validated.output;
  doc["device"] = "omp";
  // The PBF plug-in has no device part.
  doc["materials"]["water"]["solver"] = "pbf";
  const Result uncovered = run_upf("validate " + write(doc, "pbf.json"));
  EXPECT_EQ(uncovered.code, 2) << uncovered.output;
  EXPECT_NE(uncovered.output.find("--device cpu"), std::string::npos) << uncovered.output;
  const Result refused = run_upf("run " + bad + " -q --end 0.05 --out " + (dir_ / "bad").string());
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_NE(refused.output.find("bad.json:/device"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
  const Result overridden =
      run_upf("run " + bad + " -q --end 0.05 --device cpu --out " + (dir_ / "overridden").string());
  EXPECT_EQ(overridden.code, 0) << overridden.output;
}

TEST_F(DeviceCli, ADeviceThatCannotRunRefusesBeforeWritingAnything) {
  const std::string scene = write(sample());
  const fs::path out = dir_ / "refused";
  const Result unknown = run_upf("run " + scene + " --device tpu --out " + out.string());
  EXPECT_EQ(unknown.code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("'tpu' is not a device (allowed: cpu"), std::string::npos)
      << unknown.output;
  EXPECT_FALSE(fs::exists(out));

  auto with_pbf = sample();
  with_pbf["materials"]["water"]["solver"] = "pbf";
  const Result pbf =
      run_upf("run " + write(with_pbf, "pbf.json") + " --device omp --out " + out.string());
  EXPECT_EQ(pbf.code, 2) << pbf.output;
  EXPECT_NE(pbf.output.find("'pbf' has no device part"), std::string::npos) << pbf.output;
  EXPECT_FALSE(fs::exists(out));

  // Without a GPU (CI never has one) the CUDA runtime's reason is named; with one, it runs.
  const Result cuda =
      run_upf("run " + scene + " -q --end 0.05 --device cuda --out " + out.string());
  if (cuda.code == 0) GTEST_SKIP() << "a GPU is present: --device cuda ran";
  EXPECT_EQ(cuda.code, 2) << cuda.output;
  EXPECT_TRUE(cuda.output.find("no usable GPU") != std::string::npos ||
              cuda.output.find("no CUDA pipeline") != std::string::npos)
      << cuda.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace upf::cli_test
