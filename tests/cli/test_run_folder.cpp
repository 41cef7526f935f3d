// A run owns its files and no others (issue 46; it replaces the test of the pattern-based
// clearing, Cli.ARunIntoAnEarlierRunsDirectoryReplacesItsFiles): it records what it writes in
// upf_manifest.txt; a new run into the folder removes exactly what the previous run listed;
// a non-empty folder that no run recorded is refused unless --overwrite, which replaces only the
// names the run writes; links inside the folder are never followed; a scene's name is a name,
// never a path; a checkpoint of another scene is not resumed into a folder. docs/robustness.md,
// "What a run may delete".
#include <fstream>
#include <iterator>
#include <set>

#include "cli_support.h"

namespace upf::cli_test {
namespace {

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void put(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

class RunFolder : public Cli {
 protected:
  // The coarse dam break with a frame every 0.01 s.
  std::string scene() {
    auto doc = sample();
    doc["output"]["fps"] = 100;
    return write(doc);
  }
  // The user's own files, each holding its own name.
  const std::vector<std::string> user_files_ = {"render/holiday.mp4",
                                                "frames/frame_12345.png",
                                                "frames/surface_00001.obj",
                                                "dem_my_walls.csv",
                                                "scene.json",
                                                "notes.txt"};
  void add_user_files(const fs::path& d) {
    for (const auto& f : user_files_) put(d / f, f);
  }
  void expect_user_files(const fs::path& d) {
    for (const auto& f : user_files_) EXPECT_EQ(contents(d / f), f) << f;
  }
};

// The reproduction: before, every one of these files was deleted or replaced.
TEST_F(RunFolder, AFolderOfSomeoneElsesFilesIsRefusedAndKeptWhole) {
  const fs::path d = dir_ / "d";
  add_user_files(d);
  const Result r = run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no upf run recorded"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  expect_user_files(d);
  EXPECT_FALSE(fs::exists(d / "particles.pvd"));

  // --overwrite writes the run beside them and deletes none of them.
  const Result o = run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q --overwrite");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(o.output.find("replaced an earlier run"), std::string::npos) << o.output;
  expect_user_files(d);
  EXPECT_TRUE(fs::exists(d / "upf_scene.json"));
  EXPECT_TRUE(fs::exists(d / "frames" / "frame_00002.vtp"));
}

TEST_F(RunFolder, ANewRunRemovesExactlyWhatThePreviousRunWrote) {
  const fs::path d = dir_ / "d";
  ASSERT_EQ(run_upf("run " + scene() + " -o " + d.string() + " --end 0.05 -q").code, 0);
  ASSERT_TRUE(fs::exists(d / "frames" / "frame_00005.vtp"));
  const std::string manifest = contents(d / "upf_manifest.txt");
  EXPECT_NE(manifest.find("f frames/frame_00005.vtp\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("f metrics.csv\n"), std::string::npos) << manifest;
  add_user_files(d);  // put beside the run afterwards: not in its manifest

  const Result r = run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("replaced an earlier run"), std::string::npos) << r.output;
  expect_user_files(d);
  EXPECT_TRUE(fs::exists(d / "frames" / "frame_00002.vtp"));
  EXPECT_FALSE(fs::exists(d / "frames" / "frame_00003.vtp"));  // the earlier, longer run's
  EXPECT_FALSE(fs::exists(d / "frames" / "frame_00005.vtp"));
  EXPECT_EQ(contents(d / "particles.pvd").find("frame_00003"), std::string::npos);
}

TEST_F(RunFolder, LinksInsideTheFolderAreNeverFollowed) {
  // frames/ a link to another folder: nothing is written or deleted through it.
  const fs::path d = dir_ / "d", victim = dir_ / "victim";
  ASSERT_EQ(run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q").code, 0);
  put(victim / "frame_00000.vtp", "theirs");
  put(victim / "frame_00001.vtp", "theirs");
  fs::remove_all(d / "frames");
  fs::create_directory_symlink(victim, d / "frames");
  const Result r = run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("symbolic link"), std::string::npos) << r.output;
  EXPECT_EQ(contents(victim / "frame_00000.vtp"), "theirs");
  EXPECT_EQ(contents(victim / "frame_00001.vtp"), "theirs");
  // A listed file replaced by a link to someone's file: the link is not ours, nor its target.
  fs::remove(d / "frames");
  ASSERT_EQ(run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q").code, 0);
  fs::remove(d / "metrics.csv");
  fs::create_symlink(victim / "frame_00000.vtp", d / "metrics.csv");
  const Result again = run_upf("run " + scene() + " -o " + d.string() + " --end 0.02 -q");
  EXPECT_EQ(again.code, 2) << again.output;
  EXPECT_EQ(contents(victim / "frame_00000.vtp"), "theirs");
}

TEST_F(RunFolder, ASceneNameIsANameNotAPath) {
  // Without -o a run goes to out/<name>: "../victim" would have written (and cleared) beside out/.
  for (const std::string name : {"../victim", "/tmp/upf_victim", "a/b", ".."}) {
    auto doc = sample();
    doc["name"] = name;
    const std::string file = write(doc);
    const Result r = run_shell("cd " + dir_.string() + " && " + std::string(UPF_EXECUTABLE) +
                               " run " + file + " --end 0.01 -q");
    EXPECT_EQ(r.code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find(":/name"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << name;
  }
  EXPECT_FALSE(fs::exists(dir_.parent_path() / "victim"));
}

TEST_F(RunFolder, AnotherScenesCheckpointIsNotResumedIntoARun) {
  // Before: exit 0, and the folder mixed both scenes' frames, metrics and scene record.
  const fs::path a = dir_ / "a", b = dir_ / "b";
  auto small = sample();
  const std::string first = write(small, "first.json");
  small["fluid_blocks"][0]["max"][0] = 0.3;  // another scene: fewer particles
  const std::string second = write(small, "second.json");
  ASSERT_EQ(run_upf("run " + first + " -o " + a.string() + " --end 0.02 -q").code, 0);
  ASSERT_EQ(run_upf("run " + second + " -o " + b.string() + " --end 0.02 -q").code, 0);
  const std::string metrics = contents(a / "metrics.csv");
  fs::copy_file(b / "checkpoint.upfck", a / "checkpoint.upfck",
                fs::copy_options::overwrite_existing);
  const Result r = run_upf("run --resume " + a.string() + " --end 0.04 -q");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("another scene"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((a / "checkpoint.upfck").string()), std::string::npos) << r.output;
  EXPECT_EQ(contents(a / "metrics.csv"), metrics);
}

}  // namespace
}  // namespace upf::cli_test
