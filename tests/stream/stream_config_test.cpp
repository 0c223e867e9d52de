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
  EXPECT_EQ(refusal("[stream]\nlisten = \"0.0.0.0:8765\"\ntoken = \"4f1c9a7e2b8d6053\"\n"),
            "accepted");
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

constexpr const char* kFileToken = "9b2e71c04fd3a865e0c7";

class TokenFile : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = fs::temp_directory_path() / ("vem-stream-token-" + std::to_string(::getpid()));
    std::ofstream(path_) << "  " << kFileToken << "\n";
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
  EXPECT_EQ(*token, kFileToken);
}

TEST_F(TokenFile, ServerOptionsTakeTheFilesTokenAndRequireItBeyondLoopback) {
  ::chmod(path_.c_str(), 0600);
  vemd::StreamConfig config;
  config.listen = "0.0.0.0:0";
  config.tokenFile = path_.string();
  auto options = serverOptions(config, {});
  ASSERT_TRUE(options.has_value()) << options.error();
  EXPECT_EQ(options->token, kFileToken);
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

// Catches a typed word accepted as the token (issue 16: one character was): the sentence names the
// key, what is expected and the token's length, never the token.
TEST(StreamToken, ShortTokenIsRefusedNamingTheKeyWithoutQuotingIt) {
  const std::string problem = refusal("[stream]\ntoken = \"s3cret\"\n");
  EXPECT_EQ(problem,
            "vemd.toml: stream.token: expected a token of 16 to 1024 visible ASCII characters "
            "without white space (`openssl rand -hex 32` makes one), found a token of 6 bytes");
  EXPECT_EQ(problem.find("s3cret"), std::string::npos);
}

// Catches the shortest-token rule being off by one.
TEST(StreamToken, FifteenCharactersAreRefusedAndSixteenAccepted) {
  EXPECT_NE(refusal("[stream]\ntoken = \"0123456789abcde\"\n"), "accepted");
  EXPECT_EQ(refusal("[stream]\ntoken = \"0123456789abcdef\"\n"), "accepted");
  EXPECT_NE(refusal("[stream]\ntoken = \"" + std::string(1025, 'x') + "\"\n"), "accepted");
  EXPECT_EQ(refusal("[stream]\ntoken = \"" + std::string(1024, 'x') + "\"\n"), "accepted");
}

// Catches the white-space token: on 0.0.0.0 vemd started and every client got 401 (HTTP
// trims the header). Refused on loopback too, where the token grants control.
TEST(StreamToken, WhiteSpaceOnlyTokenIsRefusedOnAnyListener) {
  EXPECT_EQ(refusal("[stream]\nlisten = \"0.0.0.0:8765\"\ntoken = \"    \"\n"),
            "vemd.toml: stream.token: expected a token of 16 to 1024 visible ASCII characters "
            "without white space (`openssl rand -hex 32` makes one), found white space at byte 1 "
            "of 4");
  EXPECT_NE(refusal("[stream]\nlisten = \"127.0.0.1:8765\"\ntoken = \"\\t\"\n"), "accepted");
}

// Catches white space or control and non-ASCII bytes inside a long token: no client could present
// it through HTTP as written.
TEST(StreamToken, WhiteSpaceOrControlBytesInsideALongTokenAreRefused) {
  EXPECT_NE(
      refusal("[stream]\ntoken = \"0123456789 abcdef\"\n").find("white space at byte 11 of 17"),
      std::string::npos);
  EXPECT_NE(refusal("[stream]\ntoken = \"0123456789\\nabcdef\"\n").find("white space at byte 11"),
            std::string::npos);
  EXPECT_NE(refusal("[stream]\ntoken = \"0123456789\\u0007abcdef\"\n")
                .find("a control or non-ASCII byte at byte 11 of 17"),
            std::string::npos);
  EXPECT_NE(refusal("[stream]\ntoken = \"0123456789\u00e9abcdef\"\n")
                .find("a control or non-ASCII byte at byte 11 of 18"),
            std::string::npos);
}

// Catches a token file whose token is too short being accepted: the sentence names the key and the
// file, not the token.
TEST_F(TokenFile, ShortTokenInTheFileIsRefusedNamingTheFile) {
  std::ofstream(path_) << "s3cret\n";
  ::chmod(path_.c_str(), 0600);
  auto token = readTokenFile(path_);
  ASSERT_FALSE(token.has_value());
  EXPECT_EQ(token.error(), "stream.token_file: " + path_.string() +
                               ": expected a token of 16 to 1024 visible ASCII characters without "
                               "white space (`openssl rand -hex 32` makes one), found a token of "
                               "6 bytes");
}

// Catches a token file with two words (or a stray line) being taken whole: only the white space
// around the token is trimmed.
TEST_F(TokenFile, WhiteSpaceInsideTheFilesTokenIsRefused) {
  std::ofstream(path_) << "9b2e71c04fd3a865\ne0c7a1b2c3d4e5f6\n";
  ::chmod(path_.c_str(), 0600);
  auto token = readTokenFile(path_);
  ASSERT_FALSE(token.has_value());
  EXPECT_NE(token.error().find("found white space at byte 17 of 33"), std::string::npos)
      << token.error();
}

// Catches a file name from outside reaching the message raw: control bytes in it are escaped.
TEST(StreamToken, TokenFileNameIsEscapedInTheMessage) {
  auto token = readTokenFile("/nonexistent/tok\x1b[2Jen");
  ASSERT_FALSE(token.has_value());
  EXPECT_EQ(token.error(), "stream.token_file: /nonexistent/tok\\x1b[2Jen: cannot read it");
}

// Catches a StreamConfig made in code bypassing the token rule the configuration file applies.
TEST(StreamToken, ServerOptionsRefuseAShortTokenGivenInCode) {
  vemd::StreamConfig config;
  config.listen = "127.0.0.1:0";
  config.token = "t";
  auto options = serverOptions(config, {});
  ASSERT_FALSE(options.has_value());
  EXPECT_NE(options.error().find("stream.token: expected a token of 16"), std::string::npos)
      << options.error();
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
