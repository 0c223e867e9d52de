#include "support/mosquitto_broker.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <pwd.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

extern char** environ;

namespace vem::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr const char* kMosquitto = "/usr/sbin/mosquitto";
constexpr const char* kMosquittoPasswd = "/usr/bin/mosquitto_passwd";
constexpr auto kStartLimit = 10s;
constexpr auto kPollPeriod = 10ms;  // how often start() and waitForLog() look again
constexpr int kPortAttempts = 5;

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string lastLine(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && (trimmed.back() == '\n' || trimmed.back() == '\r')) trimmed.pop_back();
  const std::size_t newline = trimmed.rfind('\n');
  return newline == std::string::npos ? trimmed : trimmed.substr(newline + 1);
}

// Built by appending: GCC 12 reports a false -Wrestrict on "'" + string + "'".
std::string quoted(const fs::path& path) {
  std::string out = "'";
  out.append(path.string()).append("'");
  return out;
}

// Runs a shell command line in `dir`, its output in dir/tools.log; the log's last line on failure.
std::expected<void, std::string> run(const std::string& commandLine, const fs::path& dir) {
  const fs::path log = dir / "tools.log";
  const std::string command =
      "cd " + quoted(dir) + " && " + commandLine + " >" + quoted(log) + " 2>&1";
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  return std::unexpected("'" + commandLine + "' failed: " + lastLine(readAll(log)));
}

// A port nobody listens on now: bound on 127.0.0.1:0 and released.
std::expected<std::uint16_t, std::string> freePort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return std::unexpected("cannot open a socket to find a free port");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  const bool ok = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
                  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0;
  ::close(fd);
  if (!ok) return std::unexpected("cannot bind 127.0.0.1:0 to find a free port");
  return ntohs(address.sin_port);
}

bool accepts(std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return false;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(port);
  const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);
  return ok;
}

std::string currentUser() {
  const passwd* entry = ::getpwuid(::geteuid());
  return entry != nullptr ? entry->pw_name : "root";
}

// A key and a certificate signed by the test CA in `dir` (ca.crt, ca.key), for `commonName`,
// with the extensions in `extensions` (an openssl extension file's text).
std::expected<void, std::string> issueCertificate(const fs::path& dir, const std::string& name,
                                                  const std::string& commonName,
                                                  const std::string& extensions) {
  std::ofstream(dir / (name + ".ext")) << extensions;
  if (auto ok = run("openssl req -new -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes "
                    "-keyout " +
                        name + ".key -out " + name + ".csr -subj '/CN=" + commonName + "'",
                    dir);
      !ok) {
    return ok;
  }
  return run("openssl x509 -req -in " + name +
                 ".csr -CA ca.crt -CAkey ca.key -CAcreateserial "
                 "-days 2 -out " +
                 name + ".crt -extfile " + name + ".ext",
             dir);
}

}  // namespace

MosquittoBroker::MosquittoBroker(MosquittoBrokerConfig config, fs::path dir)
    : config_(std::move(config)), dir_(std::move(dir)) {}

MosquittoBroker::~MosquittoBroker() {
  stop();
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
}

std::expected<std::unique_ptr<MosquittoBroker>, std::string> MosquittoBroker::start(
    MosquittoBrokerConfig config) {
  if (::access(kMosquitto, X_OK) != 0) {
    return std::unexpected(std::string(kMosquitto) + " is missing (the mosquitto package)");
  }
  std::string pattern = (fs::temp_directory_path() / "vemcast-mosquitto-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    return std::unexpected("cannot create a temporary folder for the broker");
  }
  std::unique_ptr<MosquittoBroker> broker(new MosquittoBroker(std::move(config), pattern));
  if (auto ok = broker->writeFiles(); !ok) return std::unexpected(ok.error());
  std::string lastFailure;
  for (int attempt = 0; attempt < kPortAttempts; ++attempt) {
    auto port = freePort();
    auto tlsPort = broker->config_.tls ? freePort() : std::expected<std::uint16_t, std::string>(0);
    if (!port) return std::unexpected(port.error());
    if (!tlsPort) return std::unexpected(tlsPort.error());
    if (*port == *tlsPort) continue;
    broker->port_ = *port;
    broker->tlsPort_ = *tlsPort;
    auto launched = broker->launch();
    if (launched) return broker;
    lastFailure = launched.error();
    if (lastFailure.find("in use") == std::string::npos) break;  // not a port taken meanwhile
  }
  return std::unexpected(lastFailure);
}

std::expected<void, std::string> MosquittoBroker::writeFiles() {
  const MosquittoBrokerConfig& c = config_;
  for (std::size_t i = 0; i < c.users.size(); ++i) {
    if (::access(kMosquittoPasswd, X_OK) != 0) {
      return std::unexpected(std::string(kMosquittoPasswd) + " is missing (the mosquitto package)");
    }
    const std::string line = std::string(kMosquittoPasswd) + (i == 0 ? " -c" : "") +
                             " -b passwords '" + c.users[i].name + "' '" + c.users[i].password +
                             "'";
    if (auto ok = run(line, dir_); !ok) return ok;
  }
  if (!c.acl.empty()) std::ofstream(dir_ / "acl") << c.acl << '\n';
  if (c.tls) {
    if (auto ok = run("openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes "
                      "-keyout ca.key -out ca.crt -days 2 -subj '/CN=vemcast test CA'",
                      dir_);
        !ok) {
      return ok;
    }
    if (auto ok = issueCertificate(dir_, "server", "127.0.0.1",
                                   "subjectAltName=IP:127.0.0.1,DNS:localhost\n"
                                   "extendedKeyUsage=serverAuth\n");
        !ok) {
      return ok;
    }
  }
  return {};
}

