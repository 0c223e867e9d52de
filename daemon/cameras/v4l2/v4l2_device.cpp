#include "cameras/v4l2/v4l2_device.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstring>

#include "util/unique_fd.h"

namespace vem::cameras {

namespace {

constexpr int kMaxEintrRetries = 64;

class SystemV4l2Device final : public V4l2Device {
 public:
  explicit SystemV4l2Device(util::UniqueFd fd) : fd_(std::move(fd)) {}

  int ioctl(unsigned long request, void* arg) override {
    for (int attempt = 0; attempt < kMaxEintrRetries; ++attempt) {
      if (::ioctl(fd_.get(), request, arg) == 0) return 0;
      if (errno != EINTR) return errno;
    }
    return EINTR;
  }

  std::expected<std::span<const std::byte>, int> mmap(std::size_t length,
                                                      std::uint32_t offset) override {
    void* mapped = ::mmap(nullptr, length, PROT_READ, MAP_SHARED, fd_.get(), off_t(offset));
    if (mapped == MAP_FAILED) return std::unexpected(errno);
    return std::span<const std::byte>(static_cast<const std::byte*>(mapped), length);
  }

  void munmap(std::span<const std::byte> mapping) override {
    ::munmap(const_cast<std::byte*>(mapping.data()), mapping.size());
  }

  std::expected<V4l2PollResult, int> poll(int wakeFd, int timeoutMs) override {
    pollfd fds[2] = {{fd_.get(), POLLIN | POLLPRI, 0}, {wakeFd, POLLIN, 0}};
    const int ready = ::poll(fds, wakeFd >= 0 ? 2 : 1, timeoutMs);
    if (ready < 0) return std::unexpected(errno);
    V4l2PollResult result;
    result.frameReady = (fds[0].revents & POLLIN) != 0;
    result.deviceError = (fds[0].revents & (POLLERR | POLLHUP | POLLNVAL)) != 0;
    result.woken = wakeFd >= 0 && (fds[1].revents & POLLIN) != 0;
    return result;
  }

 private:
  util::UniqueFd fd_;
};

}  // namespace

std::expected<std::unique_ptr<V4l2Device>, int> openSystemV4l2Device(const std::string& path) {
  util::UniqueFd fd;
  do {
    fd.reset(::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC));
  } while (!fd.valid() && errno == EINTR);
  if (!fd.valid()) return std::unexpected(errno);
  return std::make_unique<SystemV4l2Device>(std::move(fd));
}

int v4l2Ioctl(V4l2Device& device, unsigned long request, void* arg) {
  int error = 0;
  for (int attempt = 0; attempt < kMaxEintrRetries; ++attempt) {
    error = device.ioctl(request, arg);
    if (error != EINTR) return error;
  }
  return error;
}

std::string errnoText(int error) {
  char buffer[128] = {};
  // GNU strerror_r returns the text (maybe not in buffer).
  return ::strerror_r(error, buffer, sizeof buffer);
}

}  // namespace vem::cameras
