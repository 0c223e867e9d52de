// LogBudget (log_budget.h): repeating events cost a bounded number of log lines.
#include "stream/log_budget.h"

#include <gtest/gtest.h>

namespace vem::stream {
namespace {

constexpr std::int64_t kS = 1'000'000'000;

TEST(LogBudget, AFloodIsLoggedUpToTheBurstThenOnlyCounted) {
  LogBudget budget(10 * kS, 5);
  int logged = 0;
  for (int i = 0; i < 100'000; ++i) logged += budget.admit(1000 + i) ? 1 : 0;
  EXPECT_EQ(logged, 5);
  EXPECT_EQ(budget.total(), 100'000u);
}

TEST(LogBudget, TheCountIsHandedOutOnceAfterItsWindowEnds) {
  LogBudget budget(10 * kS, 2);
  for (int i = 0; i < 10; ++i) (void)budget.admit(1 * kS);
  EXPECT_EQ(budget.takeSuppressed(5 * kS), 0u);  // the window is still open
  EXPECT_EQ(budget.takeSuppressed(12 * kS), 8u);
  EXPECT_EQ(budget.takeSuppressed(30 * kS), 0u);  // said once
}

TEST(LogBudget, ANewWindowLogsAgain) {
  LogBudget budget(10 * kS, 1);
  EXPECT_TRUE(budget.admit(0));
  EXPECT_FALSE(budget.admit(1 * kS));
  EXPECT_TRUE(budget.admit(11 * kS));
  EXPECT_EQ(budget.takeSuppressed(11 * kS), 1u);
}

TEST(LogBudget, QuietTimesSayNothing) {
  LogBudget budget(10 * kS, 3);
  EXPECT_TRUE(budget.admit(0));
  EXPECT_EQ(budget.takeSuppressed(100 * kS), 0u);
}

}  // namespace
}  // namespace vem::stream
