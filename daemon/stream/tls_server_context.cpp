#include "stream/tls_server_context.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>

#include "util/printable.h"

namespace vem::stream {

namespace ssl = boost::asio::ssl;

namespace {

// Why `path` cannot be read, or empty.
std::string unreadable(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) return "there is no such file";
  if (std::filesystem::is_directory(status)) return "it is a folder, not a file";
  if (::access(path.c_str(), R_OK) != 0) {
    return fmt::format("vemd cannot read it ({})", std::strerror(errno));
  }
  return {};
}

}  // namespace

std::expected<void, std::string> configureServerTls(ssl::context& context,
                                                    const std::string& certFile,
                                                    const std::string& keyFile) {
  if (certFile.empty() || keyFile.empty()) {
    return std::unexpected(std::string(
        "stream.tls_cert and stream.tls_key: give both (PEM files) for TLS, or neither"));
  }
  if (std::string why = unreadable(certFile); !why.empty()) {
    return std::unexpected(fmt::format("stream.tls_cert: {}: {}", util::printable(certFile), why));
  }
  if (std::string why = unreadable(keyFile); !why.empty()) {
    return std::unexpected(fmt::format("stream.tls_key: {}: {}", util::printable(keyFile), why));
  }
  context.set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                      ssl::context::no_sslv3 | ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1 |
                      ssl::context::no_compression);
  SSL_CTX* native = context.native_handle();
  SSL_CTX_set_min_proto_version(native, TLS1_2_VERSION);
  SSL_CTX_set_options(native,
                      SSL_OP_CIPHER_SERVER_PREFERENCE | SSL_OP_NO_RENEGOTIATION | SSL_OP_NO_TICKET);
  if (SSL_CTX_set_cipher_list(native, kTls12Ciphers) != 1) {
    return std::unexpected(
        std::string("stream: this OpenSSL offers none of vemd's TLS 1.2 ciphers"));
  }
  boost::system::error_code ec;
  context.use_certificate_chain_file(certFile, ec);
  if (ec) {
    return std::unexpected(
        fmt::format("stream.tls_cert: {}: not a usable PEM certificate chain ({})",
                    util::printable(certFile), ec.message()));
  }
  context.use_private_key_file(keyFile, ssl::context::pem, ec);
  if (ec && ec.category() == boost::asio::error::get_ssl_category() &&
      ERR_GET_REASON(static_cast<unsigned long>(ec.value())) == X509_R_KEY_VALUES_MISMATCH) {
    return std::unexpected(fmt::format("stream.tls_key: {} is not the key of the certificate in {}",
                                       util::printable(keyFile), util::printable(certFile)));
  }
  if (ec) {
    return std::unexpected(fmt::format("stream.tls_key: {}: not a usable PEM private key ({})",
                                       util::printable(keyFile), ec.message()));
  }
  if (SSL_CTX_check_private_key(native) != 1) {
    return std::unexpected(fmt::format("stream.tls_key: {} is not the key of the certificate in {}",
                                       util::printable(keyFile), util::printable(certFile)));
  }
  return {};
}

}  // namespace vem::stream
