#include "client/client_state.h"

#include <utility>

#include <spdlog/spdlog.h>

namespace vem::client {
namespace {

std::int64_t unixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ClientState::ClientState(const StreamClientOptions& options)
    : options_(options), reception_(options.latencyWindow) {}

void ClientState::setState(ConnectionState next, std::string why) {
  {
    std::lock_guard lock(mutex_);
    if (stopped_) return;
    state_ = next;
    reason_ = why;
  }
  changed_.notify_all();
  logState(next, why);
  if (options_.onStateChange) options_.onStateChange(next, why);
}

// One line per change: a retry failing for the same reason again is not logged again.
void ClientState::logState(ConnectionState next, const std::string& why) {
  if (next == ConnectionState::Connected) {
    spdlog::info("stream {}: connected", options_.url);
    std::lock_guard lock(mutex_);
    lastLoggedReason_.clear();
    return;
  }
  if (next != ConnectionState::Waiting && next != ConnectionState::Refused) return;
  {
    std::lock_guard lock(mutex_);
    if (why == lastLoggedReason_) return;
    lastLoggedReason_ = why;
  }
  spdlog::log(next == ConnectionState::Refused ? spdlog::level::err : spdlog::level::warn,
              "stream {}: {}", options_.url, why);
}

void ClientState::keepHello(Hello hello) {
  std::lock_guard lock(mutex_);
  hello_ = std::move(hello);
}

void ClientState::countConnection() {
  std::lock_guard lock(mutex_);
  if (connections_++ > 0) ++counters_.reconnects;
}

void ClientState::countDecodeError() {
  std::lock_guard lock(mutex_);
  ++counters_.decodeErrors;
}

void ClientState::onLightFrame(LightFrame frame) {
  Received<LightFrame> received{std::move(frame), std::chrono::steady_clock::now(), unixNowNs()};
  {
    std::lock_guard lock(mutex_);
    reception_.onLightFrame(received.frame.seq, received.frame.publishUnixNs,
                            received.receivedUnixNs);
    latestLight_ = received;
  }
  changed_.notify_all();
  if (options_.onLightFrame) options_.onLightFrame(received);
}

void ClientState::onEnvironmentFrame(EnvironmentFrame frame) {
  Received<EnvironmentFrame> received{std::move(frame), std::chrono::steady_clock::now(),
                                      unixNowNs()};
  {
    std::lock_guard lock(mutex_);
    ++counters_.environmentFrames;
    latestEnvironment_ = received;
  }
  if (options_.onEnvironmentFrame) options_.onEnvironmentFrame(received);
}

void ClientState::onStatus(Status status) {
  std::lock_guard lock(mutex_);
  status_ = std::move(status);
}

bool ClientState::onControlReply(ControlReply reply) {
  std::promise<ControlResult> promise;
  {
    std::lock_guard lock(mutex_);
    const auto it = pendingControls_.find(reply.requestId);
    if (it == pendingControls_.end()) return false;  // not ours, or already failed
    promise = std::move(it->second);
    pendingControls_.erase(it);
  }
  promise.set_value(std::move(reply));
  return true;
}

std::optional<std::uint64_t> ClientState::addPendingControl(std::promise<ControlResult> promise,
                                                            const std::string& notLive,
                                                            bool needConnected) {
  {
    std::lock_guard lock(mutex_);
    if (!stopped_ && state_ != ConnectionState::Refused &&
        (!needConnected || state_ == ConnectionState::Connected)) {
      const std::uint64_t id = nextRequestId_++;
      pendingControls_.emplace(id, std::move(promise));
      return id;
    }
  }
  promise.set_value(std::unexpected(notLive));
  return std::nullopt;
}

void ClientState::failPendingControl(std::uint64_t requestId, const std::string& why) {
  std::promise<ControlResult> promise;
  {
    std::lock_guard lock(mutex_);
    const auto it = pendingControls_.find(requestId);
    if (it == pendingControls_.end()) return;
    promise = std::move(it->second);
    pendingControls_.erase(it);
  }
  promise.set_value(std::unexpected(why));
}

void ClientState::failPendingControls(const std::string& why) {
  std::map<std::uint64_t, std::promise<ControlResult>> failing;
  {
    std::lock_guard lock(mutex_);
    failing.swap(pendingControls_);
  }
  for (auto& [id, promise] : failing) promise.set_value(std::unexpected(why));
}

std::uint64_t ClientState::nextRequestId() {
  std::lock_guard lock(mutex_);
  return nextRequestId_++;
}

bool ClientState::markStopped() {
  std::lock_guard lock(mutex_);
  if (stopped_) return false;
  stopped_ = true;
  return true;
}

void ClientState::finishStopped() {
  {
    std::lock_guard lock(mutex_);
    state_ = ConnectionState::Stopped;
  }
  changed_.notify_all();
}

ConnectionState ClientState::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

std::string ClientState::stateReason() const {
  std::lock_guard lock(mutex_);
  return reason_;
}

std::optional<Hello> ClientState::hello() const {
  std::lock_guard lock(mutex_);
  return hello_;
}

std::optional<Status> ClientState::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

std::optional<Received<LightFrame>> ClientState::latestLightFrame() const {
  std::lock_guard lock(mutex_);
  return latestLight_;
}

std::optional<Received<EnvironmentFrame>> ClientState::latestEnvironmentFrame() const {
  std::lock_guard lock(mutex_);
  return latestEnvironment_;
}

ClientStats ClientState::stats() const {
  std::lock_guard lock(mutex_);
  ClientStats stats = counters_;
  stats.received = reception_.received();
  stats.skipped = reception_.skipped();
  stats.latency = reception_.latency();
  return stats;
}

std::optional<Received<LightFrame>> ClientState::waitForLightFrame(
    std::optional<std::uint64_t> afterSeq, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  const auto newer = [&] {
    return latestLight_ && (!afterSeq || latestLight_->frame.seq > *afterSeq);
  };
  const bool woken = changed_.wait_for(lock, timeout, [&] {
    return state_ == ConnectionState::Refused || state_ == ConnectionState::Stopped || newer();
  });
  if (!woken || !newer()) return std::nullopt;
  return latestLight_;
}

bool ClientState::waitForState(ConnectionState state, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return state_ == state; });
}

}  // namespace vem::client
