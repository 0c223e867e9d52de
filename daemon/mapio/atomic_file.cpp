#include "mapio/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>
#include <random>
#include <utility>

namespace vem::mapio::detail {
namespace {

// Owns a file descriptor.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }
  // Closes now, reporting the error a deferred write may only show here.
  [[nodiscard]] bool close() { return ::close(std::exchange(fd_, -1)) == 0; }

 private:
  int fd_;
};

std::string lastError(const char* what) {
  const int error = errno;
  return std::string(what) + ": " + std::strerror(error);
}

// ".<name>.tmp-<pid>-<count>-<random>" beside the target: hidden, unique to this call.
std::filesystem::path temporarySibling(const std::filesystem::path& target) {
  static std::atomic<unsigned> count{0};
  const unsigned salt = std::random_device{}();
  // fmt rather than operator+ chains: GCC 12 at -O3 warns falsely (-Wrestrict) on the latter.
  const std::string name =
      fmt::format(".{}.tmp-{}-{}-{}", target.filename().string(), ::getpid(), count++, salt);
  return target.parent_path() / name;
}

std::expected<void, std::string> writeAndSync(FileDescriptor fd,
                                              std::span<const unsigned char> bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd.get(), bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return std::unexpected(lastError("cannot write the temporary file"));
    bytes = bytes.subspan(std::size_t(written));
  }
  if (::fsync(fd.get()) != 0) return std::unexpected(lastError("cannot flush the temporary file"));
  if (!fd.close()) return std::unexpected(lastError("cannot close the temporary file"));
  return {};
}

}  // namespace

std::expected<void, std::string> replaceFileAtomically(const std::filesystem::path& target,
                                                       std::span<const unsigned char> bytes) {
  const std::filesystem::path temporary = temporarySibling(target);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return std::unexpected(lastError("cannot create a temporary file beside it"));
  auto done = writeAndSync(FileDescriptor(fd), bytes);
  if (done && std::rename(temporary.c_str(), target.c_str()) != 0)
    done = std::unexpected(lastError("cannot rename the temporary file over it"));
  if (!done) {
    ::unlink(temporary.c_str());
    return done;
  }
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  FileDescriptor dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.get() >= 0) ::fsync(dir.get());  // makes the rename durable; best effort
  return {};
}

}  // namespace vem::mapio::detail
