#include "client/websocket_transport.h"

#include <openssl/err.h>
#include <openssl/ssl.h>

#include <deque>
#include <functional>
#include <optional>
#include <thread>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>

#include "client/server_message_decoder.h"
#include "client/stream_url.h"
#include "proto/stream_protocol.h"
#include "util/backoff.h"

namespace vem::client {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using asio::awaitable;
using asio::use_awaitable;
using PlainWs = websocket::stream<beast::tcp_stream>;
using TlsWs = websocket::stream<beast::ssl_stream<beast::tcp_stream>>;

// The messages waiting to be written on one connection, and the timer that wakes its writer.
struct Outbox {
  explicit Outbox(asio::any_io_executor executor) : wake(executor) {
    wake.expires_at(asio::steady_timer::time_point::max());
  }
  std::deque<std::string> messages;
  asio::steady_timer wake;
  bool open = true;
  bool closing =
      false;  // stop(): the write loop sends a close frame (1000) after its current write
};

// How long stop() waits for the daemon to answer the close frame before it drops the socket.
constexpr std::chrono::milliseconds kClosingHandshakeLimit{1000};

// How one connection ended.
struct SessionEnd {
  std::string reason;
  bool established = false;  // the Hello arrived
  bool fatal = false;        // do not retry
};

// A refusal by the daemon at the handshake (fatal, nothing to close) or by this client of one of
// the daemon's messages (decodeError: the connection is closed with 1002 and the reason).
struct ProtocolRefusal {
  std::string reason;
  bool fatal = false;
  bool decodeError = true;
};

std::string clientMessageBytes(stream::ClientMessage message) {
  message.set_protocol_major(stream::kProtocolMajor);
  message.set_protocol_minor(stream::kProtocolMinor);
  return message.SerializeAsString();
}

// The TLS handshake: SNI and host-name verification against `host`, then the handshake.
awaitable<void> secureTransport(TlsWs& ws, const std::string& host) {
  // SSL_set_tlsext_host_name without its macro's C cast.
  if (SSL_ctrl(ws.next_layer().native_handle(), SSL_CTRL_SET_TLSEXT_HOSTNAME,
               TLSEXT_NAMETYPE_host_name, const_cast<char*>(host.c_str())) != 1) {
    throw beast::system_error(
        beast::error_code(int(::ERR_get_error()), asio::error::get_ssl_category()));
  }
  ws.next_layer().set_verify_callback(asio::ssl::host_name_verification(host));
  co_await ws.next_layer().async_handshake(asio::ssl::stream_base::client, use_awaitable);
}

awaitable<void> secureTransport(PlainWs& /*ws*/, const std::string& /*host*/) { co_return; }

class WebSocketTransport final : public StreamTransport {
 public:
  WebSocketTransport(const StreamClientOptions& o, ClientState& s, StreamUrl u)
      : options(o), state(s), url(std::move(u)) {}
  ~WebSocketTransport() override { stop(); }
  WebSocketTransport(const WebSocketTransport&) = delete;
  WebSocketTransport& operator=(const WebSocketTransport&) = delete;

  void start();
  void stop() override;
  std::future<ControlResult> sendControl(const stream::Control& control) override;

  // ---- configuration (immutable after start)
  const StreamClientOptions& options;
  ClientState& state;
  StreamUrl url;
  std::optional<asio::ssl::context> tls;  // outlives the I/O context below

 private:
  // ---- I/O thread only
  std::unique_ptr<asio::io_context> io = std::make_unique<asio::io_context>();
  std::optional<asio::executor_work_guard<asio::io_context::executor_type>> work;
  std::thread thread;
  std::shared_ptr<Outbox> outbox;  // the connected session's, else null
  std::uint64_t subscribeRequestId = 0;
  bool stopping = false;                             // stop() asked: every coroutine winds down
  std::function<void()> cancelSession;               // aborts the current connection's operations
  std::unique_ptr<asio::steady_timer> closingLimit;  // stop()'s deadline for the closing handshake
  asio::steady_timer* backoffTimer = nullptr;
  bool stopped = false;  // stop() ran (caller's thread)

