// MosquittoBroker: a real Mosquitto broker (/usr/sbin/mosquitto, Debian's mosquitto package) run
// as a child process for the tests of the MQTT client and of vemd publishing; never the system's
// service. Each broker gets its own temporary folder with its generated mosquitto.conf, its log
// (mosquitto.log: the broker's stdout and stderr, with connections and subscriptions) and, as
// configured, a password file (made with mosquitto_passwd), an ACL file, a self-signed test CA and
// a server certificate for 127.0.0.1 and localhost (made with the openssl command), and a bridge
// to another broker. `persistence false`: a killed broker forgets its retained messages.
//
// Ports: listeners on 127.0.0.1 only, on free ports picked by binding 127.0.0.1:0 (Mosquitto
// cannot listen on port 0); a start that loses its port to another process is retried on new
// ones. start() and restart() return once every listener accepts TCP connections (polled, bounded
// by 10 s) or the broker exited. As root the broker keeps the user (`user` is set to the current
// one), so it reads the generated files.
//
// The destructor stops the broker (SIGTERM, then SIGKILL after 5 s) and removes the folder.
// Not thread-safe, except logText() and waitForLog().
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <expected>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vem::testing {

struct MosquittoUser {
  std::string name;
  std::string password;
};

// A bridge from this broker to another one on 127.0.0.1 (Mosquitto's `connection` section).
struct MosquittoBridge {
  std::uint16_t remotePort = 0;
  std::string topicPattern = "#";
  std::string direction = "both";  // in, out or both, seen from this broker
};

struct MosquittoBrokerConfig {
  bool allowAnonymous = true;
  std::vector<MosquittoUser> users;       // a password file when not empty
  std::string acl;                        // the ACL file's text; empty: no ACL (all allowed)
  bool tls = false;                       // a second listener with TLS (tlsPort(), caFile())
  bool requireClientCertificate = false;  // on the TLS listener (issueClientCertificate())
  std::optional<MosquittoBridge> bridge;
  std::string extraConfig;  // lines appended to mosquitto.conf
};

struct CertificateFiles {
  std::filesystem::path cert;  // PEM
  std::filesystem::path key;   // PEM, unencrypted
};

class MosquittoBroker {
 public:
  // Generates the files and starts the broker; one sentence when it cannot (mosquitto missing, a
  // tool that failed, a broker that exited: with its log's last line).
  [[nodiscard]] static std::expected<std::unique_ptr<MosquittoBroker>, std::string> start(
      MosquittoBrokerConfig config = {});
  ~MosquittoBroker();
  MosquittoBroker(const MosquittoBroker&) = delete;
  MosquittoBroker& operator=(const MosquittoBroker&) = delete;

  [[nodiscard]] std::uint16_t port() const { return port_; }        // the plain listener
  [[nodiscard]] std::uint16_t tlsPort() const { return tlsPort_; }  // 0 without TLS
  // "mqtt://127.0.0.1:PORT" and `path` ("/vemcast/cam"), and the same with mqtts:// and tlsPort().
  [[nodiscard]] std::string url(std::string_view path = "") const;
  [[nodiscard]] std::string tlsUrl(std::string_view path = "") const;
  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
  [[nodiscard]] std::filesystem::path caFile() const { return dir_ / "ca.crt"; }  // with TLS

  // A client certificate for `commonName` signed by the test CA (with TLS).
  [[nodiscard]] std::expected<CertificateFiles, std::string> issueClientCertificate(
      const std::string& commonName) const;

  // Kills the broker (SIGKILL, like a crash) and reaps it.
  void kill();
  // Starts it again on the same ports with the same files; one sentence when it cannot.
  [[nodiscard]] std::expected<void, std::string> restart();
  [[nodiscard]] bool running() const { return pid_ > 0; }
  [[nodiscard]] pid_t pid() const { return pid_; }

  // The log so far (every run of this broker, appended).
  [[nodiscard]] std::string logText() const;
  // Waits until the log holds `text` (polled); false after `timeout`.
  [[nodiscard]] bool waitForLog(std::string_view text, std::chrono::milliseconds timeout) const;

 private:
  MosquittoBroker(MosquittoBrokerConfig config, std::filesystem::path dir);
  [[nodiscard]] std::expected<void, std::string> writeFiles();
  [[nodiscard]] std::expected<void, std::string> launch();  // on port_ and tlsPort_
  void stop();

  MosquittoBrokerConfig config_;
  std::filesystem::path dir_;
  std::uint16_t port_ = 0;
  std::uint16_t tlsPort_ = 0;
  pid_t pid_ = -1;
};

}  // namespace vem::testing
