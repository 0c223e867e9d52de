#include "stream/stream_server.h"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>

#include "stream/frame_encoding.h"
#include "stream/handshake_auth.h"
#include "stream/handshake_slots.h"
#include "stream/log_budget.h"
#include "stream/thread_niceness.h"
#include "stream/tls_server_context.h"
#include "stream/upgrade_request.h"
#include "stream/websocket_session.h"
#include "util/printable.h"

namespace vem::stream {

namespace ssl = boost::asio::ssl;
using tcp = boost::asio::ip::tcp;

namespace {

// Descriptors kept for everything but client sockets (recordings, cameras, logs, libraries).
constexpr std::uint64_t kReservedDescriptors = 256;
constexpr std::uint64_t kMaxDescriptors = 65536;
// Sockets beyond the clients and handshakes that the server can still answer (refusals).
constexpr std::size_t kMinRefusalSockets = 16;
// The log's budget: per kind of event, this many lines per window, then counts.
constexpr std::int64_t kLogWindowNs = 10'000'000'000;
constexpr std::uint32_t kLogBurst = 10;
constexpr std::chrono::milliseconds kAcceptRetry{100};

SharedBytes shared(ServerMessage message) {
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

SharedBytes replyBytes(const ControlReply& reply) {
  ServerMessage message;
  *message.mutable_reply() = reply;
  return shared(std::move(message));
}

std::string endpointText(const tcp::endpoint& endpoint) {
  const auto address = endpoint.address();
  return address.is_v6() ? fmt::format("[{}]:{}", address.to_string(), endpoint.port())
                         : fmt::format("{}:{}", address.to_string(), endpoint.port());
}

std::int64_t steadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The soft descriptor limit, raised to the hard one (at most kMaxDescriptors).
std::uint64_t raiseDescriptorLimit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return 1024;
  const rlim_t wanted = std::min<rlim_t>(limit.rlim_max, kMaxDescriptors);
  if (limit.rlim_cur < wanted) {
    rlimit raised = limit;
    raised.rlim_cur = wanted;
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
  }
  return std::uint64_t(limit.rlim_cur);
}

}  // namespace

class StreamServer::Impl final : public SessionHost, public UpgradeHost {
 public:
  explicit Impl(StreamServerOptions options)
      : options_(std::move(options)),
        handshakes_(options_.maxHandshakes, options_.maxHandshakesPerAddress) {}

  ~Impl() {
    ioc_.stop();
    if (thread_.joinable()) thread_.join();
    pending_.clear();
    connections_.clear();
    const ServerCounters c = counters();
    if (c.accepted + c.refusedFull + c.refusedBusyAddress + c.handshakesTimedOut > 0) {
      spdlog::info(
          "stream: served {} clients ({} closed by vemd, {} of them too slow); refused {} (400: "
          "{}, 401: {}, 503 full: {}, 503 busy address: {}); handshakes: {} timed out, {} failed, "
          "{} evicted; {} connections closed unanswered",
          c.accepted, c.closedByServer, c.closedTooSlow,
          c.refusedBadRequest + c.refusedUnauthorized + c.refusedFull + c.refusedBusyAddress,
          c.refusedBadRequest, c.refusedUnauthorized, c.refusedFull, c.refusedBusyAddress,
          c.handshakesTimedOut, c.handshakesFailed, c.handshakesEvicted, c.closedUnanswered);
    }
  }

  std::expected<void, std::string> listen() {
    if (!options_.tlsCertFile.empty() || !options_.tlsKeyFile.empty()) {
      tls_.emplace(ssl::context::tls_server);
      if (auto configured = configureServerTls(*tls_, options_.tlsCertFile, options_.tlsKeyFile);
          !configured) {
        return configured;
      }
    }
    const std::uint64_t descriptors = raiseDescriptorLimit();
    socketBudget_ = descriptors > kReservedDescriptors ? descriptors - kReservedDescriptors : 0;
    const std::uint64_t needed = options_.maxClients + options_.maxHandshakes + kMinRefusalSockets;
    if (socketBudget_ < needed) {
      return std::unexpected(fmt::format(
          "stream.max_clients: {} clients and {} handshakes need {} file descriptors, and vemd "
          "may open {} (raise LimitNOFILE or ulimit -n, or lower stream.max_clients or "
          "stream.max_handshakes)",
          options_.maxClients, options_.maxHandshakes, needed + kReservedDescriptors, descriptors));
    }
    beast::error_code ec;
    const auto address = boost::asio::ip::make_address(options_.address, ec);
    if (ec) {
      return std::unexpected(
          fmt::format("stream.listen: {} is not an IP address", util::printable(options_.address)));
    }
    const tcp::endpoint endpoint(address, options_.port);
    acceptor_.open(endpoint.protocol(), ec);
    if (!ec) acceptor_.set_option(boost::asio::socket_base::reuse_address(true), ec);
    if (!ec) acceptor_.bind(endpoint, ec);
    if (!ec) acceptor_.listen(boost::asio::socket_base::max_listen_connections, ec);
    if (ec) {
      return std::unexpected(fmt::format("stream.listen: cannot listen on {} ({})",
                                         endpointText(endpoint), ec.message()));
    }
    boundPort_ = acceptor_.local_endpoint().port();
    accept();
    scheduleLogReport();
    thread_ = std::thread([this] {
      (void)setThisThreadNice(kIoThreadNice);
      ioc_.run();
    });
    return {};
  }

