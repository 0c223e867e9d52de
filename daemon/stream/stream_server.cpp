#include "stream/stream_server.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "stream/frame_encoding.h"
#include "stream/handshake_auth.h"
#include "stream/websocket_session.h"

namespace vem::stream {

namespace ssl = boost::asio::ssl;
using tcp = boost::asio::ip::tcp;
using TlsStream = beast::ssl_stream<beast::tcp_stream>;

namespace {

constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
// TCP connections beyond the client cap that may still be in their handshake (they get 503).
constexpr std::size_t kHandshakeSlack = 16;

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

}  // namespace

class StreamServer::Impl final : public SessionHost {
 public:
  explicit Impl(StreamServerOptions options) : options_(std::move(options)) {}

  ~Impl() {
    ioc_.stop();
    if (thread_.joinable()) thread_.join();
    connections_.clear();
  }

  std::expected<void, std::string> listen() {
    if (!options_.tlsCertFile.empty() || !options_.tlsKeyFile.empty()) {
      if (auto loaded = loadTls(); !loaded) return loaded;
    }
    beast::error_code ec;
    const auto address = boost::asio::ip::make_address(options_.address, ec);
    if (ec) {
      return std::unexpected(
          fmt::format("stream.listen: {} is not an IP address", options_.address));
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
    thread_ = std::thread([this] { ioc_.run(); });
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
    spdlog::info("stream: client {} connected from {}{}", connection.id(), connection.peer(),
                 connection.controlAllowed() ? " (control allowed)" : "");
    ServerMessage hello;
    *hello.mutable_hello() = options_.hello;
    hello.mutable_hello()->set_control_allowed(connection.controlAllowed());
    hello.mutable_hello()->set_max_client_message_bytes(std::uint32_t(kMaxClientMessageBytes));
    (void)connection.outbox.putReply(shared(std::move(hello)));
    updateDemand();  // and the count of open clients
  }

  void ended(Connection& connection, const std::string& why) override {
    if (connection.open) {
      spdlog::info("stream: client {} ({}) gone: {}; {} light frames sent, {} skipped",
                   connection.id(), connection.peer(), why, connection.outbox.sentLights(),
                   connection.outbox.skippedLights());
    }
    if (why.starts_with("closed by vemd") || why.starts_with("a send did not")) ++closedByServer_;
    skippedOfClosed_ += connection.outbox.skippedLights();
    connections_.erase(connection.id());  // may destroy `connection`: last use
    updateDemand();
  }

  void received(Connection& connection, ClientAction action) override {
    std::visit([&](auto& a) { act(connection, a); }, action);
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
    c.accepted = accepted_.load();
    c.refusedUnauthorized = refusedUnauthorized_.load();
    c.refusedFull = refusedFull_.load();
    c.closedByServer = closedByServer_.load();
    c.controlsReceived = controlsReceived_.load();
    c.lightsSkipped = skippedOfClosed_.load() + skippedOfOpen_.load();
    std::lock_guard lock(mailMutex_);
    c.lightsPublished = lightsPublished_;
    return c;
  }

  // ---- the handshake (io thread) ----
  [[nodiscard]] std::optional<std::uint16_t> admit(const http::request<http::string_body>& request,
                                                   bool& controlAllowed, std::string& body) {
    std::optional<std::string> token = bearerToken(request[http::field::authorization]);
    if (!token) token = queryToken(request.target());
    const HandshakeDecision decision =
        decideHandshake({options_.token, options_.tokenRequiredToConnect}, token);
    if (!decision.accept) {
      ++refusedUnauthorized_;
      body = decision.refusal;
      return 401;
    }
    if (connections_.size() >= options_.maxClients) {
      ++refusedFull_;
      body = fmt::format("vemd serves at most {} clients", options_.maxClients);
      return 503;
    }
    controlAllowed = decision.controlAllowed;
    return std::nullopt;
  }

  template <class Stream>
  void startSession(Stream&& stream, http::request<http::string_body> request, bool controlAllowed,
                    std::string peer) {
    auto session = std::make_shared<WebSocketSession<std::decay_t<Stream>>>(
        std::forward<Stream>(stream), *this, ++nextId_, controlAllowed, std::move(peer));
    connections_.emplace(session->id(), session);
    session->run(std::move(request));
  }

  // The count of TCP connections alive (in their handshake or open); tickets keep it.
  std::shared_ptr<void> connectionTicket() {
    ++tcpConnections_;
    return std::shared_ptr<void>(nullptr, [this](void*) { --tcpConnections_; });
  }

  ssl::context* tlsContext() { return tls_ ? &*tls_ : nullptr; }

 private:
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
    const auto now = std::chrono::steady_clock::now();
    for (auto& [id, connection] : connections_) {
      const Subscription& s = connection->subscription;
      if (!connection->open || !s.wantsCubemaps()) continue;
      auto it = messages.find(s.cube);
      if (it == messages.end()) continue;
      // 10 % early is fine: the processing thread builds at the fastest subscriber's pace.
      const auto period = std::chrono::duration<double>(0.9 / s.cubemapRateHz);
      if (now - connection->lastEnvironment < period) continue;
      connection->lastEnvironment = now;
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

  std::expected<void, std::string> loadTls() {
    if (options_.tlsCertFile.empty() || options_.tlsKeyFile.empty()) {
      return std::unexpected(std::string(
          "stream.tls_cert and stream.tls_key: give both (PEM files) for TLS, or neither"));
    }
    tls_.emplace(ssl::context::tls_server);
    tls_->set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                      ssl::context::no_sslv3 | ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1);
    beast::error_code ec;
    tls_->use_certificate_chain_file(options_.tlsCertFile, ec);
    if (ec) {
      return std::unexpected(fmt::format("stream.tls_cert: {}: not a usable PEM certificate ({})",
                                         options_.tlsCertFile, ec.message()));
    }
    tls_->use_private_key_file(options_.tlsKeyFile, ssl::context::pem, ec);
    if (ec) {
      return std::unexpected(fmt::format("stream.tls_key: {}: not a usable PEM private key ({})",
                                         options_.tlsKeyFile, ec.message()));
    }
    return {};
  }

  void accept();

  StreamServerOptions options_;
  std::optional<ssl::context> tls_;  // declared before ioc_: outlives the sessions' TLS streams
  std::atomic<std::size_t> tcpConnections_{0};
  std::map<std::uint64_t, std::shared_ptr<Connection>> connections_;  // io thread
  boost::asio::io_context ioc_{1};
  tcp::acceptor acceptor_{ioc_};
  std::thread thread_;
  std::uint16_t boundPort_ = 0;
  std::uint64_t nextId_ = 0;

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
  std::atomic<std::uint64_t> accepted_{0};
  std::atomic<std::uint64_t> refusedUnauthorized_{0};
  std::atomic<std::uint64_t> refusedFull_{0};
  std::atomic<std::uint64_t> closedByServer_{0};
  std::atomic<std::uint64_t> controlsReceived_{0};
  std::atomic<std::uint64_t> skippedOfClosed_{0};
  std::atomic<std::uint64_t> skippedOfOpen_{0};
};

namespace {

// One TCP connection until its upgrade request is read and decided: TLS handshake (when TLS is
// on), the HTTP request, then a WebSocketSession, or a 400/401/503 response and close.
template <class Stream>
class UpgradeRequest final : public std::enable_shared_from_this<UpgradeRequest<Stream>> {
 public:
  UpgradeRequest(Stream stream, StreamServer::Impl& server, std::shared_ptr<void> ticket,
                 std::string peer)
      : stream_(std::move(stream)),
        server_(server),
        ticket_(std::move(ticket)),
        peer_(std::move(peer)) {}

