// The client's counters: skipped frames from seq gaps and the latency summary
// (client/reception_stats.h). The reconnect backoff is tested with vem_util (tests/util).
#include <gtest/gtest.h>

#include "client/reception_stats.h"

namespace vem::client {
namespace {

TEST(ReceptionStats, CountsSeqGapsAsSkipped) {
  ReceptionStats stats;
  for (std::uint64_t seq : {3, 4, 7, 8, 20}) stats.onLightFrame(seq, 0, 0);
  EXPECT_EQ(stats.received(), 5U);
  EXPECT_EQ(stats.skipped(), 2U + 11U);
}

TEST(ReceptionStats, ARestartedSequenceSkipsNothing) {
  ReceptionStats stats;
  for (std::uint64_t seq : {100, 101, 0, 1, 3}) stats.onLightFrame(seq, 0, 0);
  EXPECT_EQ(stats.skipped(), 1U);  // only 2, between 1 and 3
}

TEST(ReceptionStats, LatencyMedianAndP99AreNearestRanksOverTheWindow) {
  ReceptionStats stats(100);
  for (int i = 0; i < 150; ++i) {
    stats.onLightFrame(std::uint64_t(i), 1'000'000'000, 1'000'000'000 + i * 1'000'000);
  }
  const LatencySummary latency = stats.latency();  // the window holds 50..149 ms
  EXPECT_EQ(latency.samples, 100U);
  EXPECT_DOUBLE_EQ(latency.medianMs, 99.5);
  EXPECT_DOUBLE_EQ(latency.p99Ms, 148.0);
}

TEST(ReceptionStats, NoFramesGiveAnEmptyLatency) {
  EXPECT_EQ(ReceptionStats().latency().samples, 0U);
}

}  // namespace
}  // namespace vem::client
