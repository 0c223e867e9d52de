// [stream] in vemd's configuration (vemd_config.h) and the start-up checks of stream_setup.h:
// listen addresses, tokens beyond loopback, token files' permissions, TLS file pairs.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "stream/stream_setup.h"
#include "vemd/vemd_config.h"

namespace vem::stream {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& toml) {
  auto config = vemd::parseConfig(toml, "vemd.toml");
  return config ? std::string("accepted") : config.error();
}

TEST(StreamConfig, DefaultsListenOnLoopback8765) {
  auto config = vemd::parseConfig("", "vemd.toml");
  ASSERT_TRUE(config.has_value());
  EXPECT_TRUE(config->stream.enabled);
  EXPECT_EQ(config->stream.listen, "127.0.0.1:8765");
  EXPECT_EQ(config->stream.maxClients, 64);
}

TEST(StreamConfig, BadListenAddressIsRefusedInOneSentence) {
  EXPECT_EQ(refusal("[stream]\nlisten = \"localhost:8765\"\n"),
            "vemd.toml: stream.listen: expected \"IPV4:PORT\" or \"[IPV6]:PORT\" (an IP address, "
            "port 0 to 65535), or \"\" (no server), found the string \"localhost:8765\"");
  EXPECT_NE(refusal("[stream]\nlisten = \"127.0.0.1:70000\"\n"), "accepted");
  EXPECT_NE(refusal("[stream]\nlisten = \"127.0.0.1\"\n"), "accepted");
  EXPECT_NE(refusal("[stream]\nlisten = \"::1:80\"\n"), "accepted");
  EXPECT_EQ(refusal("[stream]\nlisten = \"[::1]:0\"\n"), "accepted");
  EXPECT_EQ(refusal("[stream]\nlisten = \"\"\n"), "accepted");
}

TEST(StreamConfig, NonLoopbackWithoutTokenIsRefused) {
  const std::string problem = refusal("[stream]\nlisten = \"0.0.0.0:8765\"\n");
  EXPECT_NE(problem.find("stream.listen"), std::string::npos) << problem;
  EXPECT_NE(problem.find("needs a token"), std::string::npos) << problem;
  EXPECT_EQ(refusal("[stream]\nlisten = \"0.0.0.0:8765\"\ntoken = \"t\"\n"), "accepted");
  EXPECT_EQ(refusal("[stream]\nenabled = false\nlisten = \"0.0.0.0:8765\"\n"), "accepted");
}

TEST(StreamConfig, NonLoopbackFlagWithoutTokenIsRefused) {
  auto parsed = vemd::parseCommandLine({"vemd", "--stream-listen", "192.168.1.2:8765"});
  ASSERT_FALSE(parsed.has_value());
  EXPECT_EQ(parsed.error().exitCode, 2);
  EXPECT_NE(parsed.error().err.find("beyond loopback"), std::string::npos);
}

TEST(StreamConfig, OnlyOneTlsFileIsRefused) {
  EXPECT_NE(refusal("[stream]\ntls_cert = \"a.pem\"\n"), "accepted");
}

TEST(StreamConfig, ListenAddressLoopbackIsRecognised) {
  EXPECT_TRUE(vemd::parseListenAddress("127.0.0.1:1")->loopback);
  EXPECT_TRUE(vemd::parseListenAddress("127.3.2.1:1")->loopback);
  EXPECT_TRUE(vemd::parseListenAddress("[::1]:1")->loopback);
  EXPECT_FALSE(vemd::parseListenAddress("0.0.0.0:1")->loopback);
  EXPECT_FALSE(vemd::parseListenAddress("[::]:1")->loopback);
  EXPECT_EQ(vemd::parseListenAddress("[::1]:8765")->host, "::1");
}

class TokenFile : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = fs::temp_directory_path() / ("vem-stream-token-" + std::to_string(::getpid()));
    std::ofstream(path_) << "  s3cret\n";
  }
  void TearDown() override { fs::remove(path_); }
  fs::path path_;
};

