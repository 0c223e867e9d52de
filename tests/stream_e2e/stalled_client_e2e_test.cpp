// Back-pressure: a client that stops reading must slow neither vemd nor the other clients
// (docs/protocol.md, "Flow control: newest only").
#include <algorithm>
#include <cctype>
#include <iterator>
#include <string_view>
#include <thread>

#include <gtest/gtest.h>

#include "stream_e2e/raw_ws_client.h"
#include "stream_e2e/stream_e2e_fixture.h"

namespace vem::e2e {
namespace {

constexpr double kRateTolerance = 0.1;  // of the nominal rate

std::vector<LoggedFrame> receivedBetween(const LightFrameLog& log,
                                         std::chrono::steady_clock::time_point from,
                                         std::chrono::steady_clock::time_point to) {
  std::vector<LoggedFrame> out;
  for (const LoggedFrame& frame : log.frames()) {
    if (frame.receivedAt >= from && frame.receivedAt <= to) out.push_back(frame);
  }
  return out;
}

// The largest "N skipped" of vemd's "client ... gone: ...; M light frames sent, N skipped" lines.
std::uint64_t mostSkippedByAGoneClient(const std::string& stderrText) {
  constexpr std::string_view kSent = " light frames sent, ";
  std::uint64_t most = 0;
  for (std::size_t at = stderrText.find(kSent); at != std::string::npos;
       at = stderrText.find(kSent, at + 1)) {
    std::uint64_t skipped = 0;
    for (std::size_t i = at + kSent.size();
         i < stderrText.size() && std::isdigit(static_cast<unsigned char>(stderrText[i])); ++i) {
      skipped = skipped * 10 + std::uint64_t(stderrText[i] - '0');
    }
    most = std::max(most, skipped);
  }
  return most;
}

// Catches a server whose fan-out waits for its slowest client (a blocking write, one shared send
// queue, a publish that waits for the io thread): a client subscribed to light frames and cube maps
// with a 4 KiB receive buffer that never reads falls behind until vemd closes it
// (max_client_lag_ms = 4000, or send_timeout_ms = 4000 should a write stall first: the log line
// proves the back-pressure, and the skips counted for it). Meanwhile, a reading client keeps
// receiving the frames (at most 5 % of the seqs missing) at vemd's nominal rate, as it did before
// the stalled client came.
TEST_F(StreamE2eTest, StalledClientSlowsNeitherTheDaemonNorTheOtherClients) {
  const auto port = startVemd({"--frames", "1200"},
                              "[stream]\nsend_timeout_ms = 4000\nmax_client_lag_ms = 4000\n");
  ASSERT_TRUE(port);
  std::vector<LoggedClient> readers;
  readers.push_back(startClient(*port));
  ASSERT_TRUE(waitForSeq(readers, 0));

  // Before: two seconds with the reading client alone.
  const auto beforeStart = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(2s);
  const auto before =
      receivedBetween(*readers[0].log, beforeStart, std::chrono::steady_clock::now());

  RawWsClient stalled;
  RawConnectOptions smallBuffer;
  smallBuffer.receiveBufferBytes = 4096;
  ASSERT_EQ(stalled.connect(*port, smallBuffer), 0);
  stream::ClientMessage subscribe;
  subscribe.mutable_subscribe()->set_lights(true);
  subscribe.mutable_subscribe()->set_cubemap_rate_hz(10.0);
  subscribe.mutable_subscribe()->set_cubemap_face_px(64);
  ASSERT_TRUE(stalled.send(subscribe, 20s));
  const auto stallStart = std::chrono::steady_clock::now();
  // The stalled client is never read again; vemd closes it once it is 4 s behind.
  ASSERT_TRUE(vemd_->waitForStderr("light frames sent", kFrameTimeout))
      << "vemd never gave up on the stalled client: its writes did not back up";
  const auto stallEnd = std::chrono::steady_clock::now();
  EXPECT_GT(mostSkippedByAGoneClient(vemd_->stderrText()), 10U)
      << "the stalled client skipped (almost) nothing: no back-pressure happened";
  const auto during = receivedBetween(*readers[0].log, stallStart, stallEnd);

  ASSERT_GE(before.size(), std::size_t(kNominalRateHz));      // of 2 s
  ASSERT_GE(during.size(), std::size_t(2 * kNominalRateHz));  // of at least 4 s
  // A loaded machine may starve the reader for a frame or two; a server that waited for the stalled
  // client would make it miss hundreds.
  EXPECT_LE(missingSeqs(before), mostMissing(before.back().seq - before.front().seq));
  EXPECT_LE(missingSeqs(during), mostMissing(during.back().seq - during.front().seq))
      << "the reading client skipped frames while the other stalled";
  EXPECT_NEAR(seqRateHz(before), kNominalRateHz, kNominalRateHz * kRateTolerance);
  EXPECT_NEAR(seqRateHz(during), kNominalRateHz, kNominalRateHz * kRateTolerance)
      << "vemd's processed rate changed with a stalled client";
  EXPECT_NEAR(receivedRateHz(during), receivedRateHz(before), kNominalRateHz * kRateTolerance);
  const auto status = readers[0].client->status();
  ASSERT_TRUE(status.has_value());
  EXPECT_NEAR(status->frameRateHz, kNominalRateHz, kNominalRateHz * kRateTolerance);
  stalled.drop();
  expectCleanExit(SIGTERM);
  readers[0].client->stop();
}

}  // namespace
}  // namespace vem::e2e
