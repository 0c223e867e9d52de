#include "bench/mqtt/ws_subscriber_set.h"

#include <fmt/format.h>
#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/websocket.hpp>

#include "bench/measurements.h"

namespace vem::bench {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = boost::beast::websocket;
using tcp = asio::ip::tcp;

struct WsSubscriberSet::Client {
  explicit Client(asio::io_context& ioc, std::size_t i) : ws(asio::make_strand(ioc)), index(i) {}
  websocket::stream<beast::tcp_stream> ws;
  beast::flat_buffer buffer;
  std::size_t index = 0;
};

WsSubscriberSet::WsSubscriberSet(WsSubscriberOptions options)
    : options_(std::move(options)), work_(asio::make_work_guard(ioc_)) {}

std::expected<std::unique_ptr<WsSubscriberSet>, std::string> WsSubscriberSet::start(
    WsSubscriberOptions options) {
  std::unique_ptr<WsSubscriberSet> set(new WsSubscriberSet(std::move(options)));
  WsSubscriberSet& s = *set;
  for (std::size_t i = 0; i < s.options_.clients; ++i) {
    s.clients_.push_back(std::make_unique<Client>(s.ioc_, i));
  }
  for (const auto& client : s.clients_) s.connect(*client);
  for (std::size_t t = 0; t < std::max<std::size_t>(1, s.options_.threads); ++t) {
    s.threads_.emplace_back([&s] { s.ioc_.run(); });
  }
  const auto deadline = std::chrono::steady_clock::now() + s.options_.timeout;
  while (s.connected_.load() + s.failed_.load() < s.options_.clients &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (s.connected_.load() < s.options_.clients) {
    return std::unexpected(fmt::format("only {} of {} WebSocket clients connected ({} failed)",
                                       s.connected_.load(), s.options_.clients, s.failed_.load()));
  }
  return set;
}

void WsSubscriberSet::connect(Client& client) {
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), options_.port);
  beast::get_lowest_layer(client.ws).async_connect(endpoint, [this, &client](beast::error_code ec) {
    if (ec) {
      ++failed_;
      return;
    }
    client.ws.binary(true);
    client.ws.async_handshake("127.0.0.1", "/", [this, &client](beast::error_code handshake) {
      if (handshake) {
        ++failed_;
        return;
      }
      ++connected_;
      read(client);
    });
  });
}

void WsSubscriberSet::read(Client& client) {
  client.ws.async_read(client.buffer, [this, &client](beast::error_code ec, std::size_t) {
    const std::int64_t receivedNs = realtimeNs();
    if (ec) {
      if (!stopping_.load()) ++lost_;
      return;
    }
    const auto data = client.buffer.cdata();
    options_.onMessage(client.index,
                       std::string_view(static_cast<const char*>(data.data()), data.size()),
                       receivedNs);
    client.buffer.consume(client.buffer.size());
    read(client);
  });
}

void WsSubscriberSet::stop() {
  if (stopped_) return;
  stopped_ = true;
  stopping_ = true;
  work_.reset();
  ioc_.stop();
  for (std::thread& thread : threads_) thread.join();
}

WsSubscriberSet::~WsSubscriberSet() {
  stop();
  clients_.clear();  // the sockets close; handlers never run again
}

}  // namespace vem::bench
