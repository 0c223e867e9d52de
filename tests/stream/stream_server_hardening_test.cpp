// The stream server against hostile and slow clients (issue 16): half-sent upgrade requests,
// floods from one address, a burst of connections over the cap, clients that read slowly or never,
// forged log lines, connection churn, the read-only cube-map budget and the TLS policy. Real server
// on 127.0.0.1 port 0, Beast clients and raw sockets. Each test names the bug it catches; waits are
// for events (a count, a closed socket), bounded so that a broken server fails instead of hanging.
#include <sys/socket.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>
#include <boost/asio/connect.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/write.hpp>

#include "stream/frame_encoding.h"
#include "stream/stream_server.h"
#include "ws_test_client.h"

namespace vem::stream {
namespace {

using testing::eventually;
using testing::WsTestClient;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

std::unique_ptr<StreamServer> startServer(StreamServerOptions options = {}) {
  spdlog::set_level(spdlog::level::warn);
  options.address = "127.0.0.1";
  options.port = 0;
  auto server = StreamServer::start(std::move(options));
  EXPECT_TRUE(server.has_value()) << server.error();
  return std::move(*server);
}

StreamServerOptions loopback() {
  StreamServerOptions options;
  options.address = "127.0.0.1";
  options.port = 0;
  return options;
}

SharedBytes lightsMessage(std::uint64_t seq, int lights = 16) {
  ServerMessage message;
  LightFrame& frame = *message.mutable_lights();
  frame.set_seq(seq);
  frame.set_publish_unix_ns(unixNowNs());
  for (int i = 0; i < lights; ++i) {
    frame.add_ids(std::uint32_t(i));
    for (int k = 0; k < 3; ++k) {
      frame.add_dirs(k == 1 ? 1.0F : 0.0F);
      frame.add_rgb(1.0F);
    }
  }
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

// A plain TCP connection that says only what the test makes it say.
class RawSocket {
 public:
  explicit RawSocket(std::uint16_t port, const std::string& source = "127.0.0.1") {
    boost::system::error_code ec;
    socket_.open(tcp::v4(), ec);
    if (!ec) socket_.bind({asio::ip::make_address(source), 0}, ec);
    if (!ec) socket_.connect({asio::ip::make_address("127.0.0.1"), port}, ec);
    connected_ = !ec;
    timeval limit{20, 0};  // a broken server fails the test instead of hanging it
    ::setsockopt(socket_.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
  }
  [[nodiscard]] bool connected() const { return connected_; }
  bool send(const std::string& text) {
    boost::system::error_code ec;
    asio::write(socket_, asio::buffer(text), ec);
    return !ec;
  }
  // The answer's status line (without waiting for the server to close).
  std::string statusLine() {
    std::string text;
    char buffer[256];
    while (text.find("\r\n") == std::string::npos) {
      const ssize_t n = ::recv(socket_.native_handle(), buffer, sizeof buffer, 0);
      if (n <= 0) break;
      text.append(buffer, std::size_t(n));
    }
    return text.substr(0, text.find("\r\n"));
  }
  // Everything until the server closes (or 20 s pass).
  std::string readAll() {
    std::string text;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::recv(socket_.native_handle(), buffer, sizeof buffer, 0);
      if (n <= 0) break;
      text.append(buffer, std::size_t(n));
    }
    return text;
  }

 private:
  asio::io_context ioc_;
  tcp::socket socket_{ioc_};
  bool connected_ = false;
};

std::string upgradeRequest() {
  return "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
         "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n";
}

// Every log line of the default logger while it lives.
class CapturedLog {
 public:
  CapturedLog() {
    previous_ = spdlog::default_logger();
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(text_);
    auto logger = std::make_shared<spdlog::logger>("vemd", sink);
    logger->set_pattern("vemd %l: %v");
    logger->set_level(spdlog::level::info);
    spdlog::set_default_logger(logger);
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  std::string text() {
    spdlog::default_logger()->flush();
    return text_.str();
  }
  std::size_t linesContaining(const std::string& needle) {
    std::istringstream lines(text());
    std::size_t count = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.find(needle) != std::string::npos) ++count;
    }
    return count;
  }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::logger> previous_;
};

// ---- item 2: a slowloris flood ----

TEST(StreamServerHardening, HalfSentUpgradeRequestIsClosedAtTheHandshakeDeadlineAndCounted) {
  StreamServerOptions options;
  options.handshakeTimeout = std::chrono::milliseconds(200);
  auto server = startServer(options);
  RawSocket slow(server->boundPort());
  ASSERT_TRUE(slow.connected());
  ASSERT_TRUE(slow.send("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n"));  // and never the rest
  EXPECT_EQ(slow.readAll(), "");  // closed without an answer: there was no request to answer
  EXPECT_TRUE(eventually([&] { return server->counters().handshakesTimedOut == 1; }));
  EXPECT_EQ(server->counters().handshakes, 0u);
}

TEST(StreamServerHardening, AFloodFromOneAddressIsAnswered503AtItsCapWhileAnotherAddressConnects) {
  StreamServerOptions options;
  options.maxHandshakesPerAddress = 4;
  options.handshakeTimeout = std::chrono::minutes(5);  // the flood holds its slots
  auto server = startServer(options);
  std::vector<std::unique_ptr<RawSocket>> flood;
  for (int i = 0; i < 4; ++i) {
    flood.push_back(std::make_unique<RawSocket>(server->boundPort(), "127.0.0.2"));
    ASSERT_TRUE(flood.back()->connected());
    ASSERT_TRUE(flood.back()->send("GET / HTTP/1.1\r\n"));
  }
  ASSERT_TRUE(eventually([&] { return server->counters().handshakes == 4; }));
  WsTestClient fifth;
  EXPECT_EQ(fifth.connect(server->boundPort(), "/", std::nullopt, "127.0.0.2"), 503);
  EXPECT_EQ(server->counters().refusedBusyAddress, 1u);
  WsTestClient legit;
  EXPECT_EQ(legit.connect(server->boundPort(), "/", std::nullopt, "127.0.0.1"), 0);
}

TEST(StreamServerHardening, AFullHandshakeTableEvictsTheFloodNotTheNewcomer) {
  StreamServerOptions options;
  options.maxHandshakes = 6;
  options.maxHandshakesPerAddress = 6;
  options.handshakeTimeout = std::chrono::minutes(5);
  auto server = startServer(options);
  std::vector<std::unique_ptr<RawSocket>> flood;
  for (int i = 0; i < 6; ++i) {
    flood.push_back(std::make_unique<RawSocket>(server->boundPort(), "127.0.0.3"));
    ASSERT_TRUE(flood.back()->send("GET / HTTP/1.1\r\n"));
  }
  ASSERT_TRUE(eventually([&] { return server->counters().handshakes == 6; }));
  WsTestClient legit;
  EXPECT_EQ(legit.connect(server->boundPort()), 0);
  EXPECT_EQ(server->counters().handshakesEvicted, 1u);
  EXPECT_EQ(flood.front()->readAll(), "");  // the oldest of the flood was closed
}

// ---- item 4: every refused connection is answered ----

TEST(StreamServerHardening, TwoHundredConnectionsAtOnceAreEachAnswered101Or503) {
  StreamServerOptions options;
  options.maxClients = 4;
  options.maxHandshakes = 16;
  options.maxHandshakesPerAddress = 8;
  auto server = startServer(options);
  constexpr int kConnections = 200;
  std::vector<std::unique_ptr<RawSocket>> sockets;
  for (int i = 0; i < kConnections; ++i) {
    sockets.push_back(std::make_unique<RawSocket>(server->boundPort()));
  }
  for (auto& socket : sockets) ASSERT_TRUE(socket->send(upgradeRequest()));
  int upgraded = 0, refused = 0;
  for (auto& socket : sockets) {
    const std::string answer = socket->statusLine();
    if (answer.starts_with("HTTP/1.1 101")) {
      ++upgraded;
    } else if (answer.starts_with("HTTP/1.1 503")) {
      ++refused;
    } else {
      ADD_FAILURE() << "no answer: \"" << answer << "\"";
    }
  }
  EXPECT_LE(upgraded, 4);
  EXPECT_EQ(upgraded + refused, kConnections);
  EXPECT_EQ(server->counters().closedUnanswered, 0u);
}

// ---- item 3: a slow reader ----

TEST(StreamServerHardening, AClientThatStopsReadingGetsTheNewestFrameNotABacklog) {
  StreamServerOptions options;
  options.maxClientLag = std::chrono::minutes(5);  // held, not closed, for this test
  auto server = startServer(options);
  WsTestClient sleeper;
  ASSERT_EQ(sleeper.connect(server->boundPort()), 0);
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 1; }));
  // 300 frames over about 0.6 s while the client reads nothing (a camera at 500 Hz).
  constexpr std::uint64_t kFrames = 300;
  for (std::uint64_t seq = 0; seq < kFrames; ++seq) {
    server->publishLights(lightsMessage(seq, 64));
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  // Then it reads: the last frame comes soon, after the few that were on their way.
  int received = 0;
  for (;;) {
    auto seq = sleeper.nextLightsSeq();
    ASSERT_TRUE(seq);
    ++received;
    if (*seq == kFrames - 1) break;
  }
  // Without pacing every frame went into the socket's buffers (300 received, the last one
  // about a backlog late); with it, only those sent before the client was seen to lag.
  EXPECT_LT(received, int(kFrames) / 2);
  EXPECT_GT(server->counters().lightsSkipped, kFrames / 2);
}

