// Backoff (daemon/util/backoff.h): the delays between reconnect attempts of the client and of
// vemd's capture thread.
#include "util/backoff.h"

#include <vector>

#include <gtest/gtest.h>

namespace vem::util {
namespace {

using std::chrono::milliseconds;

TEST(Backoff, DoublesFromTheInitialDelayUpToTheMaximumAndResets) {
  Backoff backoff(milliseconds(100), milliseconds(5000));
  std::vector<long> delays;
  for (int i = 0; i < 8; ++i) delays.push_back(long(backoff.next().count()));
  EXPECT_EQ(delays, (std::vector<long>{100, 200, 400, 800, 1600, 3200, 5000, 5000}));
  backoff.reset();
  EXPECT_EQ(backoff.next(), milliseconds(100));
}

TEST(Backoff, LongOutageStaysAtTheMaximumInsteadOfOverflowing) {
  Backoff backoff(milliseconds(1), milliseconds(5000));
  milliseconds last{0};
  for (int i = 0; i < 200; ++i) last = backoff.next();
  EXPECT_EQ(last, milliseconds(5000));
}

TEST(Backoff, MaximumBelowTheInitialDelayNeverWaitsLessThanTheInitial) {
  Backoff backoff(milliseconds(300), milliseconds(100));
  EXPECT_EQ(backoff.next(), milliseconds(300));
  EXPECT_EQ(backoff.next(), milliseconds(300));
}

}  // namespace
}  // namespace vem::util
