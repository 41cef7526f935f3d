// The neighbour grid's sorting on the executor's threads, with the serial result for any thread
// count. The input is cut into one contiguous chunk per thread (chunk t of T: [n t / T,
// n (t + 1) / T)); each chunk is counted, the counts are summed in chunk order, and each chunk
// then writes its own part of the output in its own order. Chunks are indices of a static
// for_each_index, so which thread runs a chunk does not matter either.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/executors/cpu/cpu_executor.h"

namespace upf {

// Stable LSD radix sort of `order` (indices into `key`) by key[index], 8 bits a pass; passes
// whose digit is the same for every index are skipped. `scratch` is working memory.
void radix_sort_by_key(const CpuExecutor& exec, const std::uint64_t* key,
                       std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& scratch);

// out = the indices s in [0, n) where keep(s), ascending.
template <class Keep>
void chunked_select(const CpuExecutor& exec, std::size_t n, Keep&& keep,
                    std::vector<std::uint32_t>& out) {
  const std::size_t chunks = std::size_t(exec.threads());
  std::vector<std::size_t> counts(chunks + 1, 0);
  auto first = [&](std::size_t t) { return n * t / chunks; };
  exec.for_each_index(chunks, [&](std::size_t t) {
    std::size_t c = 0;
    for (std::size_t s = first(t); s < first(t + 1); ++s) c += keep(s) ? 1 : 0;
    counts[t + 1] = c;
  });
  for (std::size_t t = 0; t < chunks; ++t) counts[t + 1] += counts[t];
  out.resize(counts[chunks]);
  exec.for_each_index(chunks, [&](std::size_t t) {
    std::size_t at = counts[t];
    for (std::size_t s = first(t); s < first(t + 1); ++s)
      if (keep(s)) out[at++] = std::uint32_t(s);
  });
}

}  // namespace upf
