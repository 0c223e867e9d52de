#include "client/test_stream_server.h"

#include <deque>
#include <stdexcept>
#include <thread>

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "client/stream_test_messages.h"

namespace vem::client::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using asio::awaitable;
using asio::use_awaitable;
using Ws = websocket::stream<beast::tcp_stream>;

// One connection's socket and the messages waiting to be written to it.
struct Connection {
  explicit Connection(asio::ip::tcp::socket socket)
      : ws(std::move(socket)), wake(ws.get_executor()) {
    wake.expires_at(asio::steady_timer::time_point::max());
  }
  Ws ws;
  asio::steady_timer wake;
  std::deque<std::string> outbox;
  bool open = true;

  void push(std::string bytes) {
    outbox.push_back(std::move(bytes));
    wake.cancel();
  }
};

awaitable<void> writeLoop(std::shared_ptr<Connection> c) {
  c->ws.binary(true);
  while (c->open) {
    if (c->outbox.empty()) {
      boost::system::error_code ec;
      co_await c->wake.async_wait(asio::redirect_error(use_awaitable, ec));
      c->wake.expires_at(asio::steady_timer::time_point::max());
      continue;
    }
    std::string bytes = std::move(c->outbox.front());
    c->outbox.pop_front();
    boost::system::error_code ec;
    co_await c->ws.async_write(asio::buffer(bytes), asio::redirect_error(use_awaitable, ec));
    if (ec) co_return;
  }
}

}  // namespace

struct TestStreamServer::State {
  asio::io_context io;
  asio::ip::tcp::acceptor acceptor{io};
  std::thread thread;
  std::string requiredToken;
  std::string greeting;

  mutable std::mutex mutex;
  mutable std::condition_variable changed;
  std::size_t connectionCount = 0;
  std::vector<std::string> authorizations;
  std::vector<stream::ClientMessage> clientMessages;
  std::vector<std::string> endings;
  std::vector<std::weak_ptr<Connection>> connections;  // I/O thread only

  void record(auto update) {
    {
      std::lock_guard lock(mutex);
      update();
    }
    changed.notify_all();
  }

  awaitable<void> readLoop(std::shared_ptr<Connection> c) {
    beast::flat_buffer buffer;
    for (;;) {
      buffer.clear();
      boost::system::error_code ec;
      co_await c->ws.async_read(buffer, asio::redirect_error(use_awaitable, ec));
      if (ec) {
        const std::string ending = ec == websocket::error::closed
                                       ? "close " + std::to_string(c->ws.reason().code)
                                       : "dropped (" + ec.message() + ")";
        record([&] { endings.push_back(ending); });
        break;
      }
      stream::ClientMessage message;
      const auto data = buffer.cdata();
      if (!message.ParseFromArray(data.data(), int(data.size()))) continue;
      record([&] { clientMessages.push_back(message); });
      if (message.has_control()) {
        stream::ServerMessage reply;
        reply.mutable_reply()->set_request_id(message.request_id());
        reply.mutable_reply()->set_ok(true);
        c->push(bytesOf(reply));
      }
    }
    c->open = false;
    c->wake.cancel();
  }

  awaitable<void> serve(asio::ip::tcp::socket socket) {
    auto c = std::make_shared<Connection>(std::move(socket));
    connections.push_back(c);
    beast::flat_buffer buffer;
    http::request<http::string_body> request;
    boost::system::error_code ec;
    co_await http::async_read(c->ws.next_layer(), buffer, request,
                              asio::redirect_error(use_awaitable, ec));
    if (ec) co_return;
    const std::string authorization(request[http::field::authorization]);
    record([&] { authorizations.push_back(authorization); ++connectionCount; });
    if (!requiredToken.empty() && authorization != "Bearer " + requiredToken) {
      http::response<http::string_body> refusal{http::status::unauthorized, request.version()};
      refusal.body() = "token refused";
      refusal.prepare_payload();
      co_await http::async_write(c->ws.next_layer(), refusal, asio::redirect_error(use_awaitable, ec));
      co_return;
    }
    co_await c->ws.async_accept(request, asio::redirect_error(use_awaitable, ec));
    if (ec) co_return;
    c->push(greeting.empty() ? bytesOf(helloMessage(true)) : greeting);
    asio::co_spawn(io, writeLoop(c), asio::detached);
    co_await readLoop(c);
  }

  awaitable<void> acceptLoop() {
    for (;;) {
      boost::system::error_code ec;
      asio::ip::tcp::socket socket =
          co_await acceptor.async_accept(asio::redirect_error(use_awaitable, ec));
      if (ec) co_return;
      asio::co_spawn(io, serve(std::move(socket)), asio::detached);
    }
  }
};

TestStreamServer::TestStreamServer(std::uint16_t port, std::string requiredToken,
                                   std::string greeting)
    : state_(std::make_shared<State>()) {
  State& s = *state_;
  s.requiredToken = std::move(requiredToken);
  s.greeting = std::move(greeting);
  const asio::ip::tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), port);
  s.acceptor.open(endpoint.protocol());
  s.acceptor.set_option(asio::socket_base::reuse_address(true));
  s.acceptor.bind(endpoint);
  s.acceptor.listen();
  port_ = s.acceptor.local_endpoint().port();
  asio::co_spawn(s.io, s.acceptLoop(), asio::detached);
  s.thread = std::thread([&s] { s.io.run(); });
}

TestStreamServer::~TestStreamServer() {
  // Close everything (no close frames) and let the coroutines end: destroying suspended ones with
  // the I/O context is not safe in Boost 1.74's Asio.
  asio::post(state_->io, [s = state_.get()] {
    boost::system::error_code ignored;
    s->acceptor.close(ignored);
    for (const std::weak_ptr<Connection>& weak : s->connections) {
      if (auto c = weak.lock()) {
        beast::get_lowest_layer(c->ws).socket().close(ignored);
        c->open = false;
        c->wake.cancel();
      }
    }
  });
  state_->thread.join();
}

std::string TestStreamServer::url() const { return "ws://127.0.0.1:" + std::to_string(port_) + "/"; }

void TestStreamServer::send(const std::string& bytes) {
  asio::post(state_->io, [s = state_.get(), bytes] {
    for (const std::weak_ptr<Connection>& weak : s->connections) {
      if (auto c = weak.lock(); c && c->open && c->ws.is_open()) c->push(bytes);
    }
  });
}

bool TestStreamServer::waitForConnections(std::size_t count,
                                          std::chrono::milliseconds timeout) const {
  std::unique_lock lock(state_->mutex);
  return state_->changed.wait_for(lock, timeout,
                                  [&] { return state_->connectionCount >= count; });
}

bool TestStreamServer::waitForClientMessages(std::size_t count,
                                             std::chrono::milliseconds timeout) const {
  std::unique_lock lock(state_->mutex);
  return state_->changed.wait_for(lock, timeout,
                                  [&] { return state_->clientMessages.size() >= count; });
}

bool TestStreamServer::waitForEndings(std::size_t count, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(state_->mutex);
  return state_->changed.wait_for(lock, timeout, [&] { return state_->endings.size() >= count; });
}

std::vector<std::string> TestStreamServer::endings() const {
  std::lock_guard lock(state_->mutex);
  return state_->endings;
}

std::vector<std::string> TestStreamServer::authorizations() const {
  std::lock_guard lock(state_->mutex);
  return state_->authorizations;
}

std::vector<stream::ClientMessage> TestStreamServer::clientMessages() const {
  std::lock_guard lock(state_->mutex);
  return state_->clientMessages;
}

}  // namespace vem::client::test