  std::uint16_t boundPort() const { return boundPort_; }
  bool tls() const { return tls_.has_value(); }
  std::string url() const {
    const tcp::endpoint endpoint(boost::asio::ip::make_address(options_.address), boundPort_);
    return (tls() ? "wss://" : "ws://") + endpointText(endpoint);
  }

  // ---- SessionHost (io thread) ----
  const StreamServerOptions& options() const override { return options_; }

  void opened(Connection& connection) override {
    ++accepted_;
    if (connectedLog_.admit(steadyNowNs())) {
      spdlog::info("stream: client {} connected from {}{}", connection.id(), connection.peer(),
                   connection.controlAllowed() ? " (control allowed)" : "");
    }
    ServerMessage hello;
    *hello.mutable_hello() = options_.hello;
    hello.mutable_hello()->set_control_allowed(connection.controlAllowed());
    hello.mutable_hello()->set_max_client_message_bytes(std::uint32_t(kMaxClientMessageBytes));
    (void)connection.outbox.putReply(shared(std::move(hello)));
    updateDemand();  // and the count of open clients
  }

  void ended(Connection& connection, const ConnectionEnd& end) override {
    const ConnectionPacing pacing = connection.pacing();
    if (connection.open && goneLog_.admit(steadyNowNs())) {
      spdlog::info(
          "stream: client {} ({}) gone: {}; {} light frames sent, {} skipped, held {} times "
          "while behind, probe round trip {:.1f} to {:.1f} ms",
          connection.id(), connection.peer(), end.why, connection.outbox.sentLights(),
          connection.outbox.skippedLights(), pacing.holds, double(pacing.minRoundTripNs) * 1e-6,
          double(pacing.maxRoundTripNs) * 1e-6);
    }
    if (end.cause == ConnectionEndCause::ClosedByVemd) ++closedByServer_;
    skippedOfClosed_ += connection.outbox.skippedLights();
    connections_.erase(connection.id());  // may destroy `connection`: last use
    updateDemand();
  }

  void received(Connection& connection, ClientAction action) override {
    std::visit([&](auto& a) { act(connection, a); }, action);
  }

  void tooSlow(Connection& connection, std::int64_t lagMs) override {
    ++closedTooSlow_;
    if (goneLog_.admit(steadyNowNs())) {
      spdlog::warn("stream: client {} ({}) reads too slowly ({} ms behind); closing it",
                   connection.id(), connection.peer(), lagMs);
    }
  }

  // ---- UpgradeHost (io thread) ----
  std::chrono::milliseconds handshakeTimeout() const override { return options_.handshakeTimeout; }

  std::optional<Refusal> admit(const http::request<http::string_body>& request,
                               bool& controlAllowed) override {
    std::optional<std::string> token = bearerToken(request[http::field::authorization]);
    if (!token) token = queryToken(request.target());
    const HandshakeDecision decision =
        decideHandshake({options_.token, options_.tokenRequiredToConnect}, token);
    if (!decision.accept) {
      ++refusedUnauthorized_;
      return Refusal{401, decision.refusal};
    }
    if (connections_.size() >= options_.maxClients) {
      ++refusedFull_;
      return Refusal{503, fmt::format("vemd serves at most {} clients", options_.maxClients)};
    }
    controlAllowed = decision.controlAllowed;
    return std::nullopt;
  }

