// A WebSocket client for the stream server's tests (Boost.Beast, 127.0.0.1 only): connects with an
// optional bearer token, reads ServerMessages, sends ClientMessages or raw bytes. Every operation
// gives up after kGiveUpAfter (so a broken server fails a test instead of hanging it; never a
// timing assertion). One client per thread; each has its own io_context.
#pragma once

#include <chrono>
#include <thread>
#include <cstdint>
#include <optional>
#include <string>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "proto/stream_protocol.h"
#include "proto/vem_stream.pb.h"

namespace vem::testing {

namespace beast = boost::beast;
namespace websocket = boost::beast::websocket;
namespace http = boost::beast::http;
namespace asio = boost::asio;

inline constexpr std::chrono::seconds kGiveUpAfter{20};

class WsTestClient {
 public:
  // 0 when upgraded and the Hello read (the server then counts this client as open), else the
  // HTTP status of the refusal (-1: no answer, or no Hello first).
  // `source`: the local address to connect from (another loopback address, 127.0.0.2, makes the
  // server see another client host).
  int connect(std::uint16_t port, const std::string& target = "/",
              const std::optional<std::string>& bearer = std::nullopt,
              const std::string& source = "") {
    beast::error_code ec;
    if (!source.empty()) {
      ws_.next_layer().open(asio::ip::tcp::v4(), ec);
      if (!ec) ws_.next_layer().bind({asio::ip::make_address(source), 0}, ec);
      if (ec) return -1;
    }
    ws_.next_layer().connect({asio::ip::make_address("127.0.0.1"), port}, ec);
    if (ec) return -1;
    if (bearer) {
      ws_.set_option(websocket::stream_base::decorator([token = *bearer](websocket::request_type& r) {
        r.set(http::field::authorization, "Bearer " + token);
      }));
    }
    ws_.binary(true);
    websocket::response_type response;
    run([&](auto done) { ws_.async_handshake(response, "127.0.0.1", target, done); });
    if (!error_) {
      auto first = read();
      if (!first || !first->has_hello()) return -1;
      hello_ = *first;
      return 0;
    }
    return response.result_int() != 0 ? int(response.result_int()) : -1;
  }

  [[nodiscard]] const stream::ServerMessage& hello() const { return hello_; }

  // The next message, or nullopt when the connection ended (closeCode() tells how).
  std::optional<stream::ServerMessage> read() {
    buffer_.clear();
    run([&](auto done) { ws_.async_read(buffer_, done); });
    if (error_) return std::nullopt;
    stream::ServerMessage message;
    const auto data = buffer_.cdata();
    if (!message.ParseFromArray(data.data(), int(data.size()))) return std::nullopt;
    return message;
  }

  // The next light frame's seq, skipping other messages; nullopt when the connection ended.
  std::optional<std::uint64_t> nextLightsSeq(int* environments = nullptr) {
    for (;;) {
      auto message = read();
      if (!message) return std::nullopt;
      if (message->has_lights()) return message->lights().seq();
      if (message->has_environment() && environments != nullptr) ++*environments;
    }
  }

  // The next reply, skipping other messages.
  std::optional<stream::ControlReply> nextReply() {
    for (;;) {
      auto message = read();
      if (!message) return std::nullopt;
      if (message->has_reply()) return message->reply();
    }
  }

  bool send(stream::ClientMessage message) {
    if (message.protocol_major() == 0) message.set_protocol_major(stream::kProtocolMajor);
    return sendRaw(message.SerializeAsString());
  }

  bool sendRaw(const std::string& bytes, bool binary = true) {
    ws_.binary(binary);
    run([&](auto done) { ws_.async_write(asio::buffer(bytes), done); });
    return !error_;
  }

  // The server's close code once read() returned nullopt after a close frame (0: none).
  [[nodiscard]] int closeCode() const { return ws_.reason().code; }
  [[nodiscard]] std::string closeReason() const { return std::string(ws_.reason().reason.c_str()); }
  [[nodiscard]] beast::error_code error() const { return error_; }

  void close() {
    run([&](auto done) { ws_.async_close(websocket::close_code::normal, done); });
  }
  // A normal close (1000) with `reason` in the close frame.
  void closeWith(const std::string& reason) {
    run([&](auto done) {
      ws_.async_close(websocket::close_reason(websocket::close_code::normal, reason), done);
    });
  }
  void drop() {
    beast::error_code ignored;
    ws_.next_layer().close(ignored);
  }

 private:
  template <class Start>
  void run(Start start) {
    bool finished = false;
    error_ = {};
    start([this, &finished](beast::error_code ec, auto&&...) {
      error_ = ec;
      finished = true;
    });
    ioc_.restart();
    ioc_.run_for(kGiveUpAfter);
    if (!finished) {
      drop();
      ioc_.restart();
      ioc_.run();
      error_ = beast::error::timeout;
    }
  }

  asio::io_context ioc_;
  websocket::stream<asio::ip::tcp::socket> ws_{ioc_};
  beast::flat_buffer buffer_;
  beast::error_code error_;
  stream::ServerMessage hello_;
};

// Waits (boundedly, 20 s) until `ready` holds; the bound only keeps a broken server from hanging.
template <class Ready>
bool eventually(Ready ready) {
  for (int i = 0; i < 4000; ++i) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace vem::testing