  void enqueue(std::string bytes) {
    if (!outbox) return;
    outbox->messages.push_back(std::move(bytes));
    outbox->wake.cancel();
  }

  void sendSubscribe() {
    stream::ClientMessage message;
    subscribeRequestId = state.nextRequestId();
    message.set_request_id(subscribeRequestId);
    stream::Subscribe& subscribe = *message.mutable_subscribe();
    const Subscription& s = options.subscription;
    subscribe.set_lights(s.lights);
    subscribe.set_cubemap_rate_hz(s.cubemapRateHz);
    subscribe.set_cubemap_face_px(s.cubemapFacePx);
    subscribe.set_cubemap_levels(s.cubemapLevels);
    subscribe.set_preview(s.preview);
    enqueue(clientMessageBytes(std::move(message)));
  }

  void sendControlNow(stream::Control control, std::promise<ControlResult> promise) {
    const std::optional<Hello> hello = state.hello();
    if (!outbox) {
      promise.set_value(std::unexpected(std::string("the client is not connected to the daemon")));
      return;
    }
    if (!hello || !hello->controlAllowed) {
      promise.set_value(std::unexpected(std::string(
          "the daemon does not accept control messages on this connection (token not accepted)")));
      return;
    }
    const std::optional<std::uint64_t> id =
        state.addPendingControl(std::move(promise), "the client is not connected to the daemon");
    if (!id) return;
    stream::ClientMessage message;
    message.set_request_id(*id);
    *message.mutable_control() = std::move(control);
    enqueue(clientMessageBytes(std::move(message)));
  }

  // ---- handling decoded events (I/O thread)
  void onEvent(ServerEvent& event, bool first) {
    if (first && !std::holds_alternative<Hello>(event)) {
      throw ProtocolRefusal{"the daemon's first message is not a Hello", false};
    }
    std::visit([this](auto& value) { handle(value); }, event);
  }

  void handle(Ignored&) {}

  void handle(Hello& value) {
    state.keepHello(value);
    state.countConnection();
    sendSubscribe();
    state.setState(ConnectionState::Connected, "");
  }

  void handle(LightFrame& value) { state.onLightFrame(std::move(value)); }
  void handle(EnvironmentFrame& value) { state.onEnvironmentFrame(std::move(value)); }
  void handle(Status& value) { state.onStatus(std::move(value)); }

  void handle(ControlReply& value) {
    if (value.requestId == subscribeRequestId) {
      if (!value.ok)
        spdlog::warn("stream {}: subscription refused: {}", options.url, value.message);
      return;
    }
    state.onControlReply(std::move(value));  // not ours (or already failed): nothing waits for it
  }

  // ---- the connection (I/O thread)
  template <class Ws>
  static awaitable<void> writeLoop(std::shared_ptr<Ws> ws, std::shared_ptr<Outbox> box) {
    while (box->open) {
      if (box->closing) {
        // The read loop then ends with the daemon's answering close frame.
        boost::system::error_code ec;
        co_await ws->async_close(websocket::close_code::normal,
                                 asio::redirect_error(use_awaitable, ec));
        co_return;
      }
      if (box->messages.empty()) {
        boost::system::error_code ec;
        co_await box->wake.async_wait(asio::redirect_error(use_awaitable, ec));
        box->wake.expires_at(asio::steady_timer::time_point::max());
        continue;
      }
      std::string bytes = std::move(box->messages.front());
      box->messages.pop_front();
      boost::system::error_code ec;
      co_await ws->async_write(asio::buffer(bytes), asio::redirect_error(use_awaitable, ec));
      if (ec) co_return;  // the reader sees the failure too and ends the session
    }
  }

