// QuietStdErr (daemon/util/quiet_std_err.h): OpenCV's own error lines kept off std::cerr for one
// call, and std::cerr given back afterwards.
#include "util/quiet_std_err.h"

#include <gtest/gtest.h>

namespace vem::util {
namespace {

TEST(QuietStdErr, SwallowsWhatIsPrintedInItsScopeAndRestoresStdErrAfter) {
  std::ostringstream seen;
  std::streambuf* const original = std::cerr.rdbuf(seen.rdbuf());
  {
    const QuietStdErr quiet;
    std::cerr << "imread_('x.png'): can't read header";
  }
  std::cerr << "ours";
  std::cerr.rdbuf(original);
  EXPECT_EQ(seen.str(), "ours");
}

}  // namespace
}  // namespace vem::util
