// The light frame a plate picture is composited with (client/vemview/light_frame_ring.h).
#include "client/vemview/light_frame_ring.h"

#include <gtest/gtest.h>

namespace vem::view {
namespace {

InputFrame frameAt(std::uint64_t seq, std::optional<double> captureUnixSec) {
  InputFrame frame;
  frame.seq = seq;
  frame.captureUnixSec = captureUnixSec;
  return frame;
}

// A plate that lags the probe by 70 ms was composited with the newest lights, 70 ms younger than
// the picture: the lights of a switched lamp led the picture by two frames.
TEST(LightFrameRing, LaggingPictureTakesTheLightFrameCapturedWithItNotTheNewest) {
  LightFrameRing ring(8);
  for (std::uint64_t i = 0; i < 6; ++i) ring.push(frameAt(i, 100.0 + 0.033 * double(i)));
  const LightFrameRing::Choice choice = ring.nearest(100.0 + 0.033 * 5 - 0.070, 0.050);
  ASSERT_NE(choice.frame, nullptr);
  EXPECT_TRUE(choice.withinWindow);
  EXPECT_EQ(choice.frame->seq, 3U);  // 99 ms after the first; the picture at 95 ms
}

TEST(LightFrameRing, NoFrameWithinTheWindowFallsBackToTheNewestAndSaysSo) {
  LightFrameRing ring(8);
  ring.push(frameAt(1, 100.0));
  ring.push(frameAt(2, 100.5));
  const LightFrameRing::Choice choice = ring.nearest(102.0, 0.1);
  EXPECT_FALSE(choice.withinWindow);
  EXPECT_EQ(choice.frame->seq, 2U);
}

TEST(LightFrameRing, FramesWithoutACaptureTimeAreNeverChosenByTime) {
  LightFrameRing ring(8);
  ring.push(frameAt(1, std::nullopt));
  ring.push(frameAt(2, std::nullopt));
  const LightFrameRing::Choice choice = ring.nearest(0.0, 1e9);
  EXPECT_FALSE(choice.withinWindow);
  EXPECT_EQ(choice.frame->seq, 2U);
}

TEST(LightFrameRing, TheSameFrameTwiceIsKeptOnceAndTheOldestGoesPastCapacity) {
  LightFrameRing ring(2);
  ring.push(frameAt(1, 1.0));
  ring.push(frameAt(1, 1.0));
  ring.push(frameAt(2, 2.0));
  ring.push(frameAt(3, 3.0));
  EXPECT_EQ(ring.nearest(1.0, 0.1).frame->seq, 3U);  // frame 1 is gone: the newest, outside
  EXPECT_EQ(ring.nearest(2.0, 0.1).frame->seq, 2U);
}

}  // namespace
}  // namespace vem::view
