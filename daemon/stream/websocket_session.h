// WebSocketSession: one client's WebSocket connection after its upgrade request was accepted
// (stream_server.cpp), over a plain TCP stream or TLS: the read loop hands each binary message
// to client_message_handler.h through the SessionHost, the write loop sends the Outbox's next
// message while no write is pending. A write pending longer than the send timeout closes the
// socket.
//
// Pacing (client_lag.h, docs/protocol.md "Flow control"): after each light, environment or status
// message the session sends a probe ping ("vem-probe N"); the client's pong says it has read that
// far. While the client is behind, only replies go out and the outbox keeps replacing the rest, so
// the client gets the newest frame once it catches up; a client behind by more than maxClientLag
// is told so (close 1008) and closed. Lives on the server's io thread; kept alive by its pending
// operations.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "stream/client_lag.h"
#include "stream/client_message_handler.h"
#include "stream/stream_connection.h"
#include "util/printable.h"

namespace vem::stream {

namespace beast = boost::beast;
namespace websocket = boost::beast::websocket;
namespace http = boost::beast::http;
namespace asio = boost::asio;

template <class NextLayer>
class WebSocketSession final : public Connection,
                               public std::enable_shared_from_this<WebSocketSession<NextLayer>> {
 public:
  WebSocketSession(NextLayer&& stream, SessionHost& host, std::uint64_t id, bool controlAllowed,
                   std::string peer)
      : Connection(id, controlAllowed, std::move(peer)),
        ws_(std::move(stream)),
        sendTimer_(ws_.get_executor()),
        lagTimer_(ws_.get_executor()),
        host_(host),
        lag_(ClientLagOptions{std::chrono::nanoseconds(host.options().lagSlack).count(),
                              std::chrono::nanoseconds(host.options().maxClientLag).count()}) {}

  void run(http::request<http::string_body> request) {
    beast::get_lowest_layer(ws_).expires_never();
    websocket::stream_base::timeout timeouts =
        websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeouts.handshake_timeout = host_.options().handshakeTimeout;
    timeouts.idle_timeout = host_.options().idleTimeout;
    timeouts.keep_alive_pings = true;
    ws_.set_option(timeouts);
    ws_.set_option(websocket::stream_base::decorator(
        [](websocket::response_type& response) { response.set(http::field::server, "vemd"); }));
    ws_.read_message_max(kMaxClientMessageBytes);
    ws_.binary(true);
    // Called inside a read (which holds a reference to this session); the pong is handled after
    // it, outside Beast's read operation.
    ws_.control_callback([this](websocket::frame_type kind, beast::string_view payload) {
      if (kind != websocket::frame_type::pong) return;
      if (auto probe = probeId(payload)) {
        asio::post(ws_.get_executor(),
                   [self = this->shared_from_this(), id = *probe] { self->onPong(id); });
      }
    });
    ws_.async_accept(
        request, [self = this->shared_from_this()](beast::error_code ec) { self->onAccept(ec); });
  }

  void wake() override { pump(); }

  [[nodiscard]] ConnectionPacing pacing() const override {
    return {heldCount_, tooSlow_, lag_.minRoundTripNs().value_or(0), lag_.maxRoundTripNs()};
  }

  void closeWith(std::uint16_t code, std::string reason) override {
    if (closing_ || ended_) return;
    closing_ = true;
    closeReason_ = std::move(reason);
    pendingClose_ = websocket::close_reason(static_cast<websocket::close_code>(code), closeReason_);
    if (!writing_) sendClose();
  }

 private:
  using Cause = ConnectionEndCause;

  void onAccept(beast::error_code ec) {
    if (ec) return end({Cause::Lost, "the WebSocket handshake failed (" + ec.message() + ")"});
    open = true;
    host_.opened(*this);
    read();
    pump();
  }

  void read() {
    ws_.async_read(buffer_, [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
      self->onRead(ec);
    });
  }

  void onRead(beast::error_code ec) {
    if (ec) return end(readFailure(ec));
    if (closing_) {  // discard what comes until the close handshake ends
      buffer_.consume(buffer_.size());
      return read();
    }
    if (!ws_.got_binary()) {
      buffer_.consume(buffer_.size());
      closeWith(close_code::kUnsupportedData, "text messages are not part of the protocol");
      return read();
    }
    const auto data = buffer_.cdata();
    ClientAction action =
        handleClientMessage(std::string_view(static_cast<const char*>(data.data()), data.size()),
                            controlAllowed(), host_.options().cubemapBudget);
    buffer_.consume(buffer_.size());
    host_.received(*this, std::move(action));
    read();
  }

  void pump() {
    if (!open || writing_ || ended_) return;
    if (closing_) return sendClose();
    if (probeDue_) return sendProbe();
    const bool reply = outbox.hasReply();
    if (!reply) {
      if (outbox.empty()) return;
      const std::int64_t nowNs = steadyNowNs();
      if (lag_.tooSlow(nowNs)) return closeTooSlow(nowNs);
      if (!lag_.mayWrite(nowNs)) return hold(nowNs);
    }
    current_ = outbox.next();
    if (!current_) return;
    probeDue_ = !reply;
    startWrite([&](auto done) { ws_.async_write(asio::buffer(*current_), done); });
  }

  // Starts one write (a message or a probe) with the send timeout armed.
  template <class Start>
  void startWrite(Start start) {
    writing_ = true;
    const std::uint64_t generation = ++writeGeneration_;
    sendTimer_.expires_after(host_.options().sendTimeout);
    sendTimer_.async_wait([self = this->shared_from_this(), generation](beast::error_code ec) {
      if (ec || !self->writing_ || self->writeGeneration_ != generation) return;
      self->abort("a send did not complete within the send timeout");
    });
    start(
        [self = this->shared_from_this()](beast::error_code ec, auto&&...) { self->onWrite(ec); });
  }

  void onWrite(beast::error_code ec) {
    writing_ = false;
    current_.reset();
    sendTimer_.cancel();
    if (!ec) return pump();
    if (!abortReason_.empty()) return end({Cause::ClosedByVemd, abortReason_});
    end({Cause::Lost, "the write failed (" + ec.message() + ")"});
  }

  // The probe after a data message: a ping whose pong says the client has read that far.
  void sendProbe() {
    probeDue_ = false;
    const auto id = lag_.probeSent(steadyNowNs());
    if (!id) return pump();  // too many unconfirmed: pump holds until pongs come
    probe_ = websocket::ping_data(kProbePrefix);
    probe_.append(std::to_string(*id));
    startWrite([&](auto done) { ws_.async_ping(probe_, done); });
  }

  void onPong(std::uint64_t id) {
    if (ended_) return;
    lag_.pongReceived(id, steadyNowNs());
    if (holding_) {
      holding_ = false;
      lagTimer_.cancel();
    }
    pump();
  }

  // Holds what the outbox has until a pong comes; the timer closes the client once it is more
  // than maxClientLag behind.
  void hold(std::int64_t nowNs) {
    if (holding_) return;
    holding_ = true;
    ++heldCount_;
    const std::int64_t untilTooSlowNs =
        std::chrono::nanoseconds(host_.options().maxClientLag).count() - lag_.lagNs(nowNs) + 1;
    lagTimer_.expires_after(std::chrono::nanoseconds(std::max<std::int64_t>(untilTooSlowNs, 1)));
    lagTimer_.async_wait([self = this->shared_from_this()](beast::error_code ec) {
      if (ec || !self->holding_) return;
      self->holding_ = false;
      self->pump();
    });
  }

  void closeTooSlow(std::int64_t nowNs) {
    tooSlow_ = true;
    const std::int64_t lagMs = lag_.lagNs(nowNs) / 1'000'000;
    closeWith(close_code::kPolicyViolation,
              "the client reads too slowly: " + std::to_string(lagMs) + " ms behind");
    host_.tooSlow(*this, lagMs);
  }

  static std::int64_t steadyNowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  static std::optional<std::uint64_t> probeId(beast::string_view payload) {
    const std::string_view text(payload.data(), payload.size());
    if (!text.starts_with(kProbePrefix)) return std::nullopt;
    std::uint64_t id = 0;
    const std::string_view digits = text.substr(std::string_view(kProbePrefix).size());
    if (digits.empty() || digits.size() > 19) return std::nullopt;
    for (const char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      id = id * 10 + std::uint64_t(c - '0');
    }
    return id;
  }

  void sendClose() {
    if (!pendingClose_ || writing_ || ended_) return;
    const websocket::close_reason reason = *pendingClose_;
    pendingClose_.reset();
    // The send timeout bounds the closing handshake too: a client that does not read cannot
    // hold its connection open by never taking the close frame.
    writing_ = true;
    const std::uint64_t generation = ++writeGeneration_;
    sendTimer_.expires_after(host_.options().sendTimeout);
    sendTimer_.async_wait([self = this->shared_from_this(), generation](beast::error_code ec) {
      if (ec || !self->writing_ || self->writeGeneration_ != generation) return;
      self->abort("closed by vemd: " + self->closeReason_);
    });
    ws_.async_close(reason, [self = this->shared_from_this()](beast::error_code) {
      self->writing_ = false;
      self->end({Cause::ClosedByVemd, "closed by vemd: " + self->closeReason_});
    });
  }

  // Closes the socket: pending reads and writes complete with an error, and the connection ends
  // as closed by vemd for `why`.
  void abort(std::string why) {
    abortReason_ = std::move(why);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  ConnectionEnd readFailure(beast::error_code ec) const {
    if (!abortReason_.empty()) return {Cause::ClosedByVemd, abortReason_};
    if (!closeReason_.empty()) return {Cause::ClosedByVemd, "closed by vemd: " + closeReason_};
    if (ec == websocket::error::closed) {
      const auto& reason = ws_.reason();
      return {Cause::ClosedByClient,
              "the client closed the connection (" + std::to_string(reason.code) +
                  (reason.reason.empty() ? ""
                                         : ", \"" +
                                               util::printable(std::string_view(
                                                   reason.reason.data(), reason.reason.size())) +
                                               "\"") +
                  ")"};
    }
    if (ec == websocket::error::message_too_big) {
      return {Cause::ClosedByVemd, "closed by vemd: a message over " +
                                       std::to_string(kMaxClientMessageBytes) + " bytes (1009)"};
    }
    if (ec == beast::error::timeout) {
      return {Cause::Lost, "the client stopped answering (idle timeout)"};
    }
    if (ec == boost::asio::error::eof || ec == boost::asio::error::connection_reset) {
      return {Cause::Lost, "the client left without a closing handshake (" + ec.message() + ")"};
    }
    return {Cause::Lost, "the connection failed (" + ec.message() + ")"};
  }

  void end(const ConnectionEnd& how) {
    if (ended_) return;
    ended_ = true;
    sendTimer_.cancel();
    lagTimer_.cancel();
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
    host_.ended(*this, how);
  }

  static constexpr const char* kProbePrefix = "vem-probe ";

  websocket::stream<NextLayer> ws_;
  beast::flat_buffer buffer_;
  asio::steady_timer sendTimer_;
  asio::steady_timer lagTimer_;
  SessionHost& host_;
  ClientLag lag_;
  SharedBytes current_;
  websocket::ping_data probe_;
  bool probeDue_ = false;
  bool holding_ = false;
  bool tooSlow_ = false;
  std::uint64_t heldCount_ = 0;
  bool writing_ = false;
  bool closing_ = false;
  bool ended_ = false;
  std::uint64_t writeGeneration_ = 0;
  std::optional<websocket::close_reason> pendingClose_;
  std::string closeReason_;
  std::string abortReason_;
};

}  // namespace vem::stream
