// Connection churn: clients that come and go all the time must not crash vemd, leak its sessions,
// nor disturb a client that stays.
#include <atomic>
#include <csignal>
#include <thread>

#include <gtest/gtest.h>

#include "stream_e2e/raw_ws_client.h"
#include "stream_e2e/stream_e2e_fixture.h"

namespace vem::e2e {
namespace {

constexpr int kChurnThreads = 20;
constexpr auto kChurnFor = 8s;
constexpr double kRateTolerance = 0.15;  // of the nominal rate

// One churning thread until `stop`: even threads start and stop StreamClients (a clean close after
// the Hello), odd ones open raw connections, read a message and then alternately close cleanly or
// drop the TCP connection without a close frame. Counts the connections that got their Hello.
void churn(int thread, std::uint16_t port, const std::atomic<bool>& stop,
           std::atomic<int>& connections) {
  for (int round = 0; !stop.load(); ++round) {
    if (thread % 2 == 0) {
      client::StreamClientOptions options;
      options.url = "ws://127.0.0.1:" + std::to_string(port);
      options.connectTimeout = 20s;
      auto started = client::StreamClient::start(std::move(options));
      if (!started) continue;
      if ((*started)->waitForState(client::ConnectionState::Connected, 20s)) ++connections;
      (*started)->stop();
    } else {
      RawWsClient raw;
      if (raw.connect(port) != 0) continue;
      ++connections;
      (void)raw.readBytes(2s);
      if (round % 2 == 0) {
        raw.close(2s);
      } else {
        raw.drop();
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5 * (thread % 4)));
  }
}

// Catches sessions that crash, deadlock or leak when clients come and go (a use after free of a
// closed session, a fan-out iterating a list being changed, a session never destroyed): twenty
// threads connect and disconnect for 8 s while one client stays. vemd keeps its nominal rate for
// that client, with at most 5 % of the seqs missing; its Status counts 1 client again afterwards;
// and vemd exits 0 on SIGTERM. Built with VEM_SANITIZE, vemd's LeakSanitizer check at exit then
// proves no session leaked memory (a report fails the test).
TEST_F(StreamE2eTest, ConnectionChurnNeitherCrashesNorLeaksNorSlowsTheSteadyClient) {
  const auto port = startVemd({});
  ASSERT_TRUE(port);
  std::vector<LoggedClient> steady;
  steady.push_back(startClient(*port));
  ASSERT_TRUE(waitForSeq(steady, 0));

  std::atomic<bool> stop{false};
  std::atomic<int> connections{0};
  std::vector<std::thread> threads;
  const auto churnStart = std::chrono::steady_clock::now();
  const std::uint64_t firstSeq = steady[0].client->latestLightFrame()->frame.seq + 1;
  for (int t = 0; t < kChurnThreads; ++t) {
    threads.emplace_back(churn, t, *port, std::cref(stop), std::ref(connections));
  }
  std::this_thread::sleep_for(kChurnFor);
  const std::uint64_t lastSeq = steady[0].client->latestLightFrame()->frame.seq;
  stop = true;
  for (std::thread& thread : threads) thread.join();
  const auto churnEnd = std::chrono::steady_clock::now();

  EXPECT_FALSE(vemd_->waitForExit(0ms).has_value()) << "vemd died during the churn";
  EXPECT_GE(connections.load(), 2 * kChurnThreads) << "too little churn to mean anything";
  const std::vector<LoggedFrame> during = steady[0].log->framesBetween(firstSeq, lastSeq);
  ASSERT_GE(during.size(), 2U);
  EXPECT_LE(missingSeqs(during), mostMissing(lastSeq - firstSeq));
  EXPECT_NEAR(receivedRateHz(during), kNominalRateHz, kNominalRateHz * kRateTolerance);
  EXPECT_EQ(steady[0].client->stats().reconnects, 0U) << "the steady client lost its connection";
  EXPECT_LT(std::chrono::duration<double>(churnEnd - churnStart).count(), 60.0);

  // Every churned session ends: the daemon's Status counts the steady client alone again.
  bool alone = false;
  const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
  while (!alone && std::chrono::steady_clock::now() < deadline) {
    const auto status = steady[0].client->status();
    alone = status && status->clients == 1;
    if (!alone) std::this_thread::sleep_for(100ms);
  }
  EXPECT_TRUE(alone) << "vemd still counts "
                     << (steady[0].client->status() ? steady[0].client->status()->clients : 0)
                     << " clients after the churn";
  steady[0].client->stop();
  expectCleanExit(SIGTERM);
}

}  // namespace
}  // namespace vem::e2e
