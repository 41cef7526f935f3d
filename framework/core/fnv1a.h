// FNV-1a, 64 bits (Fowler, Noll and Vo; the parameters of the IETF draft
// draft-eastlake-fnv): the checksum of checkpoints and the identities a checkpoint is compared
// with (the scene's text, the walls', bodies' and grains' particles). Fast and fixed for every
// platform; not a defence against a chosen collision, which the checks behind it do not need.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace upf {

class Fnv1a {
 public:
  void add_bytes(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) {
      hash_ ^= bytes[k];
      hash_ *= 1099511628211ull;
    }
  }
  template <class T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    add_bytes(&value, sizeof value);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

inline std::uint64_t fnv1a(const void* data, std::size_t n) {
  Fnv1a hash;
  hash.add_bytes(data, n);
  return hash.value();
}

}  // namespace upf
