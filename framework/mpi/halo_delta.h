// Leaner ghost refreshes (bench/README.md, "Leaner halos"): a refresh runs after every stage, and
// a stage writes one or two of the particles' arrays, so most of what a full refresh sends is what
// the receiver already holds. The sender keeps the packet it sent last; the next packet carries a
// flag per array (a segment of the packet) and only the segments whose bytes changed. The
// receiver keeps the packet it received last and rebuilds the whole packet from it, so its ghosts
// get exactly the bytes a full refresh would have sent, whatever it did to them in between.
// Plain bytes, no MPI: MpiDomain (mpi_domain.h) moves the messages.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace upf {

// The sending side, for one receiving rank.
class HaloDeltaSender {
 public:
  // The message for `packet`, cut into `segments` (byte lengths, in order, summing to its size):
  // a flag byte per segment, then the changed segments. Every segment counts as changed after
  // forget() and whenever the segments differ from the last packet's. The packet is kept (its
  // buffer swapped with the one kept before, whose bytes `packet` then holds).
  void encode(std::vector<std::uint8_t>& packet, const std::vector<std::size_t>& segments,
              std::vector<std::uint8_t>& message);
  // The receiver's ghosts are new (a new ghost list): the next packet goes whole.
  void forget();

 private:
  std::vector<std::uint8_t> last_;
  std::vector<std::size_t> last_segments_;
  bool known_ = false;
};

// The receiving side, for one sending rank.
class HaloDeltaReceiver {
 public:
  // The whole packet `message` (of `size` bytes) stands for, cut into `segments`; valid until
  // the next call. Throws std::logic_error when the message does not fit the packet held (the
  // two sides out of step: a bug, not bad input).
  const std::vector<std::uint8_t>& decode(const std::uint8_t* message, std::size_t size,
                                          const std::vector<std::size_t>& segments);

 private:
  std::vector<std::uint8_t> packet_;
};

}  // namespace upf
