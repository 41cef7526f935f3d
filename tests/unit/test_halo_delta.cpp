// Leaner ghost refreshes (framework/mpi/halo_delta.h): only the arrays whose bytes changed travel,
// and the receiver rebuilds exactly the packet a full refresh would have sent.
#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>
#include <vector>

#include "framework/mpi/halo_delta.h"

namespace upf {
namespace {

std::vector<std::uint8_t> packet_of(std::size_t bytes, std::uint8_t first) {
  std::vector<std::uint8_t> p(bytes);
  std::iota(p.begin(), p.end(), first);
  return p;
}

// encode() keeps the packet it is given (a refresh packs afresh): a copy of ours.
void encode(HaloDeltaSender& sender, std::vector<std::uint8_t> packet,
            const std::vector<std::size_t>& segments, std::vector<std::uint8_t>& message) {
  sender.encode(packet, segments, message);
}

TEST(HaloDelta, TheFirstPacketGoesWholeThenOnlyTheChangedArrays) {
  const std::vector<std::size_t> segments = {12, 4, 8};
  HaloDeltaSender sender;
  HaloDeltaReceiver receiver;
  std::vector<std::uint8_t> packet = packet_of(24, 0), message;
  encode(sender, packet, segments, message);
  EXPECT_EQ(message.size(), 3u + 24u);
  EXPECT_EQ(receiver.decode(message.data(), message.size(), segments), packet);

  // A stage wrote the second array only: 3 flags and its 4 bytes travel.
  packet[13] = 99;
  encode(sender, packet, segments, message);
  EXPECT_EQ(message.size(), 3u + 4u);
  EXPECT_EQ(receiver.decode(message.data(), message.size(), segments), packet);

  // Nothing changed: the flags alone.
  encode(sender, packet, segments, message);
  EXPECT_EQ(message.size(), 3u);
  EXPECT_EQ(receiver.decode(message.data(), message.size(), segments), packet);
}

TEST(HaloDelta, NewGhostsOrAnotherLayoutSendTheWholePacket) {
  HaloDeltaSender sender;
  HaloDeltaReceiver receiver;
  std::vector<std::uint8_t> message;
  const std::vector<std::uint8_t> packet = packet_of(24, 0);
  encode(sender, packet, {12, 4, 8}, message);
  receiver.decode(message.data(), message.size(), {12, 4, 8});
  // The same bytes cut otherwise (an array added as another went): whole.
  encode(sender, packet, {12, 8, 4}, message);
  EXPECT_EQ(message.size(), 3u + 24u);
  EXPECT_EQ(receiver.decode(message.data(), message.size(), {12, 8, 4}), packet);
  // A new ghost list of the same size: whole after forget().
  sender.forget();
  encode(sender, packet, {12, 8, 4}, message);
  EXPECT_EQ(message.size(), 3u + 24u);
  // Fewer ghosts: whole.
  const std::vector<std::uint8_t> smaller = packet_of(12, 7);
  encode(sender, smaller, {6, 2, 4}, message);
  EXPECT_EQ(message.size(), 3u + 12u);
  EXPECT_EQ(receiver.decode(message.data(), message.size(), {6, 2, 4}), smaller);
}

TEST(HaloDelta, AMessageOutOfStepWithThePacketHeldIsABug) {
  HaloDeltaReceiver receiver;
  const std::vector<std::uint8_t> partial = {1, 0, 5, 5, 5, 5};
  EXPECT_THROW(receiver.decode(partial.data(), partial.size(), {4, 4}), std::logic_error);
  const std::vector<std::uint8_t> whole = {1, 1, 5, 5, 5, 5};
  EXPECT_THROW(receiver.decode(whole.data(), whole.size(), {4, 4}), std::logic_error);
}

}  // namespace
}  // namespace upf
