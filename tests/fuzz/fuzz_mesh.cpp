// libFuzzer target: the mesh loader (coupling/mesh/mesh_loader.h, assimp underneath). The first
// byte picks the file extension, the rest is the file. load_mesh must return a mesh or throw
// InputError; a crash, another exception or a sanitizer report is a bug.
//   build/asan/tests/fuzz/fuzz_mesh -max_total_time=600 NEW_DIR tests/fuzz/corpus/mesh
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/mesh/mesh_loader.h"
#include "framework/core/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static constexpr std::array<const char*, 6> kExtensions = {".obj",  ".stl", ".ply",
                                                             ".gltf", ".glb", ".off"};
  if (size == 0) return -1;
  // One file per process, rewritten for every input.
  static const std::filesystem::path base =
      std::filesystem::temp_directory_path() / ("upf_fuzz_mesh_" + std::to_string(getpid()));
  const std::filesystem::path file = base.string() + kExtensions[data[0] % kExtensions.size()];
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try {
    (void)upf::load_mesh(file, {}, "/bodies/0/mesh");
  } catch (const upf::InputError&) {
    // The expected answer to a broken mesh.
  }
  std::filesystem::remove(file);
  return 0;
}
