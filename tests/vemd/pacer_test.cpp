// FrameSchedule (when frames are due) and LoopStatistics (what the reports say): pure, no clock.
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "vemd/loop_statistics.h"
#include "vemd/pacer.h"
#include "vemd/source_rate.h"

namespace vem::vemd {
namespace {

TEST(FrameSchedule, FixedRateFramesAreDueOnePeriodApartFromTheFirst) {
  FrameSchedule schedule(10'000'000);
  EXPECT_EQ(schedule.dueNs(0, 1'000), 1'000);
  EXPECT_EQ(schedule.dueNs(0, 1'500), 10'001'000);       // early: wait for its slot
  EXPECT_EQ(schedule.dueNs(0, 30'000'000), 20'001'000);  // late: due at once (in the past)
}

TEST(FrameSchedule, RecordedRateFollowsTheTimestampSpacing) {
  FrameSchedule schedule(0);
  EXPECT_EQ(schedule.dueNs(5'000'000'000, 100), 100);
  EXPECT_EQ(schedule.dueNs(5'040'000'000, 200), 40'000'100);
  EXPECT_EQ(schedule.dueNs(5'050'000'000, 300), 50'000'100);
}

// After a stall of more than a second the schedule restarts from now, so the frames that were
// due meanwhile do not come out in a burst.
TEST(FrameSchedule, LongStallReanchorsInsteadOfBursting) {
  FrameSchedule schedule(10'000'000);
  EXPECT_EQ(schedule.dueNs(0, 0), 0);
  EXPECT_EQ(schedule.dueNs(0, 5'000'000'000), 5'000'000'000);
  EXPECT_EQ(schedule.dueNs(0, 5'000'000'001), 5'010'000'000);
}

TEST(FrameSchedule, MaxRateIsAlwaysDueNow) {
  FrameSchedule schedule(schedulePeriodNs({SourceRate::Mode::Max, 0.0}));
  EXPECT_EQ(schedule.dueNs(123, 77), 77);
  EXPECT_EQ(schedule.dueNs(0, 99), 99);
}

// A capture time of 1e18 ns after 0 made `--rate recorded` wait about 31 years. The step is
// replayed as one nominal period, said so, and the frames after it keep their own spacing.
TEST(FrameSchedule, CaptureTimeJumpOf1e18NsIsReplayedAsOneNominalPeriod) {
  FrameSchedule schedule(0, 33'333'333);
  EXPECT_EQ(schedule.next(0, 100).dueNs, 100);
  const FrameDue jumped = schedule.next(1'000'000'000'000'000'000, 200);
  EXPECT_EQ(jumped.dueNs, 100 + 33'333'333);
  EXPECT_EQ(jumped.jump, (TimestampJump{0, 1'000'000'000'000'000'000}));
  const FrameDue after = schedule.next(1'000'000'000'040'000'000, 300);
  EXPECT_EQ(after.dueNs, 100 + 33'333'333 + 40'000'000);
  EXPECT_FALSE(after.jump);
}

// A capture time going back was due at once (and unreported); now it takes one nominal period.
TEST(FrameSchedule, CaptureTimeGoingBackIsReplayedAsOneNominalPeriod) {
  FrameSchedule schedule(0, 20'000'000);
  EXPECT_EQ(schedule.next(5'000'000'000, 0).dueNs, 0);
  const FrameDue back = schedule.next(4'000'000'000, 10);
  EXPECT_EQ(back.dueNs, 20'000'000);
  EXPECT_EQ(back.jump, (TimestampJump{5'000'000'000, 4'000'000'000}));
  EXPECT_EQ(schedule.next(4'010'000'000, 20).dueNs, 30'000'000);
}

TEST(FrameSchedule, StepOfTenSecondsIsWaitedAndOneNanosecondMoreIsAJump) {
  FrameSchedule schedule(0, 1'000'000);
  EXPECT_EQ(schedule.next(0, 0).dueNs, 0);
  const FrameDue longest = schedule.next(FrameSchedule::kMaxRecordedIntervalNs, 0);
  EXPECT_EQ(longest.dueNs, FrameSchedule::kMaxRecordedIntervalNs);
  EXPECT_FALSE(longest.jump);
  const FrameDue tooLong = schedule.next(2 * FrameSchedule::kMaxRecordedIntervalNs + 1, 0);
  EXPECT_EQ(tooLong.dueNs, FrameSchedule::kMaxRecordedIntervalNs + 1'000'000);
  EXPECT_TRUE(tooLong.jump);
}

// The difference of the two ends of int64 overflowed (undefined behaviour, in practice -1: due
// at once); it is a jump like any other.
TEST(FrameSchedule, CaptureTimesAtTheEndsOfInt64DoNotOverflow) {
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  FrameSchedule schedule(0, 1'000'000);
  EXPECT_EQ(schedule.next(kMin, 5).dueNs, 5);
  const FrameDue up = schedule.next(kMax, 6);
  EXPECT_EQ(up.dueNs, 1'000'005);
  EXPECT_EQ(up.jump, (TimestampJump{kMin, kMax}));
  const FrameDue down = schedule.next(kMin, 7);
  EXPECT_EQ(down.dueNs, 2'000'005);
  EXPECT_TRUE(down.jump);
}

TEST(SourceRate, PeriodOfAFixedRate) {
  EXPECT_EQ(schedulePeriodNs({SourceRate::Mode::Fixed, 30.0}), 33'333'333);
  EXPECT_EQ(schedulePeriodNs({SourceRate::Mode::Recorded, 0.0}), 0);
  EXPECT_EQ(formatSourceRate({SourceRate::Mode::Fixed, 29.97}), "29.97");
}

ProcessedFrame timedFrame(const CapturedFrame& captured, double micros) {
  ProcessedFrame f;
  f.captured = &captured;
  for (const char* stage : {"calibrate", "tables"}) f.timings.push_back({stage, micros});
  return f;
}

TEST(LoopStatistics, WindowReportsOnlyWhatHappenedSinceTheLastReport) {
  LoopStatistics stats(0);
  const CapturedFrame a{{}, 0, 0, 1'000'000};
  stats.frameProcessed(timedFrame(a, 100.0), 10.0, 3'000'000, false);
  util::QueueCounters queue{5, 1, 4, 0, 2};
  const LoopReport first = stats.takeWindow(1'000'000'000, queue, 2);
  EXPECT_EQ(first.processed, 1u);
  EXPECT_EQ(first.framesIn, 5u);
  EXPECT_EQ(first.dropped, 4u);
  EXPECT_EQ(first.sourceErrors, 2u);
  EXPECT_DOUBLE_EQ(first.arrivalToSinksDoneMs.mean(), 2.0);
  EXPECT_DOUBLE_EQ(first.framesPerSecond(), 1.0);
  stats.frameProcessed(timedFrame(a, 300.0), 30.0, 5'000'000, true);
  queue = {7, 2, 4, 0, 2};
  const LoopReport second = stats.takeWindow(3'000'000'000, queue, 2);
  EXPECT_EQ(second.processed, 1u);
  EXPECT_EQ(second.framesIn, 2u);
  EXPECT_EQ(second.dropped, 0u);
  EXPECT_EQ(second.sourceErrors, 0u);
  EXPECT_DOUBLE_EQ(second.elapsedS, 2.0);
  EXPECT_DOUBLE_EQ(second.captureToSinksDoneMs.mean(), 5.0);
  const LoopReport total = stats.totals(3'000'000'000, queue, 2);
  EXPECT_EQ(total.processed, 2u);
  ASSERT_EQ(total.stages.size(), 3u);
  EXPECT_DOUBLE_EQ(total.stages[0].micros.mean(), 200.0);
  EXPECT_DOUBLE_EQ(total.stages[0].micros.max, 300.0);
  EXPECT_EQ(total.stages[2].stage, "sinks");
}

TEST(LoopStatistics, ReportLineNamesCountsRateLatencyAndStages) {
  LoopStatistics stats(0);
  const CapturedFrame a{{}, 0, 0, 0};
  stats.frameProcessed(timedFrame(a, 900.0), 12.0, 3'210'000, true);
  const LoopReport r = stats.totals(2'000'000'000, {3, 1, 2, 0, 2}, 0);
  EXPECT_EQ(formatReport(r, "stats"),
            "stats 2.0 s: 3 in, 1 processed (0.5 frames/s), 2 dropped, 0 bad, 0 source errors; "
            "latency from arrival to sinks done 3.21 ms mean, 3.21 max; from capture to sinks "
            "done 3.21 ms mean, 3.21 max; stages us mean/max: calibrate 900/900 tables 900/900 sinks 12/12");
}

}  // namespace
}  // namespace vem::vemd
