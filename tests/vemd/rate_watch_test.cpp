// RateWatch (vemd/rate_watch.h) driven by made-up timestamps: a source at its rate is quiet, one
// that falls below 90 % is reported once, and once again when it is back at 97 %; no flapping in
// between, no judgement before a whole window, start-up not counted.
#include "vemd/rate_watch.h"

#include <cstdint>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

namespace vem::vemd {
namespace {

constexpr std::int64_t kPollNs = 50'000'000;  // the loop samples at least every 50 ms

// Feeds `seconds` of a source delivering `hz` frames per second, sampled every 50 ms, from
// (nowNs, frames); returns the changes.
class FakeSource {
 public:
  explicit FakeSource(RateWatch& watch) : watch_(watch) {}
  std::vector<RateChange> run(double hz, double seconds) {
    std::vector<RateChange> changes;
    const auto steps = std::int64_t(seconds * 1e9 / double(kPollNs));
    for (std::int64_t i = 0; i < steps; ++i) {
      nowNs_ += kPollNs;
      produced_ += hz * double(kPollNs) * 1e-9;
      if (auto change = watch_.observe(nowNs_, std::uint64_t(produced_)))
        changes.push_back(*change);
    }
    return changes;
  }

 private:
  RateWatch& watch_;
  std::int64_t nowNs_ = 1'000'000'000;
  double produced_ = 0.0;
};

TEST(RateWatch, SourceAtItsNominalRateIsNeverReported) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  EXPECT_TRUE(source.run(30.0, 60.0).empty());
  EXPECT_FALSE(watch.below());
}

// Catches a synthetic scene at 3.9 frames/s of a nominal 30 going unreported (issue 17).
TEST(RateWatch, SlowSourceIsReportedOnceWithTheMeasuredAndNominalRates) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  ASSERT_TRUE(source.run(30.0, 5.0).empty());
  const std::vector<RateChange> changes = source.run(3.9, 20.0);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(changes[0].below);
  EXPECT_LT(changes[0].measuredHz, 27.0);
  EXPECT_EQ(changes[0].nominalHz, 30.0);
  // Once the window holds only the slow part, the measured rate is the slow one.
  const std::vector<RateChange> later = source.run(3.9, 10.0);
  EXPECT_TRUE(later.empty());
  EXPECT_TRUE(watch.below());
}

TEST(RateWatch, SlowFromTheStartIsReportedAfterOneWindowWithItsRate) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  EXPECT_TRUE(source.run(3.9, 2.9).empty()) << "no judgement before a whole window";
  const std::vector<RateChange> changes = source.run(3.9, 1.0);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_NEAR(changes[0].measuredHz, 3.9, 0.5);
}

TEST(RateWatch, RecoveryIsReportedOnlyAtTheRecoveryThreshold) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  ASSERT_EQ(source.run(10.0, 10.0).size(), 1u);
  EXPECT_TRUE(source.run(28.5, 10.0).empty()) << "95 % is not back yet (97 %)";
  const std::vector<RateChange> back = source.run(30.0, 10.0);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_FALSE(back[0].below);
  EXPECT_GE(back[0].measuredHz, 0.97 * 30.0);
  EXPECT_FALSE(watch.below());
}

TEST(RateWatch, RateHoveringBetweenTheThresholdsDoesNotFlap) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  std::vector<RateChange> changes;
  for (int i = 0; i < 10; ++i) {
    for (const RateChange& c : source.run(26.5, 4.0)) changes.push_back(c);  // 88 %
    for (const RateChange& c : source.run(28.5, 4.0)) changes.push_back(c);  // 95 %
  }
  EXPECT_EQ(changes.size(), 1u);
}

TEST(RateWatch, StartUpBeforeTheFirstFrameIsNotCounted) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  // 2 s without a frame (a camera starting), then the nominal rate.
  std::int64_t nowNs = 0;
  for (int i = 0; i < 40; ++i) EXPECT_FALSE(watch.observe(nowNs += kPollNs, 0));
  std::uint64_t frames = 0;
  for (int i = 0; i < 200; ++i) {
    nowNs += kPollNs;
    frames += (i % 2 == 0) ? 1 : 2;  // 30 frames/s
    EXPECT_FALSE(watch.observe(nowNs, frames)) << i;
  }
}

TEST(RateWatch, RestartForgetsTheWindowButKeepsTheState) {
  RateWatch watch(30.0);
  FakeSource source(watch);
  ASSERT_EQ(source.run(5.0, 5.0).size(), 1u);
  watch.restart();
  EXPECT_TRUE(watch.below());
  EXPECT_TRUE(source.run(5.0, 5.0).empty()) << "still slow: not reported again";
}

}  // namespace
}  // namespace vem::vemd