std::expected<CertificateFiles, std::string> MosquittoBroker::issueClientCertificate(
    const std::string& commonName) const {
  if (!config_.tls) return std::unexpected("the broker has no TLS, hence no test CA");
  const std::string name = "client-" + commonName;
  if (auto ok = issueCertificate(dir_, name, commonName, "extendedKeyUsage=clientAuth\n"); !ok) {
    return std::unexpected(ok.error());
  }
  return CertificateFiles{dir_ / (name + ".crt"), dir_ / (name + ".key")};
}

std::expected<void, std::string> MosquittoBroker::launch() {
  const MosquittoBrokerConfig& c = config_;
  std::ostringstream conf;
  conf << "user " << currentUser() << "\npersistence false\n"
       << "log_dest file " << (dir_ / "mosquitto.log").string() << '\n'
       << "log_type error\nlog_type warning\nlog_type notice\nlog_type information\n"
       << "log_type subscribe\nlog_type unsubscribe\nconnection_messages true\n"
       << "per_listener_settings false\n"
       << "allow_anonymous " << (c.allowAnonymous ? "true" : "false") << '\n';
  if (!c.users.empty()) conf << "password_file " << (dir_ / "passwords").string() << '\n';
  if (!c.acl.empty()) conf << "acl_file " << (dir_ / "acl").string() << '\n';
  conf << c.extraConfig << '\n';
  conf << "listener " << port_ << " 127.0.0.1\n";
  if (c.tls) {
    conf << "listener " << tlsPort_ << " 127.0.0.1\n"
         << "cafile " << caFile().string() << "\ncertfile " << (dir_ / "server.crt").string()
         << "\nkeyfile " << (dir_ / "server.key").string() << '\n'
         << "require_certificate " << (c.requireClientCertificate ? "true" : "false") << '\n';
  }
  if (c.bridge) {  // last: every line after `connection` belongs to the bridge
    conf << "connection bridge-to-" << c.bridge->remotePort
         << "\naddress 127.0.0.1:" << c.bridge->remotePort << "\ntopic " << c.bridge->topicPattern
         << ' ' << c.bridge->direction << " 0\nbridge_protocol_version mqttv50\ncleansession true\n"
         << "restart_timeout 1\n";
  }
  std::ofstream(dir_ / "mosquitto.conf") << conf.str();

  const std::string log = (dir_ / "mosquitto.log").string();
  const std::size_t logSizeBefore = readAll(log).size();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const std::string confPath = (dir_ / "mosquitto.conf").string();
  std::vector<char*> argv{const_cast<char*>(kMosquitto), const_cast<char*>("-c"),
                          const_cast<char*>(confPath.c_str()), nullptr};
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, kMosquitto, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return std::unexpected(std::string("cannot start ") + kMosquitto);
  pid_ = pid;

  const Clock::time_point deadline = Clock::now() + kStartLimit;
  while (Clock::now() < deadline) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      const std::string output = readAll(log).substr(logSizeBefore);
      const bool inUse = output.find("Address already in use") != std::string::npos;
      return std::unexpected("mosquitto exited at start" +
                             std::string(inUse ? " (port in use)" : "") + ": " + lastLine(output));
    }
    if (accepts(port_) && (tlsPort_ == 0 || accepts(tlsPort_))) return {};
    std::this_thread::sleep_for(kPollPeriod);
  }
  stop();
  return std::unexpected("mosquitto did not accept connections within 10 s: " +
                         lastLine(readAll(log)));
}

void MosquittoBroker::kill() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
}

std::expected<void, std::string> MosquittoBroker::restart() {
  kill();
  return launch();
}

void MosquittoBroker::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  const Clock::time_point deadline = Clock::now() + 5s;
  int status = 0;
  while (Clock::now() < deadline) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return;
    }
    std::this_thread::sleep_for(kPollPeriod);
  }
  kill();
}

std::string MosquittoBroker::url(std::string_view path) const {
  return "mqtt://127.0.0.1:" + std::to_string(port_) + std::string(path);
}

std::string MosquittoBroker::tlsUrl(std::string_view path) const {
  return "mqtts://127.0.0.1:" + std::to_string(tlsPort_) + std::string(path);
}

std::string MosquittoBroker::logText() const { return readAll(dir_ / "mosquitto.log"); }

bool MosquittoBroker::waitForLog(std::string_view text, std::chrono::milliseconds timeout) const {
  const Clock::time_point deadline = Clock::now() + timeout;
  while (true) {
    if (logText().find(text) != std::string::npos) return true;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(kPollPeriod);
  }
}

}  // namespace vem::testing