TEST(StreamServerHardening, AClientThatNeverReadsIsToldItIsTooSlowAndClosed) {
  StreamServerOptions options;
  options.maxClientLag = std::chrono::milliseconds(300);
  options.sendTimeout = std::chrono::minutes(5);  // the lag, not a stuck write, closes it
  auto server = startServer(options);
  WsTestClient stuck, reader;
  ASSERT_EQ(stuck.connect(server->boundPort()), 0);
  ASSERT_EQ(reader.connect(server->boundPort()), 0);
  std::uint64_t seq = 0;
  ASSERT_TRUE(eventually([&] {
    server->publishLights(lightsMessage(seq));
    EXPECT_EQ(reader.nextLightsSeq(), seq);
    ++seq;
    return server->counters().closedTooSlow == 1;
  }));
  int readAfter = 0;
  while (stuck.read()) ++readAfter;
  EXPECT_EQ(stuck.closeCode(), 1008) << stuck.error() << " after " << readAfter;
  EXPECT_TRUE(stuck.closeReason().starts_with("the client reads too slowly"))
      << stuck.closeReason();
  server->publishLights(lightsMessage(seq));
  EXPECT_EQ(reader.nextLightsSeq(), seq);  // the other client never noticed
}

// ---- items 5 and 6: the log ----

