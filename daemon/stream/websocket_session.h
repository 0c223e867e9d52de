// WebSocketSession: one client's WebSocket connection after its upgrade request was accepted
// (stream_server.cpp), over a plain TCP stream or TLS: the read loop hands each binary message
// to client_message_handler.h through the SessionHost, the write loop sends the Outbox's next
// message while no write is pending. A write pending longer than the send timeout closes the
// socket. Lives on the server's io thread; kept alive by its pending operations.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "stream/client_message_handler.h"
#include "stream/stream_connection.h"

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
        host_(host) {}

  void run(http::request<http::string_body> request) {
    beast::get_lowest_layer(ws_).expires_never();
    websocket::stream_base::timeout timeouts =
        websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeouts.handshake_timeout = host_.options().handshakeTimeout;
    timeouts.idle_timeout = host_.options().idleTimeout;
    timeouts.keep_alive_pings = true;
    ws_.set_option(timeouts);
    ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& response) {
      response.set(http::field::server, "vemd");
    }));
    ws_.read_message_max(kMaxClientMessageBytes);
    ws_.binary(true);
    ws_.async_accept(request, [self = this->shared_from_this()](beast::error_code ec) {
      self->onAccept(ec);
    });
  }

  void wake() override { pump(); }

  void closeWith(std::uint16_t code, std::string reason) override {
    if (closing_ || ended_) return;
    closing_ = true;
    closeReason_ = std::move(reason);
    pendingClose_ = websocket::close_reason(static_cast<websocket::close_code>(code), closeReason_);
    if (!writing_) sendClose();
  }

 private:
  void onAccept(beast::error_code ec) {
    if (ec) return end("the WebSocket handshake failed (" + ec.message() + ")");
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
    ClientAction action = handleClientMessage(
        std::string_view(static_cast<const char*>(data.data()), data.size()), controlAllowed());
    buffer_.consume(buffer_.size());
    host_.received(*this, std::move(action));
    read();
  }

  void pump() {
    if (!open || writing_ || ended_) return;
    if (closing_) return sendClose();
    current_ = outbox.next();
    if (!current_) return;
    writing_ = true;
    const std::uint64_t generation = ++writeGeneration_;
    sendTimer_.expires_after(host_.options().sendTimeout);
    sendTimer_.async_wait([self = this->shared_from_this(), generation](beast::error_code ec) {
      if (ec || !self->writing_ || self->writeGeneration_ != generation) return;
      self->abort("a send did not complete within the send timeout");
    });
    ws_.async_write(asio::buffer(*current_),
                    [self = this->shared_from_this()](beast::error_code ec, std::size_t) {
                      self->onWrite(ec);
                    });
  }

  void onWrite(beast::error_code ec) {
    writing_ = false;
    current_.reset();
    sendTimer_.cancel();
    if (ec) return end(abortReason_.empty() ? "the write failed (" + ec.message() + ")"
                                            : abortReason_);
    pump();
  }

  void sendClose() {
    if (!pendingClose_ || writing_ || ended_) return;
    writing_ = true;
    const websocket::close_reason reason = *pendingClose_;
    pendingClose_.reset();
    ws_.async_close(reason, [self = this->shared_from_this()](beast::error_code) {
      self->writing_ = false;
      self->end("closed by vemd: " + self->closeReason_);
    });
  }

  // Closes the socket: pending reads and writes complete with an error.
  void abort(std::string why) {
    abortReason_ = std::move(why);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  std::string readFailure(beast::error_code ec) const {
    if (!abortReason_.empty()) return abortReason_;
    if (!closeReason_.empty()) return "closed by vemd: " + closeReason_;
    if (ec == websocket::error::closed) {
      const auto& reason = ws_.reason();
      return "the client closed the connection (" + std::to_string(reason.code) +
             (reason.reason.empty() ? "" : ", " + std::string(reason.reason.c_str())) + ")";
    }
    if (ec == websocket::error::message_too_big) {
      return "closed by vemd: a message over " + std::to_string(kMaxClientMessageBytes) +
             " bytes (1009)";
    }
    if (ec == beast::error::timeout) return "the client stopped answering (idle timeout)";
    if (ec == boost::asio::error::eof || ec == boost::asio::error::connection_reset) {
      return "the client left without a closing handshake (" + ec.message() + ")";
    }
    return "the connection failed (" + ec.message() + ")";
  }

  void end(const std::string& why) {
    if (ended_) return;
    ended_ = true;
    sendTimer_.cancel();
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
    host_.ended(*this, why);
  }

  websocket::stream<NextLayer> ws_;
  beast::flat_buffer buffer_;
  asio::steady_timer sendTimer_;
  SessionHost& host_;
  SharedBytes current_;
  bool writing_ = false;
  bool closing_ = false;
  bool ended_ = false;
  std::uint64_t writeGeneration_ = 0;
  std::optional<websocket::close_reason> pendingClose_;
  std::string closeReason_;
  std::string abortReason_;
};

}  // namespace vem::stream