TEST_F(TokenFile, WorldReadableTokenFileIsRefused) {
  ::chmod(path_.c_str(), 0644);
  auto token = readTokenFile(path_);
  ASSERT_FALSE(token.has_value());
  EXPECT_NE(token.error().find("group or others"), std::string::npos) << token.error();
}

TEST_F(TokenFile, GroupReadableTokenFileIsRefused) {
  ::chmod(path_.c_str(), 0640);
  EXPECT_FALSE(readTokenFile(path_).has_value());
}

TEST_F(TokenFile, OwnerOnlyTokenFileGivesTheTrimmedToken) {
  ::chmod(path_.c_str(), 0600);
  auto token = readTokenFile(path_);
  ASSERT_TRUE(token.has_value()) << token.error();
  EXPECT_EQ(*token, "s3cret");
}

TEST_F(TokenFile, ServerOptionsTakeTheFilesTokenAndRequireItBeyondLoopback) {
  ::chmod(path_.c_str(), 0600);
  vemd::StreamConfig config;
  config.listen = "0.0.0.0:0";
  config.tokenFile = path_.string();
  auto options = serverOptions(config, {});
  ASSERT_TRUE(options.has_value()) << options.error();
  EXPECT_EQ(options->token, "s3cret");
  EXPECT_TRUE(options->tokenRequiredToConnect);
  config.listen = "127.0.0.1:0";
  EXPECT_FALSE(serverOptions(config, {})->tokenRequiredToConnect);
}

// Issue 16: the limits that keep clients from slowing vemd are settings, and reach the server.
TEST(StreamConfig, HardeningKeysReachTheServerOptions) {
  auto config = vemd::parseConfig(
      "[stream]\nhandshake_timeout_ms = 750\nmax_handshakes = 40\nmax_handshakes_per_address = 5\n"
      "max_client_lag_ms = 2500\nsend_buffer_bytes = 65536\ncubemap_max_face_px = 128\n"
      "cubemap_max_rate_hz = 2.5\n",
      "vemd.toml");
  ASSERT_TRUE(config.has_value()) << config.error();
  auto options = serverOptions(config->stream, {});
  ASSERT_TRUE(options.has_value()) << options.error();
  EXPECT_EQ(options->handshakeTimeout, std::chrono::milliseconds(750));
  EXPECT_EQ(options->maxHandshakes, 40u);
  EXPECT_EQ(options->maxHandshakesPerAddress, 5u);
  EXPECT_EQ(options->maxClientLag, std::chrono::milliseconds(2500));
  EXPECT_EQ(options->sendBufferBytes, 65536);
  EXPECT_EQ(options->cubemapBudget, (CubemapBudget{128, 2.5}));
}

TEST(StreamConfig, HardeningKeysOutOfRangeAreRefusedInOneSentence) {
  EXPECT_EQ(refusal("[stream]\ncubemap_max_face_px = 1024\n"),
            "vemd.toml: stream.cubemap_max_face_px: expected a whole number from 64 to 512, found "
            "1024");
  EXPECT_NE(refusal("[stream]\nhandshake_timeout_ms = 0\n"), "accepted");
  EXPECT_NE(refusal("[stream]\nmax_handshakes_per_address = 0\n"), "accepted");
  EXPECT_NE(refusal("[stream]\ncubemap_max_rate_hz = 61\n"), "accepted");
  EXPECT_NE(refusal("[stream]\nsend_buffer_bytes = 100\n"), "accepted");
}

TEST(StreamConfig, MissingTlsFilesFailAtStart) {
  StreamServerOptions options;
  options.port = 0;
  options.tlsCertFile = "/nonexistent/cert.pem";
  options.tlsKeyFile = "/nonexistent/key.pem";
  auto server = StreamServer::start(options);
  ASSERT_FALSE(server.has_value());
  EXPECT_NE(server.error().find("stream.tls_cert"), std::string::npos) << server.error();
}

}  // namespace
}  // namespace vem::stream
