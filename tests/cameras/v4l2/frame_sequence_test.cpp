// FrameSequence: the driver's sequence numbers to vemd's strictly increasing seq.
#include <gtest/gtest.h>

#include "cameras/v4l2/frame_sequence.h"

namespace vem::cameras {
namespace {

TEST(FrameSequence, GapsInTheDriverSequenceAreKeptAndCountedLost) {
  FrameSequence s;
  EXPECT_EQ(s.next(7), 0u);
  EXPECT_EQ(s.next(8), 1u);
  EXPECT_EQ(s.next(11), 4u);
  EXPECT_EQ(s.lost(), 2u);
}

TEST(FrameSequence, ARestartedDriverCountDoesNotGoBackwards) {
  FrameSequence s;
  EXPECT_EQ(s.next(100), 0u);
  EXPECT_EQ(s.next(101), 1u);
  s.restart();
  EXPECT_EQ(s.next(0), 2u);
  EXPECT_EQ(s.next(1), 3u);
  EXPECT_EQ(s.lost(), 0u);
  // A backwards jump without restart() is not a gap of 4 billion frames either.
  EXPECT_EQ(s.next(0), 4u);
  EXPECT_EQ(s.lost(), 0u);
}

TEST(FrameSequence, TheDriverSequenceWrapsAt32Bits) {
  FrameSequence s;
  EXPECT_EQ(s.next(0xffffffffu), 0u);
  EXPECT_EQ(s.next(1), 2u);
  EXPECT_EQ(s.lost(), 1u);
}

}  // namespace
}  // namespace vem::cameras
