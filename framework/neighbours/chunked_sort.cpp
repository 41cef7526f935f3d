#include "framework/neighbours/chunked_sort.h"

#include <algorithm>
#include <array>

namespace upf {

void radix_sort_by_key(const CpuExecutor& exec, const std::uint64_t* key,
                       std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& scratch) {
  constexpr int kPasses = 8;
  using Digits = std::array<std::uint32_t, 256>;
  const std::size_t n = order.size();
  const std::size_t chunks = std::size_t(exec.threads());
  auto first = [&](std::size_t t) { return n * t / chunks; };
  // Every digit's count over all indices: a pass whose digit one value holds throughout is
  // skipped (Morton keys leave most high bytes alike).
  std::vector<std::array<Digits, kPasses>> all(chunks);
  exec.for_each_index(chunks, [&](std::size_t t) {
    auto& h = all[t];
    for (auto& digits : h) digits.fill(0);
    for (std::size_t s = first(t); s < first(t + 1); ++s) {
      const std::uint64_t k = key[order[s]];
      for (int p = 0; p < kPasses; ++p) ++h[std::size_t(p)][(k >> (8 * p)) & 0xff];
    }
  });
  scratch.resize(n);
  std::vector<Digits> at(chunks);
  for (int p = 0; p < kPasses; ++p) {
    bool alike = false;
    for (std::size_t d = 0; d < 256 && !alike; ++d) {
      std::size_t total = 0;
      for (std::size_t t = 0; t < chunks; ++t) total += all[t][std::size_t(p)][d];
      alike = total == n;
    }
    if (alike) continue;
    const int shift = 8 * p;
    // This pass's counts per chunk (the chunks hold other indices after each pass).
    exec.for_each_index(chunks, [&](std::size_t t) {
      at[t].fill(0);
      for (std::size_t s = first(t); s < first(t + 1); ++s)
        ++at[t][(key[order[s]] >> shift) & 0xff];
    });
    // Where each chunk's indices of each digit go: digit by digit, chunk by chunk.
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < 256; ++d)
      for (std::size_t t = 0; t < chunks; ++t) {
        const std::uint32_t c = at[t][d];
        at[t][d] = sum;
        sum += c;
      }
    exec.for_each_index(chunks, [&](std::size_t t) {
      Digits& next = at[t];
      for (std::size_t s = first(t); s < first(t + 1); ++s) {
        const std::uint32_t i = order[s];
        scratch[next[(key[i] >> shift) & 0xff]++] = i;
      }
    });
    order.swap(scratch);
  }
}

}  // namespace upf
