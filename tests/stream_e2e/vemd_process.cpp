#include "stream_e2e/vemd_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <sstream>

extern char** environ;

namespace vem::e2e {

namespace {

constexpr std::chrono::milliseconds kPollInterval{10};

int shellStatus(int waitStatus) {
  if (WIFEXITED(waitStatus)) return WEXITSTATUS(waitStatus);
  if (WIFSIGNALED(waitStatus)) return 128 + WTERMSIG(waitStatus);
  return -1;
}

// The PORT of a whole "streaming on ws://ADDRESS:PORT" line (std::regex draws GCC 12's
// maybe-uninitialized warning in sanitizer builds, so by hand).
std::optional<std::uint16_t> streamingPort(const std::string& text) {
  const std::size_t at = text.find("streaming on ws");
  if (at == std::string::npos) return std::nullopt;
  const std::size_t end = text.find('\n', at);
  if (end == std::string::npos) return std::nullopt;  // the line is not complete yet
  const std::size_t colon = text.rfind(':', end);
  if (colon == std::string::npos || colon < at || colon + 1 >= end) return std::nullopt;
  std::uint32_t port = 0;
  for (std::size_t i = colon + 1; i < end && text[i] >= '0' && text[i] <= '9'; ++i) {
    port = port * 10 + std::uint32_t(text[i] - '0');
  }
  if (port == 0 || port > 65535) return std::nullopt;
  return std::uint16_t(port);
}

}  // namespace

std::expected<std::unique_ptr<VemdProcess>, std::string> VemdProcess::spawn(
    const std::string& executable, const std::vector<std::string>& args) {
  int pipeFds[2];
  if (::pipe2(pipeFds, O_CLOEXEC) != 0) {
    return std::unexpected("cannot create a pipe for vemd's stderr: " +
                           std::string(std::strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDERR_FILENO);
  std::vector<std::string> argvStrings{executable};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argvStrings) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int failed =
      ::posix_spawn(&pid, executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipeFds[1]);
  if (failed != 0) {
    ::close(pipeFds[0]);
    return std::unexpected("cannot start " + executable + ": " + std::strerror(failed));
  }
  return std::unique_ptr<VemdProcess>(new VemdProcess(pid, pipeFds[0]));
}

VemdProcess::VemdProcess(pid_t pid, int stderrFd) : pid_(pid), stderrFd_(stderrFd) {
  reader_ = std::thread([this] { readStderr(); });
}

VemdProcess::~VemdProcess() {
  if (!exitStatus_) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  // The child is gone, so its end of the pipe is closed and the reader sees end of file.
  if (reader_.joinable()) reader_.join();
  ::close(stderrFd_);
}

void VemdProcess::readStderr() {
  char chunk[4096];
  for (;;) {
    const ssize_t got = ::read(stderrFd_, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    std::lock_guard lock(mutex_);
    if (got <= 0) {
      stderrClosed_ = true;
      changed_.notify_all();
      return;
    }
    stderr_.append(chunk, std::size_t(got));
    changed_.notify_all();
  }
}

std::optional<std::uint16_t> VemdProcess::waitForPort(std::chrono::milliseconds timeout) {
  std::optional<std::uint16_t> port;
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] {
    port = streamingPort(stderr_);
    return port.has_value() || stderrClosed_;
  });
  return port;
}

bool VemdProcess::waitForStderr(const std::string& text, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] {
    return stderr_.find(text) != std::string::npos || stderrClosed_;
  }) && stderr_.find(text) != std::string::npos;
}

void VemdProcess::signal(int signal) {
  if (!exitStatus_) ::kill(pid_, signal);
}

std::optional<int> VemdProcess::waitForExit(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!exitStatus_) {
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
      exitStatus_ = shellStatus(status);
      break;
    }
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(kPollInterval);
  }
  // vemd is gone: wait (bounded) for the reader to have seen the end of its stderr.
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, std::chrono::seconds(5), [&] { return stderrClosed_; });
  return exitStatus_;
}

std::string VemdProcess::stderrText() const {
  std::lock_guard lock(mutex_);
  return stderr_;
}

std::string sanitizerReports(const std::string& stderrText) {
  std::istringstream in(stderrText);
  std::string reports;
  for (std::string line; std::getline(in, line);) {
    if (line.find("ERROR: AddressSanitizer") != std::string::npos ||
        line.find("ERROR: LeakSanitizer") != std::string::npos ||
        line.find("runtime error:") != std::string::npos) {
      reports += line + "\n";
    }
  }
  return reports;
}

}  // namespace vem::e2e
