// replaceFileAtomically (daemon/util/atomic_file.h): each test names the bug it stops.
#include "util/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vem::util {
namespace {

namespace fs = std::filesystem;

std::span<const std::byte> bytesOf(const std::string& text) {
  return std::as_bytes(std::span(text));
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir)) out.push_back(entry.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vem_atomic_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(dir_, fs::perms::owner_all, ignored);
    fs::remove_all(dir_, ignored);
  }
  fs::path dir_;
};

TEST_F(AtomicFile, ReplacesTheContentsAndLeavesNoTemporaryFile) {
  const fs::path target = dir_ / "map.exr";
  ASSERT_TRUE(replaceFileAtomically(target, bytesOf("old")));
  ASSERT_TRUE(replaceFileAtomically(target, bytesOf("new contents")));
  EXPECT_EQ(contents(target), "new contents");
  EXPECT_EQ(names(dir_), std::vector<std::string>{"map.exr"});
}

TEST_F(AtomicFile, CrashBeforeRenameLeavesTheOldFileWhole) {
  const fs::path target = dir_ / "camera.toml";
  ASSERT_TRUE(replaceFileAtomically(target, bytesOf("old and whole")));
  // Step 1 only, as if the process died before the rename: the new bytes are in a hidden file
  // beside the target, complete, and the target is untouched.
  const auto temporary = writeTemporarySibling(target, bytesOf("new"));
  ASSERT_TRUE(temporary);
  EXPECT_EQ(contents(target), "old and whole");
  EXPECT_EQ(temporary->parent_path(), dir_);
  EXPECT_TRUE(temporary->filename().string().starts_with(".camera.toml.tmp-"));
  EXPECT_EQ(contents(*temporary), "new");
  ASSERT_TRUE(renameOver(*temporary, target));
  EXPECT_EQ(contents(target), "new");
}

TEST_F(AtomicFile, FailedRenameRemovesTheTemporaryFileAndKeepsTheOldOne) {
  const fs::path target = dir_ / "preview.png";
  fs::create_directories(target / "occupied");  // rename(2) cannot replace a non-empty folder
  const auto done = replaceFileAtomically(target, bytesOf("png"));
  ASSERT_FALSE(done);
  EXPECT_EQ(done.error().step, "cannot rename the temporary file over it");
  EXPECT_EQ(names(dir_), std::vector<std::string>{"preview.png"});
  EXPECT_TRUE(fs::is_directory(target / "occupied"));
}

TEST_F(AtomicFile, MissingFolderIsOneSentenceNamingTheFile) {
  const fs::path target = dir_ / "gone" / "lights.exr";
  const auto done = replaceFileAtomically(target, bytesOf("x"));
  ASSERT_FALSE(done);
  EXPECT_EQ(done.error().error, ENOENT);
  EXPECT_EQ(done.error().message,
            target.string() +
                ": cannot create a temporary file beside it (No such file or directory); any "
                "earlier file there is unchanged");
  EXPECT_EQ(done.error().reason(),
            "cannot create a temporary file beside it: No such file or directory");
}

TEST_F(AtomicFile, NewFileFollowsTheUmaskLikeAnyCreatedFile) {
  const mode_t old = ::umask(027);
  const auto done = replaceFileAtomically(dir_ / "a.txt", bytesOf("x"));
  ::umask(old);
  ASSERT_TRUE(done);
  struct stat info {};
  ASSERT_EQ(::stat((dir_ / "a.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640U);
}

TEST_F(AtomicFile, TargetInTheWorkingFolderNeedsNoFolderInItsPath) {
  const fs::path before = fs::current_path();
  fs::current_path(dir_);
  const auto done = replaceFileAtomically("plain.txt", bytesOf("here"));
  fs::current_path(before);
  ASSERT_TRUE(done) << done.error().message;
  EXPECT_EQ(contents(dir_ / "plain.txt"), "here");
}

}  // namespace
}  // namespace vem::util