  void handshakeEnded(std::uint64_t id, HandshakeOutcome outcome, unsigned status,
                      const std::string& peer, const std::string& detail) override {
    handshakes_.release(id);
    pending_.erase(id);
    handshakesPending_ = handshakes_.pending();
    const std::int64_t nowNs = steadyNowNs();
    switch (outcome) {
      case HandshakeOutcome::Upgraded: return;
      case HandshakeOutcome::Answered:
        if (status == 400) ++refusedBadRequest_;
        if (refusedLog_.admit(nowNs)) spdlog::warn("stream: refused {} ({})", peer, detail);
        return;
      case HandshakeOutcome::TimedOut:
        ++handshakesTimedOut_;
        if (handshakeLog_.admit(nowNs)) {
          spdlog::warn("stream: the opening handshake of {} did not end within {} ms ({})", peer,
                       options_.handshakeTimeout.count(), detail);
        }
        return;
      case HandshakeOutcome::Failed:
        ++handshakesFailed_;
        if (handshakeLog_.admit(nowNs)) {
          spdlog::info("stream: the opening handshake of {} failed: {}", peer, detail);
        }
        return;
      case HandshakeOutcome::Evicted:
        ++handshakesEvicted_;
        if (handshakeLog_.admit(nowNs)) {
          spdlog::warn(
              "stream: closed the pending handshake of {} to make room: {} handshakes pending",
              peer, options_.maxHandshakes);
        }
        return;
    }
  }

  // ---- any thread ----
  void publishLights(SharedBytes message) {
    bool post = false;
    {
      std::lock_guard lock(mailMutex_);
      if (lights_) ++coalescedLights_;
      lights_ = std::move(message);
      ++lightsPublished_;
      post = !lightsPosted_;
      lightsPosted_ = true;
    }
    if (post) boost::asio::post(ioc_, [this] { fanOutLights(); });
  }

  void publishEnvironment(const CubeVariant& variant, SharedBytes message) {
    bool post = false;
    {
      std::lock_guard lock(mailMutex_);
      environments_[variant] = std::move(message);
      post = !environmentPosted_;
      environmentPosted_ = true;
    }
    if (post) boost::asio::post(ioc_, [this] { fanOutEnvironments(); });
  }

  void publishStatus(const Status& status) {
    bool post = false;
    {
      std::lock_guard lock(mailMutex_);
      status_ = status;
      post = !statusPosted_;
      statusPosted_ = true;
    }
    if (post) boost::asio::post(ioc_, [this] { fanOutStatus(); });
  }

  CubemapDemand demand() const {
    std::lock_guard lock(demandMutex_);
    return demand_;
  }

  std::vector<PendingControl> takeControls() {
    std::lock_guard lock(controlMutex_);
    return std::exchange(controls_, {});
  }

  void reply(std::uint64_t connectionId, const ControlReply& reply) {
    SharedBytes bytes = replyBytes(reply);
    boost::asio::post(ioc_, [this, connectionId, bytes = std::move(bytes)]() mutable {
      if (auto it = connections_.find(connectionId); it != connections_.end()) {
        deliverReply(*it->second, std::move(bytes));
      }
    });
  }

  ServerCounters counters() const {
    ServerCounters c;
    c.clients = openClients_.load();
    c.handshakes = handshakesPending_.load();
    c.accepted = accepted_.load();
    c.refusedBadRequest = refusedBadRequest_.load();
    c.refusedUnauthorized = refusedUnauthorized_.load();
    c.refusedFull = refusedFull_.load();
    c.refusedBusyAddress = refusedBusyAddress_.load();
    c.handshakesTimedOut = handshakesTimedOut_.load();
    c.handshakesFailed = handshakesFailed_.load();
    c.handshakesEvicted = handshakesEvicted_.load();
    c.closedUnanswered = closedUnanswered_.load();
    c.closedByServer = closedByServer_.load();
    c.closedTooSlow = closedTooSlow_.load();
    c.controlsReceived = controlsReceived_.load();
    c.lightsSkipped = skippedOfClosed_.load() + skippedOfOpen_.load();
    std::lock_guard lock(mailMutex_);
    c.lightsPublished = lightsPublished_;
    return c;
  }

 private:
  // ---- accepting (io thread) ----
  void accept() {
    acceptor_.async_accept(ioc_, [this](beast::error_code ec, tcp::socket socket) {
      if (ec == boost::asio::error::operation_aborted) return;
      if (ec) return acceptFailed(ec);
      onAccepted(std::move(socket));
      accept();
    });
  }

