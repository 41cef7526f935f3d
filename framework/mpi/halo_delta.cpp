#include "framework/mpi/halo_delta.h"

#include <cstring>
#include <numeric>
#include <stdexcept>

namespace upf {

void HaloDeltaSender::encode(std::vector<std::uint8_t>& packet,
                             const std::vector<std::size_t>& segments,
                             std::vector<std::uint8_t>& message) {
  const bool whole = !known_ || segments != last_segments_ || last_.size() != packet.size();
  message.assign(segments.size(), 0);
  std::size_t at = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const std::size_t bytes = segments[s];
    const bool changed =
        whole || (bytes > 0 && std::memcmp(packet.data() + at, last_.data() + at, bytes) != 0);
    if (changed) {
      message[s] = 1;
      message.insert(message.end(), packet.begin() + std::ptrdiff_t(at),
                     packet.begin() + std::ptrdiff_t(at + bytes));
    }
    at += bytes;
  }
  last_.swap(packet);  // no copy: a refresh packs its packet afresh
  last_segments_ = segments;
  known_ = true;
}

void HaloDeltaSender::forget() {
  known_ = false;
}

const std::vector<std::uint8_t>& HaloDeltaReceiver::decode(
    const std::uint8_t* message, std::size_t size, const std::vector<std::size_t>& segments) {
  const std::size_t total = std::accumulate(segments.begin(), segments.end(), std::size_t(0));
  if (size < segments.size()) throw std::logic_error("halo delta: a message without its flags");
  bool whole = true;
  for (std::size_t s = 0; s < segments.size(); ++s) whole = whole && message[s] != 0;
  if (whole)
    packet_.resize(total);
  else if (packet_.size() != total)
    throw std::logic_error("halo delta: a partial message for a packet of another size");
  const std::uint8_t* values = message + segments.size();
  const std::uint8_t* end = message + size;
  std::size_t at = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (message[s]) {
      if (std::size_t(end - values) < segments[s])
        throw std::logic_error("halo delta: a message shorter than its flags say");
      std::memcpy(packet_.data() + at, values, segments[s]);
      values += segments[s];
    }
    at += segments[s];
  }
  if (values != end) throw std::logic_error("halo delta: a message longer than its flags say");
  return packet_;
}

}  // namespace upf
