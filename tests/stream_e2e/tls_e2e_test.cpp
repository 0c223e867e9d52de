// TLS: with [stream] tls_cert and tls_key, vemd speaks wss:// (OpenSSL). A client that trusts the
// daemon's certificate receives light frames; one that does not never gets past the handshake.
#include <csignal>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "stream_e2e/stream_e2e_fixture.h"

namespace vem::e2e {
namespace {

client::StreamClientOptions wssOptions(std::uint16_t port, const std::string& caFile) {
  client::StreamClientOptions options;
  options.url = "wss://127.0.0.1:" + std::to_string(port);
  options.caFile = caFile;
  options.connectTimeout = 20s;
  return options;
}

// Catches a wss:// listener that does not speak TLS (a configured certificate ignored), and a
// client that does not verify the daemon's certificate: a self-signed certificate for 127.0.0.1
// made with the openssl tool; the client given it as its CA receives light frames, a client that
// trusts only the system's CAs is never connected and says why.
TEST_F(StreamE2eTest, WssServesAClientThatTrustsTheCertificateAndRefusesOneThatDoesNot) {
  const auto cert = dir_ / "cert.pem";
  const auto key = dir_ / "key.pem";
  const std::string makeCertificate =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=127.0.0.1 "
      "-addext subjectAltName=IP:127.0.0.1 -keyout '" + key.string() + "' -out '" +
      cert.string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(makeCertificate.c_str()), 0) << "openssl could not make a certificate";
  const auto port = startVemd({}, "[stream]\ntls_cert = \"" + cert.string() + "\"\ntls_key = \"" +
                                      key.string() + "\"\n");
  ASSERT_TRUE(port);
  ASSERT_NE(vemd_->stderrText().find("streaming on wss://"), std::string::npos)
      << "vemd did not say it listens with TLS";

  auto trusting = client::StreamClient::start(wssOptions(*port, cert.string()));
  ASSERT_TRUE(trusting.has_value()) << trusting.error();
  const auto frame = (*trusting)->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(frame.has_value()) << "no light frame over wss://: "
                                 << (*trusting)->stateReason();
  EXPECT_EQ(frame->frame.lights.lights.size(), kLightCount);

  auto untrusting = client::StreamClient::start(wssOptions(*port, ""));
  ASSERT_TRUE(untrusting.has_value()) << untrusting.error();
  EXPECT_FALSE((*untrusting)->waitForState(client::ConnectionState::Connected, 3s))
      << "a client connected to a self-signed daemon it had no reason to trust";
  EXPECT_FALSE((*untrusting)->waitForLightFrame(std::nullopt, 100ms).has_value());
  EXPECT_FALSE((*untrusting)->stateReason().empty());

  (*untrusting)->stop();
  (*trusting)->stop();
  expectCleanExit(SIGTERM);
}

}  // namespace
}  // namespace vem::e2e