  // Out of descriptors or memory: accepting again at once would spin; wait a moment.
  void acceptFailed(beast::error_code ec) {
    ++closedUnanswered_;
    if (unansweredLog_.admit(steadyNowNs())) {
      spdlog::warn("stream: cannot accept a connection ({}); trying again in {} ms", ec.message(),
                   kAcceptRetry.count());
    }
    acceptRetry_.expires_after(kAcceptRetry);
    acceptRetry_.async_wait([this](beast::error_code waitError) {
      if (!waitError) accept();
    });
  }

  void onAccepted(tcp::socket socket) {
    beast::error_code ignored;
    const tcp::endpoint remote = socket.remote_endpoint(ignored);
    const std::string peer = endpointText(remote);
    if (liveSockets_.load() >= socketBudget_) {
      socket.close(ignored);
      ++closedUnanswered_;
      if (unansweredLog_.admit(steadyNowNs())) {
        spdlog::warn(
            "stream: closed the connection of {} unanswered: {} sockets are open, all "
            "that vemd's descriptor limit leaves for clients",
            peer, socketBudget_);
      }
      return;
    }
    // No Nagle: a frame's last partial segment would otherwise wait for the client's delayed
    // ACK (up to 40 ms on Linux); vem_stream_bench measured a 5-10 ms median without this.
    socket.set_option(tcp::no_delay(true), ignored);
    // A small kernel send buffer: what the server has handed to a slow client stays small.
    socket.set_option(boost::asio::socket_base::send_buffer_size(options_.sendBufferBytes),
                      ignored);
    const std::uint64_t id = ++nextSocketId_;
    const std::string address = remote.address().to_string();
    const HandshakeAdmission admission = handshakes_.admit(address, id);
    if (admission.evict) evict(*admission.evict);
    std::optional<Refusal> refusal;
    if (!admission.admitted) {
      ++refusedBusyAddress_;
      refusal = Refusal{503, fmt::format("vemd has {} connections in their opening handshake "
                                         "from your address, the most it takes; try again",
                                         options_.maxHandshakesPerAddress)};
    }
    if (tls_) {
      startHandshake(TlsStream(beast::tcp_stream(std::move(socket)), *tls_), id, peer,
                     std::move(refusal));
    } else {
      startHandshake(beast::tcp_stream(std::move(socket)), id, peer, std::move(refusal));
    }
    handshakesPending_ = handshakes_.pending();
  }

  template <class Stream>
  void startHandshake(Stream stream, std::uint64_t id, const std::string& peer,
                      std::optional<Refusal> refusal) {
    auto startSession = [this](Stream&& upgraded, http::request<http::string_body> request,
                               bool controlAllowed, std::string sessionPeer) {
      auto session = std::make_shared<WebSocketSession<Stream>>(
          std::move(upgraded), *this, ++nextId_, controlAllowed, std::move(sessionPeer));
      connections_.emplace(session->id(), session);
      session->run(std::move(request));
    };
    const bool admitted = !refusal;
    auto request = std::make_shared<UpgradeRequest<Stream, decltype(startSession)>>(
        std::move(stream), *this, std::move(startSession), id, socketTicket(), peer,
        std::move(refusal));
    if (admitted) pending_.emplace(id, request);
    request->run();
  }

  void evict(std::uint64_t id) {
    const auto it = pending_.find(id);
    if (it == pending_.end()) return;
    std::shared_ptr<PendingHandshake> handshake = it->second.lock();
    pending_.erase(it);
    if (handshake) handshake->evict();
  }

  // The count of sockets alive (in their handshake, refused, or open); tickets keep it.
  std::shared_ptr<void> socketTicket() {
    ++liveSockets_;
    return std::shared_ptr<void>(nullptr, [this](void*) { --liveSockets_; });
  }

  // Once per window: how many events of each kind were not logged one by one.
  void scheduleLogReport() {
    logReport_.expires_after(std::chrono::nanoseconds(kLogWindowNs));
    logReport_.async_wait([this](beast::error_code ec) {
      if (ec) return;
      reportSuppressed();
      scheduleLogReport();
    });
  }

