// ClientLag: how far behind one streaming client reads, measured with WebSocket pings. A peer
// answers a ping with a pong once it has read everything sent before the ping (RFC 6455, 5.5.2
// and 5.5.3, frames are delivered in order), so a pong confirms that the client has read every
// message up to that ping. The server sends a probe ping after each message it writes and feeds
// the pongs back here. Browsers and Beast answer pings by themselves; nothing is asked of a client
// beyond the standard.
//
// - lagNs(now): the age of the oldest unconfirmed probe (0 when every probe is confirmed): how
//   long the client has been reading what was sent to it.
// - mayWrite(now): the pacing rule that keeps a slow reader's delay bounded. New messages go out
//   while no probe is unconfirmed or while the oldest unconfirmed probe is younger than the
//   client's smallest round trip so far plus `slackNs`. Otherwise the server holds; the client's
//   outbox keeps only the newest of each kind, so when the probe comes back the client gets the
//   newest frame, never a backlog (docs/protocol.md, "Flow control").
// - tooSlow(now): the lag has passed `maxLagNs`: the server tells the client so and closes it.
//
// Times are steady-clock nanoseconds passed in. Probe ids count up from 1. Pure; not thread-safe
// (each connection's lives on the server's io thread).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace vem::stream {

struct ClientLagOptions {
  std::int64_t slackNs = 100'000'000;     // on top of the smallest round trip
  std::int64_t maxLagNs = 5'000'000'000;  // beyond: too slow, closed
  std::size_t maxProbes = 64;             // unconfirmed probes at most (then mayWrite is false)
};

class ClientLag {
 public:
  explicit ClientLag(ClientLagOptions options = {}) : options_(options) {}

  // A new probe sent at `nowNs`; its id (the ping's payload), or empty when maxProbes wait.
  [[nodiscard]] std::optional<std::uint64_t> probeSent(std::int64_t nowNs);
  // A pong for probe `id` arrived: it and every earlier probe are confirmed. Unknown or already
  // confirmed ids change nothing.
  void pongReceived(std::uint64_t id, std::int64_t nowNs);

  [[nodiscard]] bool mayWrite(std::int64_t nowNs) const;
  [[nodiscard]] std::int64_t lagNs(std::int64_t nowNs) const;
  [[nodiscard]] bool tooSlow(std::int64_t nowNs) const { return lagNs(nowNs) > options_.maxLagNs; }

  [[nodiscard]] std::size_t unconfirmed() const { return probes_.size(); }
  [[nodiscard]] std::optional<std::int64_t> minRoundTripNs() const { return minRoundTripNs_; }
  [[nodiscard]] std::optional<std::int64_t> lastRoundTripNs() const { return lastRoundTripNs_; }
  [[nodiscard]] std::int64_t maxRoundTripNs() const { return maxRoundTripNs_; }

 private:
  struct Probe {
    std::uint64_t id = 0;
    std::int64_t sentNs = 0;
  };
  ClientLagOptions options_;
  std::deque<Probe> probes_;  // unconfirmed, oldest first
  std::uint64_t nextId_ = 1;
  std::optional<std::int64_t> minRoundTripNs_;
  std::optional<std::int64_t> lastRoundTripNs_;
  std::int64_t maxRoundTripNs_ = 0;
};

}  // namespace vem::stream
