// BracketGrouper alone: groups by reported exposure and consecutive seq, drops with reasons.
#include "cameras/bracketing/bracket_grouper.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cameras/bracketing/bracket_settings.h"

namespace vem::cameras {
namespace {

BracketGrouper grouper3() { return BracketGrouper({100.0, 400.0, 1600.0}, 0.05); }

TEST(BracketGrouper, CompletesAGroupOnlyAfterKMatchingConsecutiveFrames) {
  BracketGrouper g = grouper3();
  EXPECT_FALSE(g.offer(10, 100.0).complete);
  EXPECT_FALSE(g.offer(11, 400.0).complete);
  const GroupStep last = g.offer(12, 1600.0);
  EXPECT_TRUE(last.keepFrame);
  EXPECT_TRUE(last.complete);
  EXPECT_EQ(last.dropPending, 0u);
  EXPECT_EQ(g.pendingFrames(), 0u);
}

TEST(BracketGrouper, MatchesWithinTheToleranceOnly) {
  BracketGrouper g = grouper3();
  EXPECT_EQ(g.match(104.9), std::optional<std::size_t>(0));
  EXPECT_EQ(g.match(380.5), std::optional<std::size_t>(1));
  EXPECT_EQ(g.match(106.0), std::nullopt);
  EXPECT_EQ(g.match(200.0), std::nullopt);
}

TEST(BracketGrouper, FramesBeforeTheCycleStartAreDroppedOneByOne) {
  BracketGrouper g = grouper3();
  for (std::uint64_t seq = 0; seq < 2; ++seq) {  // a camera still on 1600 us, then on 400 us
    const GroupStep s = g.offer(seq, seq == 0 ? 1600.0 : 400.0);
    EXPECT_FALSE(s.keepFrame) << seq;
    EXPECT_EQ(s.dropPending, 0u);
  }
  EXPECT_TRUE(g.offer(2, 100.0).keepFrame);
}

TEST(BracketGrouper, ASeqGapDropsTheGroupInProgressForGap) {
  BracketGrouper g = grouper3();
  (void)g.offer(0, 100.0);
  (void)g.offer(1, 400.0);
  const GroupStep s = g.offer(3, 1600.0);  // frame 2 was lost
  EXPECT_EQ(s.dropPending, 2u);
  EXPECT_EQ(s.pendingReason, BracketDropReason::Gap);
  EXPECT_FALSE(s.keepFrame);  // 1600 us cannot start a group
  EXPECT_FALSE(s.complete);
}

TEST(BracketGrouper, AGapBeforeTheFirstExposureStartsANewGroup) {
  BracketGrouper g = grouper3();
  (void)g.offer(0, 100.0);
  const GroupStep s = g.offer(5, 100.0);
  EXPECT_EQ(s.dropPending, 1u);
  EXPECT_EQ(s.pendingReason, BracketDropReason::Gap);
  EXPECT_TRUE(s.keepFrame);
  EXPECT_EQ(g.pendingFrames(), 1u);
}

TEST(BracketGrouper, AnUnexpectedExposureDropsItsGroupAndItself) {
  BracketGrouper g = grouper3();
  (void)g.offer(0, 100.0);
  const GroupStep s = g.offer(1, 700.0);
  EXPECT_EQ(s.dropPending, 1u);
  EXPECT_EQ(s.pendingReason, BracketDropReason::OutOfCycle);
  EXPECT_FALSE(s.keepFrame);
  EXPECT_EQ(g.pendingFrames(), 0u);
}

TEST(BracketGrouper, AnExposureOutOfCycleOrderDropsTheGroup) {
  BracketGrouper g = grouper3();
  (void)g.offer(0, 100.0);
  const GroupStep s = g.offer(1, 1600.0);  // skipped 400 us
  EXPECT_EQ(s.dropPending, 1u);
  EXPECT_FALSE(s.keepFrame);
  // A repeated first exposure restarts the group with the new frame.
  (void)g.offer(2, 100.0);
  const GroupStep again = g.offer(3, 100.0);
  EXPECT_EQ(again.dropPending, 1u);
  EXPECT_TRUE(again.keepFrame);
}

TEST(BracketGrouper, ResetForgetsTheGroupAndTheLastSeq) {
  BracketGrouper g = grouper3();
  (void)g.offer(0, 100.0);
  (void)g.offer(1, 400.0);
  EXPECT_EQ(g.reset(), 2u);
  const GroupStep s = g.offer(7, 100.0);  // no gap is seen across a reset
  EXPECT_EQ(s.dropPending, 0u);
  EXPECT_TRUE(s.keepFrame);
}

TEST(BracketSettings, EveryFieldOutOfRangeIsRefusedWithASentenceNamingIt) {
  const BracketSettings good;
  EXPECT_EQ(bracketSettingsProblem(good), std::nullopt);
  const auto problem = [&](auto change) {
    BracketSettings s = good;
    change(s);
    return bracketSettingsProblem(s).value_or("");
  };
  EXPECT_NE(problem([](BracketSettings& s) { s.count = 1; }).find("count is 1"), std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.count = 10; }).find("2 to 9"), std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.stopsApart = 0.0; }).find("stops"),
            std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.baseExposureUs = -1.0; }).find("base_exposure_us"),
            std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) {
              s.count = 9;
              s.stopsApart = 4.0;
            }).find("longest"),
            std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.gain = 0.0; }).find("gain"), std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.matchTolerance = 0.7; }).find("match_tolerance"),
            std::string::npos);
  EXPECT_NE(problem([](BracketSettings& s) { s.matchTolerance = 0.0; }).find("match_tolerance"),
            std::string::npos);
}

TEST(BracketSettings, ExposuresGrowByTheStopsFromTheBase) {
  BracketSettings s;
  s.count = 4;
  s.stopsApart = 1.5;
  s.baseExposureUs = 50.0;
  const std::vector<double> e = bracketExposuresUs(s);
  ASSERT_EQ(e.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(e[std::size_t(k)], 50.0 * std::exp2(1.5 * k));
}

}  // namespace
}  // namespace vem::cameras
