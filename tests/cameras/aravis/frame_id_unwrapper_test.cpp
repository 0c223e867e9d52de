// Frame ids to seq: wraps of the 16-bit GigE Vision counter, gaps, restarts.
#include "cameras/aravis/frame_id_unwrapper.h"

#include <gtest/gtest.h>

namespace vem::cameras {
namespace {

TEST(FrameIdUnwrapper, SixteenBitWrapSkipsZeroAndKeepsSeqConsecutive) {
  FrameIdUnwrapper u;
  EXPECT_EQ(u.next(65534).seq, 0u);
  EXPECT_EQ(u.next(65535).seq, 1u);
  const auto afterWrap = u.next(1);  // GigE Vision ids never take 0
  EXPECT_EQ(afterWrap.seq, 2u);
  EXPECT_EQ(afterWrap.skipped, 0u);
}

TEST(FrameIdUnwrapper, GapsAdvanceSeqAndCountTheLostFrames) {
  FrameIdUnwrapper u;
  (void)u.next(10);
  const auto step = u.next(13);
  EXPECT_EQ(step.seq, 3u);
  EXPECT_EQ(step.skipped, 2u);
  const auto wrapped = u.next(13);  // a repeat: the counter restarted
  EXPECT_EQ(wrapped.seq, 4u);
}

TEST(FrameIdUnwrapper, GapAcrossTheWrapIsCounted) {
  FrameIdUnwrapper u;
  (void)u.next(65530);
  const auto step = u.next(3);  // 65531..65535, 1, 2 skipped
  EXPECT_EQ(step.skipped, 7u);
  EXPECT_EQ(step.seq, 8u);
}

TEST(FrameIdUnwrapper, RestartContinuesAfterTheLastSeqWhateverTheNewIds) {
  FrameIdUnwrapper u;
  (void)u.next(65400);
  (void)u.next(65401);
  u.restart();
  const auto step = u.next(65401);
  EXPECT_EQ(step.seq, 2u);
  EXPECT_EQ(step.skipped, 0u);
}

TEST(FrameIdUnwrapper, SixtyFourBitIdsDoNotWrapAtSixteenBits) {
  FrameIdUnwrapper u;
  (void)u.next(70000);
  EXPECT_EQ(u.next(70001).seq, 1u);
  EXPECT_EQ(u.next(5).seq, 2u);  // far below: a restart, not a wrap
}

}  // namespace
}  // namespace vem::cameras
