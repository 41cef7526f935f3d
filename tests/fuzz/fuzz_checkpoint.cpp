// libFuzzer target: restoring a checkpoint (World::restore_state behind checkpoint_file.h). A
// checksum only proves that a file was not damaged by accident: someone who changes a byte can
// seal it again. Every input is a real checkpoint changed as the input says
// (checkpoint_mutation.h); the world must either take it and step on, or throw InputError naming
// the checkpoint. Anything else (a crash, a sanitizer report, a hang, a huge allocation) is a bug.
//   build/asan/tests/fuzz/fuzz_checkpoint -max_total_time=600 NEW_DIR tests/fuzz/corpus/checkpoint
#include "tests/fuzz/checkpoint_mutation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fz = upf::checkpoint_fuzz;
  const fz::Fixture& f = fz::fixture();
  (void)fz::restore_and_step(f, fz::mutated(f.checkpoint, data, size));
  return 0;
}