  template <class Ws>
  awaitable<void> handshake(Ws& ws, asio::ip::tcp::resolver& resolver) {
    const auto endpoints =
        co_await resolver.async_resolve(url.host, std::to_string(url.port), use_awaitable);
    beast::get_lowest_layer(ws).expires_after(options.connectTimeout);
    co_await beast::get_lowest_layer(ws).async_connect(endpoints, use_awaitable);
    co_await secureTransport(ws, url.host);
    beast::get_lowest_layer(ws).expires_never();
    websocket::stream_base::timeout timeouts{};
    timeouts.handshake_timeout = options.connectTimeout;
    timeouts.idle_timeout = std::chrono::seconds(10);
    timeouts.keep_alive_pings = true;
    ws.set_option(timeouts);
    ws.set_option(websocket::stream_base::decorator([token = options.token](auto& request) {
      request.set(beast::http::field::user_agent, "vemcast-client");
      if (!token.empty()) request.set(beast::http::field::authorization, "Bearer " + token);
    }));
    ws.read_message_max(stream::kMaxServerMessageBytes);
    ws.binary(true);
    websocket::response_type response;
    boost::system::error_code ec;
    co_await ws.async_handshake(response, url.hostHeader(), url.target,
                                asio::redirect_error(use_awaitable, ec));
    if (response.result() == beast::http::status::unauthorized ||
        response.result() == beast::http::status::forbidden) {
      throw ProtocolRefusal{
          fmt::format("the daemon refused the {} (HTTP {})",
                      options.token.empty() ? "connection without a token" : "token",
                      response.result_int()),
          true, false};
    }
    if (ec) throw beast::system_error(ec);
  }

  template <class Ws>
  awaitable<void> readLoop(Ws& ws, SessionEnd& end) {
    beast::flat_buffer buffer;
    for (bool first = true;; first = false) {
      buffer.clear();
      co_await ws.async_read(buffer, use_awaitable);
      if (ws.got_text()) throw ProtocolRefusal{"the daemon sent a text message", false};
      const auto data = buffer.cdata();
      DecodeResult decoded =
          decodeServerMessage(std::string_view(static_cast<const char*>(data.data()), data.size()));
      if (!decoded.ok()) throw ProtocolRefusal{decoded.error, decoded.unsupportedMajor};
      onEvent(decoded.event, first);
      if (first) end.established = true;
    }
  }

  // Closes `ws` with 1002 and the reason (cut to what a close frame holds), ignoring failures.
  template <class Ws>
  static awaitable<void> closeRefused(Ws& ws, const std::string& reason) {
    websocket::close_reason close(websocket::close_code::protocol_error);
    close.reason = reason.substr(0, 120);
    boost::system::error_code ec;
    co_await ws.async_close(close, asio::redirect_error(use_awaitable, ec));
  }

  template <class Ws, class... TransportArgs>
  awaitable<SessionEnd> session(TransportArgs&... transportArgs) {
    auto ws = std::make_shared<Ws>(co_await asio::this_coro::executor, transportArgs...);
    asio::ip::tcp::resolver resolver(co_await asio::this_coro::executor);
    cancelSession = [this, ws, &resolver] {
      resolver.cancel();
      boost::system::error_code ignored;
      beast::get_lowest_layer(*ws).socket().close(ignored);
      if (outbox) {
        outbox->open = false;
        outbox->wake.cancel();
      }
    };
    SessionEnd end;
    std::optional<ProtocolRefusal> refusal;
    try {
      co_await handshake(*ws, resolver);
      outbox = std::make_shared<Outbox>(co_await asio::this_coro::executor);
      asio::co_spawn(co_await asio::this_coro::executor, writeLoop(ws, outbox), asio::detached);
      co_await readLoop(*ws, end);
    } catch (const ProtocolRefusal& r) {
      refusal = r;
    } catch (const boost::system::system_error& e) {
      end.reason = connectionError(e.code());
    }
    if (outbox) {
      outbox->open = false;
      outbox->wake.cancel();
      outbox.reset();
    }
    if (closingLimit) closingLimit->cancel();
    if (refusal) {
      end.reason = refusal->reason;
      end.fatal = refusal->fatal;
    }
    if (refusal && refusal->decodeError && !stopping) {
      state.countDecodeError();
      co_await closeRefused(*ws, refusal->reason);
    }
    cancelSession = nullptr;
    co_return end;
  }

  std::string connectionError(const boost::system::error_code& ec) const {
    if (ec == websocket::error::closed) return "the daemon closed the connection";
    if (ec == asio::error::eof || ec == asio::error::connection_reset) {
      return fmt::format("the connection to {}:{} was lost ({})", url.host, url.port, ec.message());
    }
    return fmt::format("the connection to {}:{} failed: {}", url.host, url.port, ec.message());
  }

