// util/contract.h: a broken contract aborts with one line naming the place and the condition, in
// every build type. This binary is built in the Release configuration like the rest (NDEBUG set),
// so the death test proves the check is not compiled out the way assert is.
#include "util/contract.h"

#include <cassert>

#include <gtest/gtest.h>

namespace vem::util {
namespace {

int checkedHalf(int even) {
  VEM_EXPECTS(even % 2 == 0);
  return even / 2;
}

TEST(Contract, KeptExpectationReturnsNormally) { EXPECT_EQ(checkedHalf(8), 4); }

TEST(Contract, ViolatedExpectationAbortsInReleaseToo) {
#ifdef NDEBUG
  // The Release configuration: here an assert is gone, the contract check is not.
  assert(checkedHalf(8) == 5);
#endif
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH((void)checkedHalf(7),
               "contract_test\\.cpp:[0-9]+: even % 2 == 0: contract violated");
}

TEST(Contract, UnreachableAbortsNamingWhy) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(VEM_UNREACHABLE("every case returns above"),
               "contract_test\\.cpp:[0-9]+: every case returns above: contract violated");
}

}  // namespace
}  // namespace vem::util
