// Disk full while recording: the recorder sink writes into a 256 KiB tmpfs until it is full. The
// recording must stop with one clear sentence, the file so far must stay readable, later frames
// must be harmless no-ops for the recorder, and the JSON-lines sink beside it (on another file
// system) must keep delivering every frame's lights.
//
// How the disk fills: a child process enters new user and mount namespaces (unshare(2), as
// `unshare -rm` does; no privileges needed where user namespaces are allowed) and mounts a 256 KiB
// tmpfs, so ENOSPC comes from a real file system. Where namespaces or mounting are refused (some
// containers), the child falls back to RLIMIT_FSIZE = 256 KiB with SIGXFSZ ignored, so write()
// fails part-way with EFBIG instead; the test prints which one it used. Everything runs in the
// child (the tmpfs and the limit stay there); the child copies the recording out and reports.
#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "sinks/sink_test_frames.h"
#include "vemd/sinks/sink_factory.h"

namespace vem::testing {
namespace {

constexpr int kFrames = 200;
constexpr const char* kDiskSize = "size=256k";
constexpr rlim_t kFileSizeLimit = 256 * 1024;

bool writeProcFile(const char* path, const std::string& text) {
  const int fd = ::open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::write(fd, text.data(), text.size()) == ssize_t(text.size());
  ::close(fd);
  return ok;
}

// A 256 KiB tmpfs at `mountPoint`, in namespaces of this (single-threaded, forked) process only.
bool mountSmallTmpfs(const fs::path& mountPoint) {
  const uid_t uid = ::geteuid();
  const gid_t gid = ::getegid();
  if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) == 0) {
    if (!writeProcFile("/proc/self/setgroups", "deny") ||
        !writeProcFile("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1") ||
        !writeProcFile("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1")) {
      return false;
    }
  } else if (::unshare(CLONE_NEWNS) != 0) {
    return false;
  }
  if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
  return ::mount("vem_sinks_test", mountPoint.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, kDiskSize) ==
         0;
}

// The child: feeds kFrames frames to a JSON-lines sink and a recorder on the small disk as vemd
// would (every sink, every frame), then reports as JSON in `dir`/report.json.
[[noreturn]] void runDiskFullChild(const fs::path& dir) {
  const fs::path disk = dir / "disk";
  std::string method = "tmpfs";
  if (!mountSmallTmpfs(disk)) {
    method = "RLIMIT_FSIZE";
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{kFileSizeLimit, kFileSizeLimit};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(3);
  }
  vemd::SinkConfig config;
  config.jsonl = dir / "lights.jsonl";
  config.record = disk / "run.vem";
  auto sinks = vemd::makeSinks(config, smallContext());
  if (!sinks || sinks->size() != 2) ::_exit(4);
  nlohmann::json report;
  report["method"] = method;
  report["failures"] = nlohmann::json::array();
  for (int i = 0; i < kFrames; ++i) {
    TestFrame frame(i);
    for (const auto& sink : *sinks) {
      if (auto done = sink->consume(frame.processed); !done) {
        report["failures"].push_back(
            {{"sink", sink->name()}, {"frame", i}, {"message", done.error().message}});
      }
    }
  }
  for (const auto& sink : *sinks) {
    if (auto closed = sink->close(); !closed)
      report["close_failures"].push_back(closed.error().message);
  }
  std::error_code error;
  fs::copy_file(disk / "run.vem", dir / "copy.vem", error);
  report["copied"] = !error;
  std::ofstream(dir / "report.json") << report.dump();
  ::_exit(0);
}

class DiskFullTest : public SinkFiles {};

TEST_F(DiskFullTest, RecordingStopsWithOneSentenceFileStaysReadableAndLightsKeepFlowing) {
  fs::create_directories(dir_ / "disk");
  std::cout.flush();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) runDiskFullChild(dir_);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "child status " << status;

  std::ifstream in(dir_ / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  const std::string method = report.at("method");
  std::cout << "[ disk full ] filled by " << method << "\n";
  RecordProperty("disk_full_method", method);

  // One failure, from the recorder only, once: later frames were harmless no-ops.
  ASSERT_EQ(report.at("failures").size(), 1U) << report.dump(2);
  const nlohmann::json& failure = report["failures"][0];
  EXPECT_EQ(failure.at("sink"), "recorder");
  const int failedAt = failure.at("frame");
  EXPECT_GT(failedAt, 0);
  EXPECT_LT(failedAt, kFrames) << "the disk never filled";
  const std::string message = failure.at("message");
  const std::string cause = method == "tmpfs" ? "No space left on device" : "File too large";
  EXPECT_EQ(message, "recorder: " + (dir_ / "disk" / "run.vem").string() + ": cannot write frame " +
                         std::to_string(kFirstSeq + std::uint64_t(failedAt)) + " (" + cause +
                         "); the " + std::to_string(failedAt) +
                         " frames before it stay readable; recording stopped, the file closed " +
                         (message.ends_with("with an index") ? "with an index"
                                                             : "without an index (`vemtool "
                                                               "recover` can add one)"));
  EXPECT_FALSE(report.contains("close_failures")) << report.dump(2);

  // The file so far: every frame before the failure, intact, bit for bit.
  ASSERT_TRUE(report.at("copied").get<bool>());
  auto reader = recording::RecordingReader::open(dir_ / "copy.vem");
  ASSERT_TRUE(reader) << reader.error().message;
  std::cout << "[ disk full ] " << failedAt << " frames recorded, "
            << (reader->hasIndex() ? "indexed" : "no index") << "\n";
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), std::size_t(failedAt));
  EXPECT_EQ(back.damage.damagedRecords, 0U);
  EXPECT_EQ(back.damage.truncatedTailBytes, 0U);
  for (int i = 0; i < failedAt; ++i) {
    const TestFrame frame(i);
    EXPECT_EQ(back.frames[std::size_t(i)].frame.codes, frame.captured.frame.codes) << i;
    ASSERT_TRUE(back.frames[std::size_t(i)].lights);
    EXPECT_TRUE(sameLights(*back.frames[std::size_t(i)].lights, frame.processed.lights)) << i;
  }

  // The other sink kept delivering lights for every frame.
  const std::vector<std::string> lines = readLines(dir_ / "lights.jsonl");
  ASSERT_EQ(lines.size(), std::size_t(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    EXPECT_EQ(nlohmann::json::parse(lines[std::size_t(i)]).at("seq").get<std::uint64_t>(),
              kFirstSeq + std::uint64_t(i));
  }
}

}  // namespace
}  // namespace vem::testing
