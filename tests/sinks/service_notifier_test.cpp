// ServiceNotifier against a stand-in for systemd's notify socket: an AF_UNIX datagram socket in a
// temporary folder, named by NOTIFY_SOCKET in this process's environment, as systemd sets it for
// a Type=notify service; WATCHDOG_USEC / WATCHDOG_PID as systemd sets them with WatchdogSec=.
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdlib>

#include "sinks/sink_test_frames.h"
#include "vemd/service_notifier.h"

namespace vem::testing {
namespace {

using namespace std::chrono_literals;
using vemd::ServiceNotifier;

class ServiceNotifierTest : public SinkFiles {
 protected:
  void SetUp() override {
    SinkFiles::SetUp();
    socket_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    ASSERT_GE(socket_, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string path = (dir_ / "notify").string();
    ASSERT_LT(path.size(), sizeof address.sun_path);
    path.copy(address.sun_path, path.size());
    ASSERT_EQ(::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    const timeval timeout{2, 0};
    ::setsockopt(socket_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    ::setenv("NOTIFY_SOCKET", path.c_str(), 1);
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
  }
  void TearDown() override {
    ::unsetenv("NOTIFY_SOCKET");
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
    if (socket_ >= 0) ::close(socket_);
    SinkFiles::TearDown();
  }

  // The next datagram, or "" after 2 s (or at once with `wait` false).
  std::string receive(bool wait = true) {
    char buffer[4096];
    const ssize_t n = ::recv(socket_, buffer, sizeof buffer, wait ? 0 : MSG_DONTWAIT);
    return n < 0 ? std::string() : std::string(buffer, std::size_t(n));
  }

  int socket_ = -1;
};

TEST_F(ServiceNotifierTest, ReadyWatchdogStatusAndStoppingReachTheNotifySocket) {
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  EXPECT_TRUE(notifier.enabled());
  notifier.ready();
  EXPECT_EQ(receive(), "READY=1");
  notifier.watchdog();
  EXPECT_EQ(receive(), "WATCHDOG=1");
  notifier.status("capturing at 30.0 frames/s, 1024 lights");
  EXPECT_EQ(receive(), "STATUS=capturing at 30.0 frames/s, 1024 lights");
  notifier.stopping();
  EXPECT_EQ(receive(), "STOPPING=1");
  EXPECT_EQ(receive(false), "") << "one datagram per call";
}

TEST_F(ServiceNotifierTest, StatusTextCannotInjectAnotherAssignment) {
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  notifier.status("camera lost\nREADY=1");
  EXPECT_EQ(receive(), "STATUS=camera lost READY=1");
}

TEST_F(ServiceNotifierTest, WatchdogIntervalIsHalfOfWatchdogUsecForThisProcess) {
  ::setenv("WATCHDOG_USEC", "3000000", 1);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  EXPECT_EQ(notifier.watchdogTimeout(), std::optional(3'000'000us));
  EXPECT_EQ(notifier.watchdogInterval(), std::optional(1'500'000us));
}

TEST_F(ServiceNotifierTest, WatchdogMeantForAnotherProcessIsNotOurs) {
  ::setenv("WATCHDOG_USEC", "3000000", 1);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid() + 1).c_str(), 1);
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  EXPECT_EQ(notifier.watchdogInterval(), std::nullopt);
}

TEST_F(ServiceNotifierTest, WithoutWatchdogUsecThereIsNoInterval) {
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  EXPECT_EQ(notifier.watchdogTimeout(), std::nullopt);
  EXPECT_EQ(notifier.watchdogInterval(), std::nullopt);
}

TEST_F(ServiceNotifierTest, OutsideSystemdItIsDisabledAndSendsNothing) {
  ::unsetenv("NOTIFY_SOCKET");
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  EXPECT_FALSE(notifier.enabled());
  notifier.ready();
  notifier.watchdog();
  notifier.status("x");
  notifier.stopping();
  EXPECT_EQ(receive(false), "");
  EXPECT_FALSE(ServiceNotifier().enabled());
}

// A notifier made outside systemd stays quiet even if NOTIFY_SOCKET appears later (the
// environment is read once, at start-up).
TEST_F(ServiceNotifierTest, NotifierMadeWithoutNotifySocketStaysQuiet) {
  ::unsetenv("NOTIFY_SOCKET");
  const ServiceNotifier notifier = ServiceNotifier::fromEnvironment();
  ::setenv("NOTIFY_SOCKET", (dir_ / "notify").c_str(), 1);
  notifier.ready();
  EXPECT_EQ(receive(false), "");
}

}  // namespace
}  // namespace vem::testing
