// HandshakeSlots (handshake_slots.h): the caps that keep a slowloris flood from locking others out.
#include "stream/handshake_slots.h"

#include <gtest/gtest.h>

namespace vem::stream {
namespace {

TEST(HandshakeSlots, AnAddressOverItsCapIsRefusedWhileOthersAreAdmitted) {
  HandshakeSlots slots(100, 3);
  for (std::uint64_t id = 1; id <= 3; ++id) EXPECT_TRUE(slots.admit("10.0.0.9", id).admitted);
  const HandshakeAdmission fourth = slots.admit("10.0.0.9", 4);
  EXPECT_FALSE(fourth.admitted);
  EXPECT_FALSE(fourth.evict);
  EXPECT_TRUE(slots.admit("10.0.0.1", 5).admitted);
  EXPECT_EQ(slots.pendingFrom("10.0.0.9"), 3u);
  EXPECT_EQ(slots.pending(), 4u);
}

TEST(HandshakeSlots, AFullTableEvictsTheOldestOfTheAddressWithTheMost) {
  HandshakeSlots slots(5, 4);
  ASSERT_TRUE(slots.admit("a", 1).admitted);
  ASSERT_TRUE(slots.admit("flood", 2).admitted);
  ASSERT_TRUE(slots.admit("flood", 3).admitted);
  ASSERT_TRUE(slots.admit("flood", 4).admitted);
  ASSERT_TRUE(slots.admit("b", 5).admitted);
  const HandshakeAdmission newcomer = slots.admit("c", 6);
  EXPECT_TRUE(newcomer.admitted);
  ASSERT_TRUE(newcomer.evict);
  EXPECT_EQ(*newcomer.evict, 2u);  // flood's oldest, not "a" (older but alone)
  EXPECT_EQ(slots.pending(), 5u);
  EXPECT_EQ(slots.pendingFrom("flood"), 2u);
}

TEST(HandshakeSlots, AmongEqualAddressesTheOldestHandshakeGoes) {
  HandshakeSlots slots(2, 4);
  ASSERT_TRUE(slots.admit("x", 7).admitted);
  ASSERT_TRUE(slots.admit("y", 3).admitted);
  const HandshakeAdmission third = slots.admit("z", 9);
  ASSERT_TRUE(third.evict);
  EXPECT_EQ(*third.evict, 3u);
}

TEST(HandshakeSlots, AReleasedHandshakeFreesItsSlotAndItsAddress) {
  HandshakeSlots slots(2, 1);
  ASSERT_TRUE(slots.admit("a", 1).admitted);
  EXPECT_FALSE(slots.admit("a", 2).admitted);
  slots.release(1);
  slots.release(1);   // twice: no harm
  slots.release(42);  // unknown: no harm
  EXPECT_EQ(slots.pending(), 0u);
  const HandshakeAdmission again = slots.admit("a", 3);
  EXPECT_TRUE(again.admitted);
  EXPECT_FALSE(again.evict);
}

TEST(HandshakeSlots, AFloodFromManyAddressesStillLeavesANewcomerASlot) {
  HandshakeSlots slots(64, 8);
  std::uint64_t id = 0;
  for (int address = 0; address < 100; ++address) {
    for (int k = 0; k < 8; ++k) (void)slots.admit("flood-" + std::to_string(address), ++id);
  }
  EXPECT_EQ(slots.pending(), 64u);
  const HandshakeAdmission legit = slots.admit("render-node", ++id);
  EXPECT_TRUE(legit.admitted);
  EXPECT_TRUE(legit.evict);
  EXPECT_EQ(slots.pendingFrom("render-node"), 1u);
}

}  // namespace
}  // namespace vem::stream