  void reportSuppressed() {
    const std::int64_t nowNs = steadyNowNs();
    const std::uint64_t connected = connectedLog_.takeSuppressed(nowNs);
    const std::uint64_t gone = goneLog_.takeSuppressed(nowNs);
    const std::uint64_t refused = refusedLog_.takeSuppressed(nowNs);
    const std::uint64_t handshakes = handshakeLog_.takeSuppressed(nowNs);
    const std::uint64_t unanswered = unansweredLog_.takeSuppressed(nowNs);
    handshakesPending_ = handshakes_.pending();
    if (connected + gone + refused + handshakes + unanswered == 0) return;
    spdlog::warn(
        "stream: not logged one by one in the last {} s: {} clients connected, {} gone, {} "
        "refused, {} handshakes that failed, timed out or were evicted, {} connections closed "
        "unanswered; {} clients and {} handshakes now",
        kLogWindowNs / 1'000'000'000, connected, gone, refused, handshakes, unanswered,
        openClients_.load(), handshakes_.pending());
  }

  // ---- client actions (io thread) ----
  void act(Connection& connection, SubscribeAction& a) {
    connection.subscription = a.subscription;
    updateDemand();
    ControlReply reply;
    reply.set_request_id(a.requestId);
    reply.set_ok(true);
    deliverReply(connection, replyBytes(reply));
  }

  void act(Connection& connection, ControlAction& a) {
    {
      std::lock_guard lock(controlMutex_);
      if (controls_.size() < options_.maxPendingControls) {
        controls_.push_back({connection.id(), a.requestId, std::move(a.command)});
        ++controlsReceived_;
        return;
      }
    }
    ControlReply reply;
    reply.set_request_id(a.requestId);
    reply.set_ok(false);
    reply.set_message("too many control messages are waiting; try again");
    deliverReply(connection, replyBytes(reply));
  }

  void act(Connection& connection, ReplyAction& a) {
    deliverReply(connection, replyBytes(a.reply));
  }

  void act(Connection& connection, CloseAction& a) {
    connection.closeWith(a.code, std::move(a.reason));
  }

  void deliverReply(Connection& connection, SharedBytes bytes) {
    if (!connection.outbox.putReply(std::move(bytes))) {
      connection.closeWith(close_code::kPolicyViolation,
                           "too many requests unanswered: the client does not read its replies");
      return;
    }
    connection.wake();
  }

  // ---- fan-out (io thread) ----
  void fanOutLights() {
    SharedBytes message;
    std::uint64_t coalesced = 0;
    {
      std::lock_guard lock(mailMutex_);
      message = std::move(lights_);
      coalesced = std::exchange(coalescedLights_, 0);
      lightsPosted_ = false;
    }
    if (!message) return;
    std::uint64_t skippedOpen = 0;
    for (auto& [id, connection] : connections_) {
      if (!connection->open) continue;
      if (connection->subscription.lights) {
        connection->outbox.putLights(message, coalesced);
        connection->wake();
      }
      skippedOpen += connection->outbox.skippedLights();
    }
    skippedOfOpen_ = skippedOpen;
  }

  void fanOutEnvironments() {
    std::map<CubeVariant, SharedBytes> messages;
    {
      std::lock_guard lock(mailMutex_);
      messages = std::exchange(environments_, {});
      environmentPosted_ = false;
    }
    const std::int64_t nowNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                   std::chrono::steady_clock::now().time_since_epoch())
                                   .count();
    for (auto& [id, connection] : connections_) {
      const Subscription& s = connection->subscription;
      if (!connection->open || !s.wantsCubemaps()) continue;
      auto it = messages.find(s.cube);
      if (it == messages.end()) continue;
      if (!connection->environmentPacing.admit(nowNs, s.cubemapRateHz)) continue;
      connection->outbox.putEnvironment(it->second);
      connection->wake();
    }
  }

  void fanOutStatus() {
    Status status;
    {
      std::lock_guard lock(mailMutex_);
      status = status_;
      statusPosted_ = false;
    }
    status.set_clients(std::uint32_t(openClients_.load()));
    for (auto& [id, connection] : connections_) {
      if (!connection->open) continue;
      status.set_skipped_for_you(connection->outbox.skippedLights());
      ServerMessage message;
      *message.mutable_status() = status;
      connection->outbox.putStatus(shared(std::move(message)));
      connection->wake();
    }
  }

  void updateDemand() {
    std::vector<Subscription> subscriptions;
    std::size_t open = 0;
    for (auto& [id, connection] : connections_) {
      if (!connection->open) continue;
      ++open;
      subscriptions.push_back(connection->subscription);
    }
    openClients_ = open;
    CubemapDemand demand = vem::stream::cubemapDemand(subscriptions);
    std::lock_guard lock(demandMutex_);
    demand_ = std::move(demand);
  }

