// seq and captureTsNs from libcamera's sequence numbers and timestamps
// (libcamera_frame_identity.h).
#include "cameras/libcamera/libcamera_frame_identity.h"

#include <gtest/gtest.h>

namespace vem::cameras {
namespace {

TEST(LibcameraFrameIdentity, GapInSequenceIsCountedAsLostAndSeqJumpsWithIt) {
  LibcameraFrameNumbering n;
  n.startSession();
  EXPECT_EQ(n.accept(0)->seq, 0u);
  EXPECT_EQ(n.accept(1)->seq, 1u);
  const auto jumped = n.accept(5);
  ASSERT_TRUE(jumped);
  EXPECT_EQ(jumped->seq, 5u);
  EXPECT_EQ(jumped->lost, 3u);
}

TEST(LibcameraFrameIdentity, SequenceWrappingAt2Pow32KeepsSeqIncreasing) {
  LibcameraFrameNumbering n;
  EXPECT_EQ(n.accept(0xffffffffu)->seq, 0u);
  const auto wrapped = n.accept(0u);
  ASSERT_TRUE(wrapped);
  EXPECT_EQ(wrapped->seq, 1u);
  EXPECT_EQ(wrapped->lost, 0u);
}

TEST(LibcameraFrameIdentity, RepeatedOrOlderSequenceIsRefused) {
  LibcameraFrameNumbering n;
  ASSERT_TRUE(n.accept(10));
  EXPECT_FALSE(n.accept(10));
  EXPECT_FALSE(n.accept(9));
  EXPECT_EQ(n.accept(11)->seq, 1u);
}

TEST(LibcameraFrameIdentity, NewSessionRestartingAtZeroContinuesSeq) {
  LibcameraFrameNumbering n;
  for (std::uint32_t s = 0; s < 4; ++s) ASSERT_TRUE(n.accept(s));
  n.startSession();
  const auto first = n.accept(0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->seq, 4u);
  EXPECT_EQ(first->lost, 0u);
}

TEST(LibcameraFrameIdentity, BoottimeStampIsShiftedByTheSuspendedTime) {
  // Boottime runs 7 s ahead of monotonic (7 s suspended); the frame was 2 ms ago.
  const std::int64_t mono = 1'000'000'000'000;
  const std::int64_t boot = mono + 7'000'000'000;
  EXPECT_EQ(
      monotonicCaptureNs(std::uint64_t(boot - 2'000'000), LibcameraClock::Boottime, boot, mono),
      mono - 2'000'000);
  EXPECT_EQ(monotonicCaptureNs(123, LibcameraClock::Monotonic, boot, mono), 123);
}

}  // namespace
}  // namespace vem::cameras