  awaitable<void> run() {
    util::Backoff backoff(options.initialBackoff, options.maxBackoff);
    asio::steady_timer timer(co_await asio::this_coro::executor);
    backoffTimer = &timer;
    while (!stopping) {
      state.setState(ConnectionState::Connecting, "");
      // Not a conditional expression: GCC 12 destroys co_await temporaries in one twice.
      SessionEnd end;
      if (tls) {
        end = co_await session<TlsWs>(*tls);
      } else {
        end = co_await session<PlainWs>();
      }
      state.failPendingControls("the connection to the daemon ended before it replied");
      if (stopping) break;
      if (end.established) backoff.reset();
      if (end.fatal) {
        state.setState(ConnectionState::Refused, end.reason);
        break;
      }
      const std::chrono::milliseconds delay = backoff.next();
      state.setState(ConnectionState::Waiting, end.reason);
      timer.expires_after(delay);
      boost::system::error_code ec;
      co_await timer.async_wait(asio::redirect_error(use_awaitable, ec));
    }
    backoffTimer = nullptr;
  }
};

void WebSocketTransport::start() {
  work.emplace(io->get_executor());
  asio::co_spawn(*io, run(), asio::detached);
  thread = std::thread([this] { io->run(); });
}

void WebSocketTransport::stop() {
  if (stopped) return;
  stopped = true;
  // The coroutines wind down on their own (destroying suspended ones with the I/O context is not
  // safe in Boost 1.74's Asio): cancel what they wait on, then let the context run dry.
  // A connected session ends with a closing handshake (bounded by kClosingHandshakeLimit), so the
  // daemon sees a client that left, not a lost connection; anything else is cancelled at once.
  asio::post(*io, [this] {
    stopping = true;
    if (backoffTimer != nullptr) backoffTimer->cancel();
    if (!outbox) {
      if (cancelSession) cancelSession();
      return;
    }
    outbox->closing = true;
    outbox->wake.cancel();
    closingLimit = std::make_unique<asio::steady_timer>(*io, kClosingHandshakeLimit);
    closingLimit->async_wait([this](boost::system::error_code ec) {
      if (!ec && cancelSession) cancelSession();
    });
  });
  work.reset();
  if (thread.joinable()) thread.join();
  outbox.reset();
  closingLimit.reset();
  io.reset();
}

std::future<ControlResult> WebSocketTransport::sendControl(const stream::Control& control) {
  std::promise<ControlResult> promise;
  std::future<ControlResult> future = promise.get_future();
  if (options.token.empty()) {
    promise.set_value(std::unexpected(
        std::string("control messages need the daemon's token; this client has none")));
    return future;
  }
  // Posted under the state's lock: stop() (which marks the state stopped first) cannot destroy the
  // I/O context meanwhile.
  const bool posted = state.whileLive([&] {
    asio::post(*io, [this, control, p = std::move(promise)]() mutable {
      sendControlNow(std::move(control), std::move(p));
    });
  });
  if (!posted) {
    promise.set_value(std::unexpected(std::string("the client is not connected to the daemon")));
  }
  return future;
}

}  // namespace

std::expected<std::unique_ptr<StreamTransport>, std::string> startWebSocketTransport(
    const StreamClientOptions& options, ClientState& state) {
  auto url = parseStreamUrl(options.url);
  if (!url) return std::unexpected(url.error());
  auto transport = std::make_unique<WebSocketTransport>(options, state, std::move(*url));
  if (transport->url.tls) {
    std::optional<asio::ssl::context>& tls = transport->tls;
    tls.emplace(asio::ssl::context::tls_client);
    tls->set_verify_mode(asio::ssl::verify_peer);
    boost::system::error_code ec;
    if (options.caFile.empty()) {
      tls->set_default_verify_paths(ec);
    } else {
      tls->load_verify_file(options.caFile, ec);
    }
    if (ec) {
      return std::unexpected(fmt::format("cannot load the CA certificates{}{}: {}",
                                         options.caFile.empty() ? "" : " of ", options.caFile,
                                         ec.message()));
    }
  }
  transport->start();
  return transport;
}

}  // namespace vem::client
