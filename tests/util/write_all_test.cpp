// writeAll / writeAllAt (daemon/util/write_all.h): each test names the write bug it stops. The loop
// is driven by a fake write(2) where a real file cannot be made to misbehave on cue.
#include "util/write_all.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vem::util {
namespace {

std::span<const std::byte> bytesOf(const std::string& text) {
  return std::as_bytes(std::span(text));
}

// A write(2) that takes at most `chunk` bytes per call and follows a script of errors first.
struct FakeWrite {
  std::string written;
  std::size_t chunk = 3;
  std::vector<int> errorsFirst;  // errno values returned (as -1) by the first calls; 0: write 0
  std::size_t calls = 0;

  ssize_t operator()(std::span<const std::byte> rest, std::size_t) {
    if (calls < errorsFirst.size()) {
      const int error = errorsFirst[calls++];
      if (error == 0) return 0;
      errno = error;
      return -1;
    }
    ++calls;
    const std::size_t n = std::min(chunk, rest.size());
    written.append(reinterpret_cast<const char*>(rest.data()), n);
    return ssize_t(n);
  }
};

TEST(WriteAll, ShortWriteIsContinuedNotTruncated) {
  FakeWrite fake;
  const std::string text = "twenty-six letters, a to z";
  ASSERT_TRUE(writeAllWith(fake, bytesOf(text)));
  EXPECT_EQ(fake.written, text);
  EXPECT_EQ(fake.calls, (text.size() + 2) / 3);
}

TEST(WriteAll, EintrIsRetried) {
  FakeWrite fake;
  fake.errorsFirst = {EINTR, EINTR};
  ASSERT_TRUE(writeAllWith(fake, bytesOf("abcdef")));
  EXPECT_EQ(fake.written, "abcdef");
}

TEST(WriteAll, RealErrorStopsAndSaysHowMuchReachedTheFile) {
  FakeWrite fake;
  fake.chunk = 4;
  int calls = 0;
  auto failsThird = [&](std::span<const std::byte> rest, std::size_t done) -> ssize_t {
    if (++calls == 3) {
      errno = ENOSPC;
      return -1;
    }
    return fake(rest, done);
  };
  const auto done = writeAllWith(failsThird, bytesOf("0123456789abcdef"));
  ASSERT_FALSE(done);
  EXPECT_EQ(done.error().error, ENOSPC);
  EXPECT_EQ(done.error().written, 8U);
}

TEST(WriteAll, AWriteOfNothingIsAnErrorNotAnEndlessLoop) {
  FakeWrite fake;
  fake.errorsFirst = {0};
  const auto done = writeAllWith(fake, bytesOf("abc"));
  ASSERT_FALSE(done);
  EXPECT_EQ(done.error().error, EIO);
  EXPECT_EQ(done.error().written, 0U);
}

TEST(WriteAll, FullDiskIsReportedWithItsErrno) {
  const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
  if (fd < 0) GTEST_SKIP() << "no /dev/full";
  const auto done = writeAll(fd, bytesOf("x"));
  ::close(fd);
  ASSERT_FALSE(done);
  EXPECT_EQ(done.error().error, ENOSPC);
}

TEST(WriteAll, WriteAllAtContinuesAtTheRightOffsetAndLeavesTheFileOffsetAlone) {
  char name[] = "/tmp/vem_write_all_XXXXXX";
  const int fd = ::mkstemp(name);
  ASSERT_GE(fd, 0);
  ::unlink(name);
  ASSERT_TRUE(writeAll(fd, bytesOf("head")));
  ASSERT_TRUE(writeAllAt(fd, bytesOf("-tail"), 4));
  EXPECT_EQ(::lseek(fd, 0, SEEK_CUR), 4);
  char back[16] = {};
  EXPECT_EQ(::pread(fd, back, sizeof back, 0), 9);
  EXPECT_STREQ(back, "head-tail");
  ::close(fd);
}

}  // namespace
}  // namespace vem::util
