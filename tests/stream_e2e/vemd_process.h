// VemdProcess: the real vemd executable run as a child process for end-to-end tests and the
// stream benchmark. It spawns `vemd ARGS...` (posix_spawn) with stdout discarded and stderr piped;
// a reader thread keeps draining stderr (so vemd never blocks on a full pipe) into a transcript and
// finds the "streaming on ws://ADDRESS:PORT" line to learn the port. The destructor kills (SIGKILL)
// a child still running and reaps it: nothing outlives the test.
//
// Every wait is bounded by its timeout argument (steady clock); none waits forever. Exit status:
// the child's exit code, or 128 + N when signal N ended it (as a shell reports it).
// Not thread-safe as a whole, except stderrText(), waitForPort() and waitForStderr(), which any
// thread may call.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <expected>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace vem::e2e {

class VemdProcess {
 public:
  // Starts `executable` with `args` (not including argv[0]); one sentence when it cannot.
  [[nodiscard]] static std::expected<std::unique_ptr<VemdProcess>, std::string> spawn(
      const std::string& executable, const std::vector<std::string>& args);
  ~VemdProcess();
  VemdProcess(const VemdProcess&) = delete;
  VemdProcess& operator=(const VemdProcess&) = delete;

  // The port of the "streaming on ws://...:PORT" line; empty after `timeout` or when vemd closed
  // stderr (exited) before logging it.
  [[nodiscard]] std::optional<std::uint16_t> waitForPort(std::chrono::milliseconds timeout);
  // Waits until stderr holds `text`; false after `timeout` or at vemd's exit without it.
  [[nodiscard]] bool waitForStderr(const std::string& text, std::chrono::milliseconds timeout);

  // Sends `signal` (SIGTERM, SIGINT...) to the child, if it still runs.
  void signal(int signal);
  // Waits for the child to exit; its status (see above), or empty after `timeout` (still running).
  [[nodiscard]] std::optional<int> waitForExit(std::chrono::milliseconds timeout);

  // Everything vemd wrote to stderr so far (all of it once waitForExit returned a status).
  [[nodiscard]] std::string stderrText() const;
  [[nodiscard]] pid_t pid() const { return pid_; }

 private:
  VemdProcess(pid_t pid, int stderrFd);
  void readStderr();

  pid_t pid_ = -1;
  int stderrFd_ = -1;
  std::optional<int> exitStatus_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::string stderr_;
  bool stderrClosed_ = false;
  std::thread reader_;
};

// The sanitizer reports a vemd built with VEM_SANITIZE would print (empty when none): the lines
// with "ERROR: AddressSanitizer", "ERROR: LeakSanitizer" or "runtime error:" (UBSan).
[[nodiscard]] std::string sanitizerReports(const std::string& stderrText);

}  // namespace vem::e2e
