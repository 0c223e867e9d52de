#include "stream_e2e/stream_e2e_fixture.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <thread>

#include "recording/recording_reader.h"
#include "stream_e2e/small_camera.h"

namespace vem::e2e {

namespace fs = std::filesystem;

void StreamE2eTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  dir_ = fs::temp_directory_path() /
         ("vem_stream_e2e_" + std::to_string(::getpid()) + "_" + info->name());
  fs::create_directories(dir_);
}

void StreamE2eTest::TearDown() {
  if (vemd_ && HasFailure()) {
    std::cerr << "--- vemd's stderr ---\n" << vemd_->stderrText() << "---\n";
  }
  vemd_.reset();  // kills vemd if a failed test left it running
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
}

std::optional<std::uint16_t> StreamE2eTest::startVemd(const std::vector<std::string>& extraArgs,
                                                      const std::string& streamToml,
                                                      bool listenOnLoopback) {
  const fs::path camera = writeFile("camera.toml", smallCameraToml());
  const fs::path config =
      writeFile("vemd.toml", "version = 1\n[source]\ncamera = \"" + camera.string() +
                                 "\"\n[processing]\nmap_width = 256\nmap_height = 64\nlights = " +
                                 std::to_string(kLightCount) + "\n" + streamToml);
  std::vector<std::string> args{"--config",      config.string(),
                                "--source",      "synthetic:sky",
                                "--rate",        std::to_string(int(kNominalRateHz)),
                                "--stats-every", "0"};
  if (listenOnLoopback) args.insert(args.end(), {"--stream-listen", "127.0.0.1:0"});
  args.insert(args.end(), extraArgs.begin(), extraArgs.end());
  auto spawned = VemdProcess::spawn(VEMD_PATH, args);
  if (!spawned) {
    ADD_FAILURE() << spawned.error();
    return std::nullopt;
  }
  vemd_ = std::move(*spawned);
  const auto port = vemd_->waitForPort(kStartTimeout);
  if (!port) ADD_FAILURE() << "vemd did not log \"streaming on ws://...\" in time";
  return port;
}

fs::path StreamE2eTest::writeFile(const std::string& name, const std::string& text,
                                  fs::perms mode) {
  const fs::path path = dir_ / name;
  std::ofstream(path) << text;
  fs::permissions(path, mode);
  return path;
}

LoggedClient StreamE2eTest::startClient(std::uint16_t port, const std::string& token,
                                        client::Subscription subscription) {
  LoggedClient logged;
  client::StreamClientOptions options;
  options.url = "ws://127.0.0.1:" + std::to_string(port);
  options.token = token;
  options.subscription = subscription;
  options.connectTimeout = 20s;
  options.onLightFrame = [log = logged.log.get()](const auto& received) { log->record(received); };
  auto started = client::StreamClient::start(std::move(options));
  EXPECT_TRUE(started.has_value()) << (started ? "" : started.error());
  if (started) logged.client = std::move(*started);
  return logged;
}

void StreamE2eTest::expectCleanExit(int signal) {
  ASSERT_NE(vemd_, nullptr);
  if (signal != 0) vemd_->signal(signal);
  const auto status = vemd_->waitForExit(kExitTimeout);
  ASSERT_TRUE(status.has_value()) << "vemd did not exit in time";
  EXPECT_EQ(*status, 0) << "vemd's exit status";
  EXPECT_EQ(sanitizerReports(vemd_->stderrText()), "");
}

// The seqs of the intact frames of the recording at `path`, in file order.
std::vector<std::uint64_t> recordedSeqs(const fs::path& path) {
  std::vector<std::uint64_t> seqs;
  auto reader = recording::RecordingReader::open(path);
  if (!reader) {
    ADD_FAILURE() << "cannot open " << path;
    return seqs;
  }
  for (;;) {
    auto frame = reader->next();
    if (!frame || !*frame) break;
    seqs.push_back((*frame)->seq);
  }
  return seqs;
}

std::uint64_t mostMissing(std::uint64_t seqs) {
  return std::max<std::uint64_t>(1, std::uint64_t(std::ceil(kMostMissingShare * double(seqs))));
}

bool waitForSeq(const std::vector<LoggedClient>& clients, std::uint64_t seq) {
  const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
  for (const LoggedClient& logged : clients) {
    for (;;) {
      const auto now = std::chrono::steady_clock::now();
      if (now >= deadline) return false;
      const auto frame = logged.client->waitForLightFrame(
          seq == 0 ? std::nullopt : std::optional<std::uint64_t>(seq - 1),
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now));
      if (frame && frame->frame.seq >= seq) break;
      if (!frame) std::this_thread::sleep_for(5ms);  // Refused or Stopped: returns at once
    }
  }
  return true;
}

std::optional<std::uint64_t> newestCommonSeq(const std::vector<LoggedClient>& clients) {
  std::optional<std::uint64_t> common;
  for (const LoggedClient& logged : clients) {
    const auto newest = logged.client->latestLightFrame();
    if (!newest) return std::nullopt;
    common = std::min(common.value_or(newest->frame.seq), newest->frame.seq);
  }
  return common;
}

}  // namespace vem::e2e
