// Checkpoints are validated, not trusted (issue 46): a file whose checksum is valid may still
// hold another scene's particles, repeated or out-of-range ids, values that are not finite; and a
// path may name a device, a FIFO or a folder. Each is an InputError naming the file, before the
// world is touched; random single-byte changes (sealed again, as the fuzz target does) never
// crash. Reference: the checks listed in docs/robustness.md ("Damaged or foreign checkpoints").
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "framework/checkpoint/checkpoint_file.h"
#include "tests/fuzz/checkpoint_mutation.h"

namespace upf {
namespace {

namespace fs = std::filesystem;
namespace fz = checkpoint_fuzz;

// The fixture's world after a few steps, changed by `change`, saved: what a hostile checkpoint
// holds. Returns the message of the InputError a fresh world throws on it ("" if it took it).
template <class Change>
std::string refusal_of(Change&& change) {
  const fz::Fixture& f = fz::fixture();
  auto world = build_world(f.scene, f.registry, 1);
  world->prepare();
  world->step_towards(0.01);
  change(world->particles());
  StateWriter out;
  world->save_state(out);
  auto fresh = build_world(f.scene, f.registry, 1);
  fresh->prepare();
  const ParticleId before = fresh->particles().id[0];
  try {
    StateReader in(out.bytes(), "hostile.upfck");
    fresh->restore_state(in);
  } catch (const InputError& e) {
    // Nothing was taken: the world is still the prepared one.
    EXPECT_EQ(fresh->particles().id[0], before);
    return e.what();
  }
  return "";
}

TEST(CheckpointValidation, AnUnchangedCheckpointIsTaken) {
  EXPECT_EQ(refusal_of([](Particles&) {}), "");
  const fz::Fixture& f = fz::fixture();
  EXPECT_TRUE(fz::restore_and_step(f, f.checkpoint));
}

TEST(CheckpointValidation, ARepeatedParticleIdIsRefused) {
  const std::string why = refusal_of([](Particles& p) { p.id[1] = p.id[0]; });
  EXPECT_NE(why.find("appears twice"), std::string::npos) << why;
  EXPECT_NE(why.find("hostile.upfck"), std::string::npos) << why;
}

TEST(CheckpointValidation, AnIdBeyondTheCounterIsRefused) {
  const std::string why = refusal_of([](Particles& p) { p.id[3] = 1u << 30; });
  EXPECT_NE(why.find("beyond the id counter"), std::string::npos) << why;
}

TEST(CheckpointValidation, AnUnknownTypeOrMaterialIsRefused) {
  std::string why = refusal_of([](Particles& p) { p.type[2] = ParticleType(9); });
  EXPECT_NE(why.find("particle type 9"), std::string::npos) << why;
  why = refusal_of([](Particles& p) { p.material[2] = 77; });
  EXPECT_NE(why.find("material 77"), std::string::npos) << why;
  why = refusal_of([](Particles& p) {  // a liquid particle made a wall: its material is liquid
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Liquid) {
        p.type[i] = ParticleType::Frozen;
        break;
      }
  });
  EXPECT_NE(why.find("of another type"), std::string::npos) << why;
}

TEST(CheckpointValidation, ANonFinitePositionIsRefused) {
  const std::string why =
      refusal_of([](Particles& p) { p.position[5].y = std::numeric_limits<Real>::quiet_NaN(); });
  EXPECT_NE(why.find("position is not finite"), std::string::npos) << why;
}

TEST(CheckpointValidation, AnotherScenesParticlesAreRefused) {
  // Sound on their own, but not this scene's: a grain turned into a liquid particle (another
  // material and type of the same scene), or a body particle given to no body.
  std::string why = refusal_of([](Particles& p) {
    MaterialId water = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Liquid) water = p.material[i];
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.type[i] == ParticleType::Granular) {
        p.type[i] = ParticleType::Liquid;
        p.material[i] = water;
        break;
      }
  });
  EXPECT_NE(why.find("another run"), std::string::npos) << why;
  why = refusal_of([](Particles& p) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body[i] != kNoBody) {
        p.body[i] = kNoBody;
        break;
      }
  });
  EXPECT_NE(why.find("another run"), std::string::npos) << why;
}

TEST(CheckpointValidation, RandomSingleByteChangesNeverCrash) {
  // The experiment: single changed bytes, re-sealed; 8 of 250 crashed before. Each is
  // either taken (and the world steps on) or refused; a crash ends the test binary.
  const fz::Fixture& f = fz::fixture();
  std::mt19937 random(46);
  std::uniform_int_distribution<std::uint32_t> offset(0, std::uint32_t(f.checkpoint.size() - 1));
  std::uniform_int_distribution<int> bit(0, 7);
  int refused = 0;
  constexpr int kChanges = 300;
  for (int k = 0; k < kChanges; ++k) {
    std::vector<char> bytes = f.checkpoint;
    bytes[offset(random)] ^= char(1 << bit(random));
    if (!fz::restore_and_step(f, std::move(bytes))) ++refused;
  }
  RecordProperty("refused", refused);
  // Most bytes are particle data: a flipped mantissa bit is a sound (if different) state.
  EXPECT_GT(refused, 0);
  EXPECT_LT(refused, kChanges);
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("upf_ckpt_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The message of read_checkpoint's InputError on `path` (before: a hang or a crash).
  static std::string refusal(const fs::path& path) {
    try {
      (void)read_checkpoint(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(CheckpointFile, ALinkToADeviceIsRefusedWithoutReadingIt) {
  const fs::path link = dir_ / "checkpoint.upfck";
  fs::create_symlink("/dev/zero", link);
  const std::string why = refusal(link);
  EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
  EXPECT_NE(why.find(link.string()), std::string::npos) << why;
}

TEST_F(CheckpointFile, AFifoIsRefusedWithoutWaiting) {
  const fs::path fifo = dir_ / "checkpoint.upfck";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string why = refusal(fifo);  // before: blocked in open() for ever
  EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
}

TEST_F(CheckpointFile, ADirectoryIsRefusedByName) {
  const fs::path folder = dir_ / "checkpoint.upfck";
  fs::create_directories(folder);
  const std::string why = refusal(folder);
  EXPECT_NE(why.find("is a directory"), std::string::npos) << why;
  EXPECT_NE(why.find(folder.string()), std::string::npos) << why;
}

TEST_F(CheckpointFile, AHeaderClaimingMoreThanTheFileIsRefused) {
  const fs::path path = dir_ / "checkpoint.upfck";
  write_checkpoint(path, std::vector<char>(64, 'x'));
  // The payload size field sits just before the checksum, 16 bytes before the payload.
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  const auto size = fs::file_size(path);
  f.seekp(std::streamoff(size - 64 - 16));
  const std::uint64_t huge = std::uint64_t(1) << 60;
  f.write(reinterpret_cast<const char*>(&huge), sizeof huge);
  f.close();
  const std::string why = refusal(path);
  EXPECT_NE(why.find("the header says"), std::string::npos) << why;
  // And the real one still reads.
  write_checkpoint(path, std::vector<char>(64, 'x'));
  EXPECT_EQ(read_checkpoint(path).remaining(), 64u);
}

}  // namespace
}  // namespace upf
