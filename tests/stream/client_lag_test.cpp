// ClientLag (client_lag.h): the pacing of one client by probe pings. Times are made up; each test
// names the bug it stops.
#include "stream/client_lag.h"

#include <gtest/gtest.h>

namespace vem::stream {
namespace {

constexpr std::int64_t kMs = 1'000'000;

ClientLagOptions options() {
  ClientLagOptions o;
  o.slackNs = 100 * kMs;
  o.maxLagNs = 5'000 * kMs;
  o.maxProbes = 8;
  return o;
}

TEST(ClientLag, AClientThatKeepsUpIsNeverHeld) {
  ClientLag lag(options());
  std::int64_t now = 0;
  for (int frame = 0; frame < 100; ++frame) {
    ASSERT_TRUE(lag.mayWrite(now));
    const auto probe = lag.probeSent(now);
    ASSERT_TRUE(probe);
    now += 2 * kMs;  // a 2 ms round trip
    lag.pongReceived(*probe, now);
    EXPECT_EQ(lag.lagNs(now), 0);
    now += 31 * kMs;
  }
  EXPECT_EQ(lag.minRoundTripNs(), 2 * kMs);
}

TEST(ClientLag, ASlowReaderIsHeldOnceItsOldestProbeIsOlderThanItsRoundTripPlusSlack) {
  ClientLag lag(options());
  const auto first = lag.probeSent(0);
  lag.pongReceived(*first, 10 * kMs);  // round trip 10 ms
  (void)lag.probeSent(100 * kMs);      // not read yet
  EXPECT_TRUE(lag.mayWrite(150 * kMs));
  EXPECT_TRUE(lag.mayWrite(209 * kMs));   // 109 ms behind: under 10 + 100
  EXPECT_FALSE(lag.mayWrite(211 * kMs));  // 111 ms behind: held
  EXPECT_EQ(lag.lagNs(211 * kMs), 111 * kMs);
}

TEST(ClientLag, APongConfirmsItsProbeAndEveryEarlierOne) {
  ClientLag lag(options());
  const auto a = lag.probeSent(0);
  const auto b = lag.probeSent(1 * kMs);
  const auto c = lag.probeSent(2 * kMs);
  ASSERT_TRUE(a && b && c);
  lag.pongReceived(*b, 500 * kMs);
  EXPECT_EQ(lag.unconfirmed(), 1u);
  EXPECT_EQ(lag.lagNs(600 * kMs), 598 * kMs);  // c's age
  EXPECT_EQ(lag.lastRoundTripNs(), 499 * kMs);
  lag.pongReceived(*c, 600 * kMs);
  EXPECT_EQ(lag.unconfirmed(), 0u);
  EXPECT_TRUE(lag.mayWrite(600 * kMs));
}

TEST(ClientLag, UnknownOrAlreadyConfirmedPongsChangeNothing) {
  ClientLag lag(options());
  const auto a = lag.probeSent(0);
  lag.pongReceived(*a, 5 * kMs);
  const auto b = lag.probeSent(10 * kMs);
  lag.pongReceived(*a, 20 * kMs);   // stale
  lag.pongReceived(999, 20 * kMs);  // never sent
  lag.pongReceived(0, 20 * kMs);    // never sent
  EXPECT_EQ(lag.unconfirmed(), 1u);
  EXPECT_EQ(lag.minRoundTripNs(), 5 * kMs);
  lag.pongReceived(*b, 30 * kMs);
  EXPECT_EQ(lag.unconfirmed(), 0u);
}

TEST(ClientLag, AClientBehindByMoreThanMaxLagIsTooSlow) {
  ClientLag lag(options());
  (void)lag.probeSent(0);
  EXPECT_FALSE(lag.tooSlow(5'000 * kMs));
  EXPECT_TRUE(lag.tooSlow(5'001 * kMs));
}

TEST(ClientLag, TooManyUnconfirmedProbesHoldTheClientWhateverTheirAge) {
  ClientLag lag(options());
  const auto first = lag.probeSent(0);
  lag.pongReceived(*first, 1'000 * kMs);  // a 1 s round trip: a distant client
  for (int i = 0; i < 8; ++i) ASSERT_TRUE(lag.probeSent(1'000 * kMs));
  EXPECT_FALSE(lag.probeSent(1'000 * kMs));
  EXPECT_FALSE(lag.mayWrite(1'000 * kMs));
}

TEST(ClientLag, NothingSentNothingBehind) {
  ClientLag lag(options());
  EXPECT_TRUE(lag.mayWrite(1'000'000 * kMs));
  EXPECT_EQ(lag.lagNs(1'000'000 * kMs), 0);
  EXPECT_FALSE(lag.tooSlow(1'000'000 * kMs));
}

}  // namespace
}  // namespace vem::stream
