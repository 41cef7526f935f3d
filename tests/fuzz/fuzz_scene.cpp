// libFuzzer target: the scene parser (framework/scene/scene_reader.h). Any bytes go in; the
// reader must either return a scene or throw InputError naming the culprit. Anything else (a
// crash, another exception, a sanitizer report, a hang) is a bug.
//   build/asan/tests/fuzz/fuzz_scene -max_total_time=600 NEW_DIR tests/fuzz/corpus/scene
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string_view>

#include "framework/core/errors.h"
#include "framework/scene/scene_reader.h"
#include "solvers/register_builtin_solvers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const upf::Registry registry = [] {
    upf::Registry r;
    upf::register_builtins(r);
    return r;
  }();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The JSON library's own syntax errors are reported by load_scene_file; here only the
  // documents it accepts are interesting.
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (document.is_discarded()) return -1;  // not kept in the corpus
  try {
    // Named as a file in samples/, so the samples' relative mesh paths resolve.
    (void)upf::read_scene(document, registry, UPF_SOURCE_DIR "/samples/fuzz.json");
  } catch (const upf::InputError&) {
    // The expected answer to bad input.
  }
  return 0;
}