  StreamServerOptions options_;
  std::optional<ssl::context> tls_;  // declared before ioc_: outlives the sessions' TLS streams
  std::atomic<std::size_t> liveSockets_{0};
  std::uint64_t socketBudget_ = 0;
  HandshakeSlots handshakes_;                                         // io thread
  std::map<std::uint64_t, std::weak_ptr<PendingHandshake>> pending_;  // io thread
  std::map<std::uint64_t, std::shared_ptr<Connection>> connections_;  // io thread
  LogBudget connectedLog_{kLogWindowNs, kLogBurst};                   // io thread, all five
  LogBudget goneLog_{kLogWindowNs, kLogBurst};
  LogBudget refusedLog_{kLogWindowNs, kLogBurst};
  LogBudget handshakeLog_{kLogWindowNs, kLogBurst};
  LogBudget unansweredLog_{kLogWindowNs, kLogBurst};
  boost::asio::io_context ioc_{1};
  tcp::acceptor acceptor_{ioc_};
  boost::asio::steady_timer acceptRetry_{ioc_};
  boost::asio::steady_timer logReport_{ioc_};
  std::thread thread_;
  std::uint16_t boundPort_ = 0;
  std::uint64_t nextId_ = 0;
  std::uint64_t nextSocketId_ = 0;

  mutable std::mutex mailMutex_;
  SharedBytes lights_;
  std::uint64_t coalescedLights_ = 0;
  std::uint64_t lightsPublished_ = 0;
  bool lightsPosted_ = false;
  std::map<CubeVariant, SharedBytes> environments_;
  bool environmentPosted_ = false;
  Status status_;
  bool statusPosted_ = false;

  mutable std::mutex demandMutex_;
  CubemapDemand demand_;
  std::mutex controlMutex_;
  std::vector<PendingControl> controls_;

  std::atomic<std::size_t> openClients_{0};
  std::atomic<std::size_t> handshakesPending_{0};
  std::atomic<std::uint64_t> accepted_{0};
  std::atomic<std::uint64_t> refusedBadRequest_{0};
  std::atomic<std::uint64_t> refusedUnauthorized_{0};
  std::atomic<std::uint64_t> refusedFull_{0};
  std::atomic<std::uint64_t> refusedBusyAddress_{0};
  std::atomic<std::uint64_t> handshakesTimedOut_{0};
  std::atomic<std::uint64_t> handshakesFailed_{0};
  std::atomic<std::uint64_t> handshakesEvicted_{0};
  std::atomic<std::uint64_t> closedUnanswered_{0};
  std::atomic<std::uint64_t> closedByServer_{0};
  std::atomic<std::uint64_t> closedTooSlow_{0};
  std::atomic<std::uint64_t> controlsReceived_{0};
  std::atomic<std::uint64_t> skippedOfClosed_{0};
  std::atomic<std::uint64_t> skippedOfOpen_{0};
};

std::expected<std::unique_ptr<StreamServer>, std::string> StreamServer::start(
    StreamServerOptions options) {
  auto impl = std::make_unique<Impl>(std::move(options));
  if (auto listening = impl->listen(); !listening) return std::unexpected(listening.error());
  return std::unique_ptr<StreamServer>(new StreamServer(std::move(impl)));
}

StreamServer::StreamServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
StreamServer::~StreamServer() = default;

std::uint16_t StreamServer::boundPort() const { return impl_->boundPort(); }
bool StreamServer::tls() const { return impl_->tls(); }
std::string StreamServer::url() const { return impl_->url(); }
void StreamServer::publishLights(SharedBytes message) { impl_->publishLights(std::move(message)); }
void StreamServer::publishEnvironment(const CubeVariant& variant, SharedBytes message) {
  impl_->publishEnvironment(variant, std::move(message));
}
void StreamServer::publishStatus(const Status& status) { impl_->publishStatus(status); }
CubemapDemand StreamServer::cubemapDemand() const { return impl_->demand(); }
std::vector<PendingControl> StreamServer::takeControls() { return impl_->takeControls(); }
void StreamServer::reply(std::uint64_t connection, const ControlReply& reply) {
  impl_->reply(connection, reply);
}
ServerCounters StreamServer::counters() const { return impl_->counters(); }

}  // namespace vem::stream
