// The TLS context of vemd's stream server (wss://): the certificate chain and private key from PEM
// files, and the server's TLS policy:
// - TLS 1.2 and 1.3 only;
// - TLS 1.2 with forward-secret AEAD suites only (ECDHE with AES-GCM or ChaCha20-Poly1305): no
//   static-RSA key exchange, no CBC, no SHA-1 MACs; the server's order of preference wins;
// - TLS 1.3 with OpenSSL's default suites (all AEAD);
// - no renegotiation, no compression, no session tickets.
// This is Mozilla's "intermediate" server configuration for TLS 1.2 (docs/vemd.md, "TLS").
// A file that is missing, unreadable or not PEM is refused in one sentence naming the key and the
// file.
#pragma once

#include <expected>
#include <string>

#include <boost/asio/ssl/context.hpp>

namespace vem::stream {

// The TLS 1.2 cipher list vemd offers, in OpenSSL's syntax.
inline constexpr const char* kTls12Ciphers =
    "ECDHE-ECDSA-AES128-GCM-SHA256:ECDHE-RSA-AES128-GCM-SHA256:ECDHE-ECDSA-AES256-GCM-SHA384:"
    "ECDHE-RSA-AES256-GCM-SHA384:ECDHE-ECDSA-CHACHA20-POLY1305:ECDHE-RSA-CHACHA20-POLY1305";

// Sets the policy on `context` (a tls_server context) and loads the two files.
[[nodiscard]] std::expected<void, std::string> configureServerTls(
    boost::asio::ssl::context& context, const std::string& certFile, const std::string& keyFile);

}  // namespace vem::stream
