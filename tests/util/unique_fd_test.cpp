// UniqueFd (daemon/util/unique_fd.h): each test names the fd bug it stops.
#include "util/unique_fd.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include <gtest/gtest.h>

namespace vem::util {
namespace {

bool isOpen(int fd) { return ::fcntl(fd, F_GETFD) != -1; }

int openDevNull() { return ::open("/dev/null", O_RDONLY | O_CLOEXEC); }

TEST(UniqueFd, DestructorClosesTheFdSoNoneLeaks) {
  int raw = -1;
  {
    const UniqueFd fd(openDevNull());
    raw = fd.get();
    ASSERT_TRUE(isOpen(raw));
  }
  EXPECT_FALSE(isOpen(raw));
}

TEST(UniqueFd, MoveLeavesTheSourceEmptySoTheFdClosesOnce) {
  UniqueFd source(openDevNull());
  const int raw = source.get();
  {
    UniqueFd target(std::move(source));
    EXPECT_FALSE(source.valid());  // NOLINT(bugprone-use-after-move): that is the point
    EXPECT_EQ(target.get(), raw);
    UniqueFd assigned;
    assigned = std::move(target);
    EXPECT_FALSE(target.valid());  // NOLINT(bugprone-use-after-move)
    EXPECT_EQ(assigned.get(), raw);
  }
  EXPECT_FALSE(isOpen(raw));
  // A second close of `raw` would hit whatever fd the next open() got: the emptied source must
  // not close again.
  const UniqueFd next(openDevNull());
  ASSERT_EQ(next.get(), raw);
  source.reset();
  EXPECT_TRUE(isOpen(raw));
}

TEST(UniqueFd, MoveAssignmentClosesTheFdItHeldBefore) {
  UniqueFd first(openDevNull());
  const int old = first.get();
  UniqueFd second(openDevNull());
  first = std::move(second);
  EXPECT_FALSE(isOpen(old));
  EXPECT_TRUE(first.valid());
}

TEST(UniqueFd, SelfMoveAssignmentKeepsTheFdOpen) {
  UniqueFd fd(openDevNull());
  const int raw = fd.get();
  UniqueFd& alias = fd;
  fd = std::move(alias);
  EXPECT_EQ(fd.get(), raw);
  EXPECT_TRUE(isOpen(raw));
}

TEST(UniqueFd, CloseReportsTheErrorOfCloseAndEmptiesTheHolder) {
  UniqueFd fd(openDevNull());
  EXPECT_TRUE(fd.close());
  EXPECT_FALSE(fd.valid());
  EXPECT_TRUE(fd.close());  // nothing held: nothing to report
  UniqueFd stale(1 << 20);  // no such fd: close(2) says EBADF
  EXPECT_FALSE(stale.close());
  EXPECT_EQ(errno, EBADF);
  EXPECT_FALSE(stale.valid());
}

}  // namespace
}  // namespace vem::util
