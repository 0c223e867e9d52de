#include "util/mosquitto_client.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>
#include <openssl/x509.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>

#include <fmt/format.h>

namespace vem::util {
namespace {

std::string randomClientId() {
  std::random_device random;
  const std::uint64_t bits = (std::uint64_t(random()) << 32) | random();
  return fmt::format("vemcast-{:012x}", bits & 0xffff'ffff'ffffULL);  // 20 characters: MQTT 3's 23
}

bool readable(const std::string& path) { return std::ifstream(path).good(); }

// OpenSSL's directory of the system's CA certificates ($SSL_CERT_DIR first), as a CA path: the
// system's CAs for libmosquitto 2.0.11, whose MOSQ_OPT_TLS_USE_OS_CERTS fails every reconnection.
std::string systemCaDirectory() {
  const char* fromEnvironment = std::getenv(X509_get_default_cert_dir_env());
  return fromEnvironment != nullptr && *fromEnvironment != '\0' ? fromEnvironment
                                                                : X509_get_default_cert_dir();
}

std::expected<void, std::string> setUpTls(mosquitto* client, const MqttSecurity& s) {
  if (!s.caFile.empty() && !readable(s.caFile)) {
    return std::unexpected(fmt::format("cannot read the CA certificates of {}", s.caFile));
  }
  if (!s.certFile.empty() && !readable(s.certFile)) {
    return std::unexpected(fmt::format("cannot read the client certificate {}", s.certFile));
  }
  if (!s.keyFile.empty() && !readable(s.keyFile)) {
    return std::unexpected(fmt::format("cannot read the client key {}", s.keyFile));
  }
  const std::string caDirectory = s.caFile.empty() ? systemCaDirectory() : "";
  const auto noPassphrase = [](char*, int, int, void*) { return 0; };  // never a prompt
  const int rc = mosquitto_tls_set(client, s.caFile.empty() ? nullptr : s.caFile.c_str(),
                                   caDirectory.empty() ? nullptr : caDirectory.c_str(),
                                   s.certFile.empty() ? nullptr : s.certFile.c_str(),
                                   s.keyFile.empty() ? nullptr : s.keyFile.c_str(), noPassphrase);
  if (rc != MOSQ_ERR_SUCCESS) {
    return std::unexpected(fmt::format("cannot set up TLS: {}", mosquitto_strerror(rc)));
  }
  return {};
}

std::expected<void, std::string> setUp(mosquitto* client, const MqttUrl& url,
                                       const MqttSecurity& s) {
  mosquitto_int_option(client, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V5);
  // Nagle's algorithm off: a light frame written while the previous one waits for its ACK would
  // otherwise wait for the broker's delayed ACK (p99 13 ms instead of 3 on loopback,
  // docs/BENCHMARKS.md, "MQTT fan-out").
  mosquitto_int_option(client, MOSQ_OPT_TCP_NODELAY, 1);
  if (!s.username.empty() && !url.username.empty() && s.username != url.username) {
    return std::unexpected(fmt::format("the user name is given twice: '{}' in the address and '{}'",
                                       url.username, s.username));
  }
  const std::string& username = s.username.empty() ? url.username : s.username;
  if (!s.password.empty() && username.empty()) {
    return std::unexpected("a password needs a user name (USER@ in the address, or --username)");
  }
  if (!username.empty()) {
    const int rc = mosquitto_username_pw_set(client, username.c_str(),
                                             s.password.empty() ? nullptr : s.password.c_str());
    if (rc != MOSQ_ERR_SUCCESS) {
      return std::unexpected(fmt::format("cannot use the user name: {}", mosquitto_strerror(rc)));
    }
  }
  if (s.certFile.empty() != s.keyFile.empty()) {
    return std::unexpected("a client certificate needs its key, and a key its certificate");
  }
  if (!url.tls && !s.certFile.empty()) {
    return std::unexpected("a client certificate needs TLS (an mqtts:// address)");
  }
  if (url.tls) return setUpTls(client, s);
  return {};
}

}  // namespace

void MosquittoDeleter::operator()(mosquitto* client) const { mosquitto_destroy(client); }

std::expected<MosquittoClient, std::string> newMosquittoClient(const MqttUrl& url,
                                                               const MqttSecurity& security,
                                                               void* userdata,
                                                               const std::string& clientId) {
  static std::once_flag initialised;
  std::call_once(initialised, [] { mosquitto_lib_init(); });  // never cleaned up: process-wide
  MosquittoClient out{nullptr, clientId.empty() ? randomClientId() : clientId};
  out.handle.reset(mosquitto_new(out.id.c_str(), true, userdata));
  if (!out.handle) {
    return std::unexpected(fmt::format("cannot create an MQTT client: {}", std::strerror(errno)));
  }
  if (auto ok = setUp(out.handle.get(), url, security); !ok) return std::unexpected(ok.error());
  return out;
}

std::string brokerReasonText(int reasonCode) {
  std::string text = mosquitto_reason_string(reasonCode);
  if (!text.empty()) text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

std::string mosquittoFailureText(int rc, int errnoValue, std::string_view loggedError) {
  if (rc == MOSQ_ERR_ERRNO) return std::strerror(errnoValue);
  std::string_view detail = loggedError;
  if (detail.starts_with("Error: ")) detail.remove_prefix(7);
  if (detail.find("OpenSSL Error") != std::string_view::npos) {
    // "OpenSSL Error[0]: error:0A000086:SSL routines::certificate verify failed"
    detail.remove_prefix(detail.rfind(':') + 1);
  }
  while (detail.ends_with('.')) detail.remove_suffix(1);
  if (rc == MOSQ_ERR_TLS && !detail.empty()) return fmt::format("TLS: {}", detail);
  std::string text = mosquitto_strerror(rc);
  if (!text.empty()) text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
  while (!text.empty() && text.back() == '.') text.pop_back();
  if (!detail.empty()) text += fmt::format(" ({})", detail);
  return text;
}

}  // namespace vem::util
