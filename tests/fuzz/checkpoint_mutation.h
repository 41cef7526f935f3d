// A real checkpoint of a small scene with all four particle types (liquid, grains, a Bullet box,
// walls), changed as an attacker who re-seals the checksum would, and handed to a freshly
// prepared world as a resumed run would: shared by the libFuzzer target (fuzz_checkpoint.cpp) and
// the unit test that replays random changes in every build (test_checkpoint_validation.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "coupling/bodies/bodies_section.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

namespace upf::checkpoint_fuzz {

constexpr const char* kScene = R"({
  "name": "fuzz_checkpoint",
  "particle_spacing": 0.05,
  "materials": {
    "water": { "type": "liquid", "density": 1000, "solver": "pcisph" },
    "walls": { "type": "frozen" },
    "sand": { "type": "granular", "density": 2600, "radius": 0.02, "solver": "dem_linear" },
    "wood": { "type": "rigid", "density": 500 }
  },
  "containers": [ { "material": "walls", "min": [0, 0, 0], "max": [0.5, 0.5, 0.3] } ],
  "fluid_blocks": [ { "material": "water", "min": [0, 0, 0], "max": [0.25, 0.2, 0.3] } ],
  "granular_blocks": [ { "material": "sand", "min": [0.3, 0.1, 0.05], "max": [0.45, 0.25, 0.2] } ],
  "bodies": [ { "name": "box", "material": "wood",
      "mesh": { "file": "../assets/meshes/unit_box.obj", "scale": 0.1, "position": [0.35, 0.35, 0.15] } } ],
  "time": { "end": 1, "dt_max": 0.002 }
})";

struct Fixture {
  Registry registry;
  SceneDescription scene;
  std::vector<char> checkpoint;  // of the world after a few steps
};

inline const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture made;
    register_builtins(made.registry);
    register_coupling(made.registry);
    made.scene = read_scene(nlohmann::json::parse(kScene), made.registry,
                            UPF_SOURCE_DIR "/samples/fuzz_checkpoint.json");
    auto world = build_world(made.scene, made.registry, 1);
    world->prepare();
    world->step_towards(0.01);
    StateWriter out;
    world->save_state(out);
    made.checkpoint = out.bytes();
    return made;
  }();
  return f;
}

// `checkpoint` changed by `data`: 4 bytes "cut" (when its top bit is set, the checkpoint is cut
// to cut % size bytes), then 5-byte records: a little-endian 32-bit offset (modulo the size) and
// a byte to XOR there.
inline std::vector<char> mutated(std::vector<char> bytes, const std::uint8_t* data,
                                 std::size_t size) {
  if (size < 4) return bytes;
  std::uint32_t cut;
  std::memcpy(&cut, data, 4);
  if (cut & 0x80000000u) bytes.resize(std::size_t(cut & 0x7fffffffu) % (bytes.size() + 1));
  for (std::size_t k = 4; k + 5 <= size && !bytes.empty(); k += 5) {
    std::uint32_t at;
    std::memcpy(&at, data + k, 4);
    bytes[at % bytes.size()] = char(bytes[at % bytes.size()] ^ char(data[k + 4]));
  }
  return bytes;
}

// Restores `bytes` into a fresh world of the fixture's scene and steps on. Returns true when the
// world took it, false when it was refused with InputError (or stopped by InstabilityError: a
// state the checks let through may still blow up, and the run stops cleanly). Anything else
// escapes: a crash or another exception is the bug the callers look for.
inline bool restore_and_step(const Fixture& f, std::vector<char> bytes) {
  auto world = build_world(f.scene, f.registry, 1);
  world->prepare();
  try {
    StateReader in(std::move(bytes), "fuzz.upfck");
    world->restore_state(in);
    world->step_towards(world->time() + 0.004);
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const InstabilityError&) {
    return false;
  }
}

}  // namespace upf::checkpoint_fuzz
