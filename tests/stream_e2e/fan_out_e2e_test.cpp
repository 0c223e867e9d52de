// Fan-out: several render clients of one vemd see the same stream (docs/protocol.md: one message
// serialized once and shared by every connection).
#include <algorithm>
#include <csignal>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "stream_e2e/stream_e2e_fixture.h"

namespace vem::e2e {
namespace {

constexpr std::uint64_t kWindowFrames = 120;

// Catches a fan-out that loses, reorders or alters light frames for some clients (a per-client
// encoding, a shared buffer reused while still being sent, a frame published to only the first
// connection): three clients on loopback must hold the same seqs with the same lights (ids, dirs,
// rgb, bit for bit), in order, over a window of 120 consecutive seqs at the nominal rate, each
// missing at most 5 % of them; then vemd stops cleanly on SIGTERM. (--frames 480 only bounds the
// run: stopping at the window's end instead of the 480th frame saves 20 s of the test.)
TEST_F(StreamE2eTest, ThreeClientsReceiveTheSameLightFrames) {
  const auto port = startVemd({"--frames", "480"});
  ASSERT_TRUE(port);
  std::vector<LoggedClient> clients;
  for (int i = 0; i < 3; ++i) clients.push_back(startClient(*port));
  for (const LoggedClient& logged : clients) ASSERT_NE(logged.client, nullptr);
  ASSERT_TRUE(waitForSeq(clients, 0)) << "a client received no light frame";
  const std::uint64_t first = *newestCommonSeq(clients) + 2;
  const std::uint64_t last = first + kWindowFrames - 1;
  ASSERT_LT(last, 480U) << "the clients connected too late for a whole window";
  ASSERT_TRUE(waitForSeq(clients, last + 1)) << "the window's frames did not all arrive";

  // Every frame is keyed by seq; a loaded machine may starve one client for a frame or two (it
  // then skips them: newest only), so each client may miss a few (mostMissing) of the frames the
  // others got, and every frame two clients both got must be the same.
  std::map<std::uint64_t, LoggedFrame> everyFrame;  // the first client's version of each seq
  std::vector<std::map<std::uint64_t, LoggedFrame>> perClient(clients.size());
  for (std::size_t c = 0; c < clients.size(); ++c) {
    for (const LoggedFrame& frame : clients[c].log->framesBetween(first, last)) {
      ASSERT_TRUE(perClient[c].emplace(frame.seq, frame).second)
          << "client " << c << " received seq " << frame.seq << " twice";
      everyFrame.emplace(frame.seq, frame);
    }
  }
  ASSERT_GE(everyFrame.size(), 100U) << "too few frames in seq " << first << ".." << last;
  EXPECT_GT(everyFrame.begin()->second.lightCount, 0U);
  for (std::size_t c = 0; c < clients.size(); ++c) {
    EXPECT_LE(everyFrame.size() - perClient[c].size(), mostMissing(everyFrame.size()))
        << "client " << c << " missed frames the others received";
    for (const auto& [seq, frame] : perClient[c]) {
      EXPECT_EQ(frame.lightCount, everyFrame.at(seq).lightCount)
          << "client " << c << ", seq " << seq;
      EXPECT_EQ(frame.lightsDigest, everyFrame.at(seq).lightsDigest)
          << "client " << c << " got other lights in seq " << seq;
    }
    const std::vector<LoggedFrame> inOrder = clients[c].log->framesBetween(first, last);
    EXPECT_TRUE(std::ranges::is_sorted(inOrder, {}, &LoggedFrame::seq))
        << "client " << c << " received frames out of order";
  }
  expectCleanExit(SIGTERM);
  for (LoggedClient& logged : clients) logged.client->stop();
}

}  // namespace
}  // namespace vem::e2e