  void run() {
    beast::get_lowest_layer(stream_).expires_after(server_.options().handshakeTimeout);
    if constexpr (std::is_same_v<Stream, TlsStream>) {
      stream_.async_handshake(ssl::stream_base::server,
                              [self = this->shared_from_this()](beast::error_code ec) {
                                if (ec) {
                                  spdlog::debug("stream: TLS handshake with {} failed: {}",
                                                self->peer_, ec.message());
                                  return;
                                }
                                self->read();
                              });
    } else {
      read();
    }
  }

 private:
  void read() {
    parser_.header_limit(kMaxHeaderBytes);
    parser_.body_limit(kMaxHeaderBytes);
    http::async_read(stream_, buffer_, parser_,
                     [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
                       self->onRead(ec);
                     });
  }

  void onRead(beast::error_code ec) {
    if (ec) return;  // a port scan, a timeout: nothing to answer
    http::request<http::string_body> request = parser_.release();
    if (!websocket::is_upgrade(request)) {
      return respond(http::status::bad_request,
                     "this is vemd's WebSocket endpoint (proto/vem_stream.proto); connect with a "
                     "WebSocket client");
    }
    bool controlAllowed = false;
    std::string body;
    if (auto status = server_.admit(request, controlAllowed, body)) {
      spdlog::warn("stream: refused {} ({}): {}", peer_, *status, body);
      return respond(http::status(*status), body);
    }
    server_.startSession(std::move(stream_), std::move(request), controlAllowed,
                         std::move(peer_));
  }

  void respond(http::status status, const std::string& body) {
    response_.result(status);
    response_.version(11);
    response_.set(http::field::server, "vemd");
    response_.set(http::field::content_type, "text/plain");
    if (status == http::status::unauthorized) {
      response_.set(http::field::www_authenticate, "Bearer realm=\"vemd\"");
    }
    response_.keep_alive(false);
    response_.body() = body + "\n";
    response_.prepare_payload();
    http::async_write(stream_, response_,
                      [self = this->shared_from_this()](beast::error_code, std::size_t) {
                        beast::error_code ignored;
                        beast::get_lowest_layer(self->stream_).socket().shutdown(
                            tcp::socket::shutdown_both, ignored);
                        beast::get_lowest_layer(self->stream_).close();
                      });
  }

  Stream stream_;
  StreamServer::Impl& server_;
  std::shared_ptr<void> ticket_;
  std::string peer_;
  beast::flat_buffer buffer_;
  http::request_parser<http::string_body> parser_;
  http::response<http::string_body> response_;
};

}  // namespace

void StreamServer::Impl::accept() {
  acceptor_.async_accept(ioc_, [this](beast::error_code ec, tcp::socket socket) {
    if (ec == boost::asio::error::operation_aborted) return;
    if (!ec) {
      beast::error_code ignored;
      const std::string peer = endpointText(socket.remote_endpoint(ignored));
      // No Nagle: a frame's last partial segment would otherwise wait for the client's delayed
      // ACK (up to 40 ms on Linux); vem_stream_bench measured a 5-10 ms median without this.
      socket.set_option(tcp::no_delay(true), ignored);
      if (tcpConnections_.load() >= options_.maxClients + kHandshakeSlack) {
        socket.close(ignored);  // a flood: not even a 503
      } else if (tls_) {
        std::make_shared<UpgradeRequest<TlsStream>>(
            TlsStream(beast::tcp_stream(std::move(socket)), *tls_), *this, connectionTicket(), peer)
            ->run();
      } else {
        std::make_shared<UpgradeRequest<beast::tcp_stream>>(beast::tcp_stream(std::move(socket)),
                                                            *this, connectionTicket(), peer)
            ->run();
      }
    }
    accept();
  });
}

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