TEST(StreamServerHardening, CloseReasonWithANewlineCannotForgeALogLine) {
  CapturedLog log;
  auto server = StreamServer::start(loopback());
  ASSERT_TRUE(server.has_value());
  {
    WsTestClient client;
    ASSERT_EQ(client.connect((*server)->boundPort()), 0);
    client.closeWith("bye\nvemd info: FAKE LINE");
  }
  ASSERT_TRUE(eventually(
      [&] { return log.text().find("the client closed the connection") != std::string::npos; }));
  const std::string text = log.text();
  EXPECT_NE(text.find("bye\\nvemd info: FAKE LINE"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nvemd info: FAKE LINE"), std::string::npos) << text;
}

TEST(StreamServerHardening, ConnectionChurnIsLoggedWithinTheBudgetNotOnceAConnection) {
  CapturedLog log;
  auto server = StreamServer::start(loopback());
  ASSERT_TRUE(server.has_value());
  constexpr int kConnections = 100;
  for (int i = 0; i < kConnections; ++i) {
    WsTestClient client;
    ASSERT_EQ(client.connect((*server)->boundPort()), 0);
    client.close();
  }
  ASSERT_TRUE(eventually([&] { return (*server)->counters().clients == 0; }));
  EXPECT_EQ((*server)->counters().accepted, std::uint64_t(kConnections));
  EXPECT_LE(log.linesContaining("connected from"), 10u);
  EXPECT_LE(log.linesContaining(") gone: "), 10u);
}

// ---- item 1: the read-only budget reaches the server ----

TEST(StreamServerHardening, ReadOnlyClientOverTheCubemapBudgetIsRefusedTokenHolderIsNot) {
  StreamServerOptions options;
  options.token = "a-token-long-enough-0123456789";
  options.cubemapBudget = {128, 5.0};
  auto server = startServer(options);
  ClientMessage subscribe;
  subscribe.set_request_id(1);
  subscribe.mutable_subscribe()->set_lights(true);
  subscribe.mutable_subscribe()->set_cubemap_face_px(512);
  subscribe.mutable_subscribe()->set_cubemap_rate_hz(60.0);
  WsTestClient readOnly, withToken;
  ASSERT_EQ(readOnly.connect(server->boundPort()), 0);
  ASSERT_EQ(withToken.connect(server->boundPort(), "/", options.token), 0);
  ASSERT_TRUE(readOnly.send(subscribe));
  auto refused = readOnly.nextReply();
  ASSERT_TRUE(refused);
  EXPECT_FALSE(refused->ok());
  ASSERT_TRUE(withToken.send(subscribe));
  auto accepted = withToken.nextReply();
  ASSERT_TRUE(accepted);
  EXPECT_TRUE(accepted->ok()) << accepted->message();
  const CubemapDemand demand = server->cubemapDemand();
  ASSERT_EQ(demand.variants.size(), 1u);
  EXPECT_EQ(demand.variants[0].variant.facePx, 512);
}

// ---- item 11: TLS ----

class TlsFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() / ("vem-tls-policy-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    const std::string make =
        "openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=127.0.0.1 -keyout " +
        (dir_ / "key.pem").string() + " -out " + (dir_ / "cert.pem").string() + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(make.c_str()), 0) << "openssl could not make a certificate";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Whether a TLS 1.2 client offering only `ciphers` completes a handshake with the server.
  static bool handshakeWith(std::uint16_t port, const char* ciphers) {
    asio::ssl::context context(asio::ssl::context::tls_client);
    SSL_CTX_set_max_proto_version(context.native_handle(), TLS1_2_VERSION);
    if (SSL_CTX_set_cipher_list(context.native_handle(), ciphers) != 1) return false;
    context.set_verify_mode(asio::ssl::verify_none);
    asio::io_context ioc;
    asio::ssl::stream<tcp::socket> stream(ioc, context);
    boost::system::error_code ec;
    stream.next_layer().connect({asio::ip::make_address("127.0.0.1"), port}, ec);
    if (ec) return false;
    stream.handshake(asio::ssl::stream_base::client, ec);
    return !ec;
  }

  std::filesystem::path dir_;
};

TEST_F(TlsFiles, Tls12RefusesStaticRsaKeyExchangeAndCbcWithSha1) {
  StreamServerOptions options;
  options.tlsCertFile = (dir_ / "cert.pem").string();
  options.tlsKeyFile = (dir_ / "key.pem").string();
  auto server = startServer(options);
  EXPECT_FALSE(handshakeWith(server->boundPort(), "AES128-SHA"));         // static RSA, CBC, SHA-1
  EXPECT_FALSE(handshakeWith(server->boundPort(), "AES256-GCM-SHA384"));  // static RSA
  EXPECT_FALSE(handshakeWith(server->boundPort(), "ECDHE-RSA-AES128-SHA"));  // CBC, SHA-1
  EXPECT_TRUE(handshakeWith(server->boundPort(), "ECDHE-RSA-AES128-GCM-SHA256"));
  EXPECT_TRUE(handshakeWith(server->boundPort(), "ECDHE-RSA-CHACHA20-POLY1305"));
}

TEST_F(TlsFiles, AMissingCertificateIsNamedAsMissingNotAsABadPem) {
  StreamServerOptions options;
  options.port = 0;
  options.tlsCertFile = (dir_ / "no-such-cert.pem").string();
  options.tlsKeyFile = (dir_ / "key.pem").string();
  auto server = StreamServer::start(options);
  ASSERT_FALSE(server.has_value());
  EXPECT_EQ(server.error(), "stream.tls_cert: " + options.tlsCertFile + ": there is no such file");
}

TEST_F(TlsFiles, AKeyThatIsNotTheCertificatesIsRefused) {
  const std::string other = (dir_ / "other-key.pem").string();
  ASSERT_EQ(std::system(("openssl genrsa -out " + other + " 2048 >/dev/null 2>&1").c_str()), 0);
  StreamServerOptions options;
  options.port = 0;
  options.tlsCertFile = (dir_ / "cert.pem").string();
  options.tlsKeyFile = other;
  auto server = StreamServer::start(options);
  ASSERT_FALSE(server.has_value());
  EXPECT_TRUE(server.error().starts_with("stream.tls_key: " + other + " is not the key of"))
      << server.error();
}

}  // namespace
}  // namespace vem::stream
