#include "stream_e2e/raw_ws_client.h"

#include <boost/asio/ip/address.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/http/field.hpp>
#include <boost/beast/websocket.hpp>

#include "proto/stream_protocol.h"

namespace vem::e2e {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = boost::beast::websocket;
using tcp = asio::ip::tcp;

RawWsClient::RawWsClient() : ws_(ioc_) {}

RawWsClient::~RawWsClient() { drop(); }

// Runs one asynchronous operation to its end or to `timeout`, when the socket is dropped (which
// ends the operation) and false returned.
template <class Start>
bool RawWsClient::run(Start start, std::chrono::milliseconds timeout) {
  bool finished = false;
  beast::error_code error;
  start([&](beast::error_code ec, auto&&...) {
    error = ec;
    finished = true;
  });
  ioc_.restart();
  ioc_.run_for(timeout);
  if (!finished) {
    drop();
    ioc_.restart();
    ioc_.run();
    lastError_ = "timed out";
    return false;
  }
  lastError_ = error ? error.message() : "";
  return !error;
}

int RawWsClient::connect(std::uint16_t port, const RawConnectOptions& options) {
  beast::error_code ec;
  tcp::socket& socket = ws_.next_layer();
  hello_.Clear();
  socket.open(tcp::v4(), ec);
  if (!ec && !options.source.empty()) {
    const auto local = asio::ip::make_address(options.source, ec);
    if (!ec) socket.bind({local, 0}, ec);
  }
  if (ec) return -1;
  if (options.receiveBufferBytes) {
    socket.set_option(asio::socket_base::receive_buffer_size(*options.receiveBufferBytes), ec);
    if (ec) return -1;
  }
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), port);
  if (!run([&](auto done) { socket.async_connect(endpoint, done); }, options.timeout)) return -1;
  if (options.token) {
    ws_.set_option(websocket::stream_base::decorator(
        [token = *options.token](websocket::request_type& request) {
          request.set(beast::http::field::authorization, "Bearer " + token);
        }));
  }
  ws_.binary(true);
  websocket::response_type response;
  if (!run([&](auto done) { ws_.async_handshake(response, "127.0.0.1", options.target, done); },
           options.timeout)) {
    return response.result_int() != 0 ? int(response.result_int()) : -1;
  }
  const auto hello = readBytes(options.timeout);
  stream::ServerMessage message;
  if (!hello || !message.ParseFromString(*hello) || !message.has_hello()) return -1;
  hello_ = std::move(message);
  return 0;
}

bool RawWsClient::send(stream::ClientMessage message, std::chrono::milliseconds timeout) {
  if (message.protocol_major() == 0) {
    message.set_protocol_major(stream::kProtocolMajor);
    message.set_protocol_minor(stream::kProtocolMinor);
  }
  return sendBytes(message.SerializeAsString(), true, timeout);
}

bool RawWsClient::sendBytes(const std::string& bytes, bool binary, std::chrono::milliseconds timeout) {
  ws_.binary(binary);
  return run([&](auto done) { ws_.async_write(asio::buffer(bytes), done); }, timeout);
}

std::optional<std::string> RawWsClient::readBytes(std::chrono::milliseconds timeout) {
  buffer_.clear();
  if (!run([&](auto done) { ws_.async_read(buffer_, done); }, timeout)) return std::nullopt;
  return beast::buffers_to_string(buffer_.cdata());
}

void RawWsClient::close(std::chrono::milliseconds timeout, const std::string& reason) {
  if (!ws_.is_open()) return;
  const websocket::close_reason frame(websocket::close_code::normal, reason);
  (void)run([&](auto done) { ws_.async_close(frame, done); }, timeout);
  drop();
}

void RawWsClient::drop() {
  beast::error_code ignored;
  ws_.next_layer().close(ignored);
}

int RawWsClient::closeCode() const { return ws_.reason().code; }

std::string RawWsClient::closeReason() const { return std::string(ws_.reason().reason.c_str()); }

}  // namespace vem::e2e
