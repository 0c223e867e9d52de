// UpgradeRequest: one TCP connection from its accept until its HTTP upgrade request is decided:
// the TLS handshake (when TLS is on), the request read within a deadline, then either a
// WebSocketSession or an HTTP answer (400, 401, 503) and a close. A connection the server
// refuses before looking at it (handshake_slots.h: too many handshakes from its address) takes the
// same path with a short deadline and its answer decided in advance, so every refused client that
// sends its request reads why (docs/protocol.md, "Errors and limits").
//
// The server (UpgradeHost) is told exactly once how the handshake ended (handshakeEnded), and may
// evict a pending one (evict(): the socket is closed, the outcome is Evicted). Lives on the
// server's io thread; kept alive by its pending operations.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>

namespace vem::stream {

namespace upgrade {
namespace beast = boost::beast;
namespace http = boost::beast::http;
namespace ssl = boost::asio::ssl;
using tcp = boost::asio::ip::tcp;
}  // namespace upgrade

using TlsStream = boost::beast::ssl_stream<boost::beast::tcp_stream>;

enum class HandshakeOutcome {
  Upgraded,  // handed to a WebSocketSession
  Answered,  // answered 400, 401 or 503 and closed
  TimedOut,  // no complete request (or TLS handshake) within the deadline
  Failed,    // TLS failed, the request was malformed or too large, the client left
  Evicted,   // closed to make room for another (handshake_slots.h)
};

// An answer decided before the request is read.
struct Refusal {
  unsigned status = 503;
  std::string body;
};

// What an UpgradeRequest needs from the server (StreamServer::Impl).
class UpgradeHost {
 public:
  [[nodiscard]] virtual std::chrono::milliseconds handshakeTimeout() const = 0;
  // Decides a complete upgrade request: empty to accept (then startSession follows), or an
  // HTTP status and a body.
  [[nodiscard]] virtual std::optional<Refusal> admit(
      const upgrade::http::request<upgrade::http::string_body>& request, bool& controlAllowed) = 0;
  // The handshake ended; `status` is the HTTP status of an Answered one (0 otherwise), `detail`
  // one phrase for the log.
  virtual void handshakeEnded(std::uint64_t id, HandshakeOutcome outcome, unsigned status,
                              const std::string& peer, const std::string& detail) = 0;

 protected:
  ~UpgradeHost() = default;
};

class PendingHandshake {
 public:
  virtual ~PendingHandshake() = default;
  virtual void evict() = 0;
};

// `StartSession`: void(Stream&&, request, bool controlAllowed, std::string peer).
template <class Stream, class StartSession>
class UpgradeRequest final
    : public PendingHandshake,
      public std::enable_shared_from_this<UpgradeRequest<Stream, StartSession>> {
 public:
  static constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
  // A connection refused at once gets this long to send its request and read the answer.
  static constexpr std::chrono::milliseconds kRefusalTimeout{1000};

  UpgradeRequest(Stream stream, UpgradeHost& host, StartSession startSession, std::uint64_t id,
                 std::shared_ptr<void> ticket, std::string peer, std::optional<Refusal> refusal)
      : stream_(std::move(stream)),
        host_(host),
        startSession_(std::move(startSession)),
        id_(id),
        ticket_(std::move(ticket)),
        peer_(std::move(peer)),
        refusal_(std::move(refusal)) {}

  void run() {
    upgrade::beast::get_lowest_layer(stream_).expires_after(refusal_ ? kRefusalTimeout
                                                                     : host_.handshakeTimeout());
    if constexpr (std::is_same_v<Stream, TlsStream>) {
      stream_.async_handshake(upgrade::ssl::stream_base::server,
                              [self = this->shared_from_this()](upgrade::beast::error_code ec) {
                                if (ec) return self->fail(ec, "the TLS handshake failed");
                                self->read();
                              });
    } else {
      read();
    }
  }

  void evict() override {
    if (done_) return;
    finish(HandshakeOutcome::Evicted, "");
    upgrade::beast::error_code ignored;
    upgrade::beast::get_lowest_layer(stream_).socket().close(ignored);
  }

 private:
  void read() {
    parser_.header_limit(kMaxHeaderBytes);
    parser_.body_limit(kMaxHeaderBytes);
    upgrade::http::async_read(stream_, buffer_, parser_,
                              [self = this->shared_from_this()](upgrade::beast::error_code ec,
                                                                std::size_t) { self->onRead(ec); });
  }

  void onRead(upgrade::beast::error_code ec) {
    if (ec) return fail(ec, "no complete upgrade request");
    upgrade::http::request<upgrade::http::string_body> request = parser_.release();
    if (refusal_) return respond(std::move(*refusal_));
    if (!boost::beast::websocket::is_upgrade(request)) {
      return respond({400,
                      "this is vemd's WebSocket endpoint (proto/vem_stream.proto); connect with a "
                      "WebSocket client"});
    }
    bool controlAllowed = false;
    if (auto refused = host_.admit(request, controlAllowed)) return respond(std::move(*refused));
    finish(HandshakeOutcome::Upgraded, "");
    startSession_(std::move(stream_), std::move(request), controlAllowed, std::move(peer_));
  }

  void fail(upgrade::beast::error_code ec, const char* what) {
    if (done_) return;  // evicted: the close made the operation fail
    const bool timedOut = ec == upgrade::beast::error::timeout;
    finish(timedOut ? HandshakeOutcome::TimedOut : HandshakeOutcome::Failed,
           timedOut ? std::string(what) : std::string(what) + " (" + ec.message() + ")");
  }

  void respond(Refusal refusal) {
    finish(HandshakeOutcome::Answered, std::to_string(refusal.status) + ": " + refusal.body,
           refusal.status);
    response_.result(upgrade::http::status(refusal.status));
    response_.version(11);
    response_.set(upgrade::http::field::server, "vemd");
    response_.set(upgrade::http::field::content_type, "text/plain");
    if (refusal.status == 401) {
      response_.set(upgrade::http::field::www_authenticate, "Bearer realm=\"vemd\"");
    }
    if (refusal.status == 503) response_.set(upgrade::http::field::retry_after, "1");
    response_.keep_alive(false);
    response_.body() = std::move(refusal.body) + "\n";
    response_.prepare_payload();
    upgrade::http::async_write(
        stream_, response_,
        [self = this->shared_from_this()](upgrade::beast::error_code, std::size_t) {
          upgrade::beast::error_code ignored;
          auto& socket = upgrade::beast::get_lowest_layer(self->stream_).socket();
          socket.shutdown(upgrade::tcp::socket::shutdown_both, ignored);
          socket.close(ignored);
        });
  }

  void finish(HandshakeOutcome outcome, const std::string& detail, unsigned status = 0) {
    if (done_) return;
    done_ = true;
    host_.handshakeEnded(id_, outcome, status, peer_, detail);
  }

  Stream stream_;
  UpgradeHost& host_;
  StartSession startSession_;
  std::uint64_t id_;
  std::shared_ptr<void> ticket_;
  std::string peer_;
  std::optional<Refusal> refusal_;
  bool done_ = false;
  upgrade::beast::flat_buffer buffer_;
  upgrade::http::request_parser<upgrade::http::string_body> parser_;
  upgrade::http::response<upgrade::http::string_body> response_;
};

}  // namespace vem::stream
