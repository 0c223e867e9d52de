// StreamE2eTest: the gtest fixture of the end-to-end stream tests: a scratch folder, the real vemd
// (VEMD_PATH) started on 127.0.0.1 port 0 with a synthetic scene, StreamClients logging what they
// receive, and the checks every test ends with (vemd exits 0, no sanitizer report).
//
// Timeouts are generous (an ASan build on two loaded cores starts and runs slower); they bound
// every wait, so a broken daemon fails a test instead of hanging it. They never assert speed:
// rates are checked against vemd's nominal --rate with a tolerance.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "client/stream_client.h"
#include "stream_e2e/light_frame_log.h"
#include "stream_e2e/vemd_process.h"

namespace vem::e2e {

using namespace std::chrono_literals;

// vemd's --rate. Under ASan (vemd and these tests built with VEM_SANITIZE) vemd holds about 50
// frames/s of the small camera on two loaded cores, so the sanitizer run asks for 15 to leave it
// headroom: the tests check that clients do not slow vemd, not how fast an ASan build is.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr double kNominalRateHz = 15.0;
#else
inline constexpr double kNominalRateHz = 60.0;
#endif
inline constexpr std::size_t kLightCount = 256;  // vemd's light count in these tests
// The share of a window's seqs a reading client may miss. A client starved of CPU for longer than
// a frame (two loaded cores, an ASan build) skips frames by design (newest only); the bugs these
// tests catch make it miss most of them, or all for seconds.
inline constexpr double kMostMissingShare = 0.05;
inline constexpr std::chrono::milliseconds kStartTimeout = 60s;  // vemd up, a client connected
inline constexpr std::chrono::milliseconds kExitTimeout = 60s;   // vemd gone after its end
inline constexpr std::chrono::milliseconds kFrameTimeout = 30s;  // the next frames

// A client and the log its callback fills (the log outlives the client: declared first).
struct LoggedClient {
  std::unique_ptr<LightFrameLog> log = std::make_unique<LightFrameLog>();
  std::unique_ptr<client::StreamClient> client;
};

class StreamE2eTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // vemd --config vemd.toml --source synthetic:sky --rate 60 --stream-listen 127.0.0.1:0
  // --stats-every 0 plus `extraArgs`; the port once it listens. Fails the test (empty) when vemd
  // does not come up. vemd.toml: the small camera (small_camera.h), 256 x 64 polar maps and
  // kLightCount lights, then `streamToml` (a [stream] section; with one that sets listen, pass
  // listenOnLoopback = false so that no flag overrides it).
  std::optional<std::uint16_t> startVemd(const std::vector<std::string>& extraArgs,
                                         const std::string& streamToml = "",
                                         bool listenOnLoopback = true);
  // A file in the scratch folder with `text`, mode `mode`.
  std::filesystem::path writeFile(
      const std::string& name, const std::string& text,
      std::filesystem::perms mode = std::filesystem::perms::owner_read |
                                    std::filesystem::perms::owner_write);
  // A StreamClient to ws://127.0.0.1:PORT logging its light frames (not yet connected).
  static LoggedClient startClient(std::uint16_t port, const std::string& token = "",
                                  client::Subscription subscription = {});
  // Ends vemd with `signal` (0: waits for its own end) and checks it exits 0 without a sanitizer
  // report (with VEM_SANITIZE, LeakSanitizer's check at exit is the proof of no leak).
  void expectCleanExit(int signal);

  std::filesystem::path dir_;
  std::unique_ptr<VemdProcess> vemd_;
};

// The seqs of the intact frames of the recording at `path`, in file order.
[[nodiscard]] std::vector<std::uint64_t> recordedSeqs(const std::filesystem::path& path);
// The seqs a client may miss out of `seqs` (kMostMissingShare of them, at least 1).
[[nodiscard]] std::uint64_t mostMissing(std::uint64_t seqs);
// Waits (bounded by kFrameTimeout) until every log holds a frame with seq >= `seq`.
[[nodiscard]] bool waitForSeq(const std::vector<LoggedClient>& clients, std::uint64_t seq);
// The newest seq every client has received (the smallest of their newest), or empty.
[[nodiscard]] std::optional<std::uint64_t> newestCommonSeq(
    const std::vector<LoggedClient>& clients);

}  // namespace vem::e2e
