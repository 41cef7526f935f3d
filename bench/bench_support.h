// What the benchmarks share: the median of several runs.
#pragma once

#include <algorithm>
#include <vector>

namespace upf::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace upf::bench
