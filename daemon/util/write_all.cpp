#include "util/write_all.h"

#include <unistd.h>

namespace vem::util {

std::expected<void, WriteFailure> writeAll(int fd, std::span<const std::byte> bytes) {
  return writeAllWith([fd](std::span<const std::byte> rest,
                           std::size_t) { return ::write(fd, rest.data(), rest.size()); },
                      bytes);
}

std::expected<void, WriteFailure> writeAllAt(int fd, std::span<const std::byte> bytes,
                                             std::uint64_t offsetBytes) {
  return writeAllWith(
      [fd, offsetBytes](std::span<const std::byte> rest, std::size_t done) {
        return ::pwrite(fd, rest.data(), rest.size(), off_t(offsetBytes + done));
      },
      bytes);
}

}  // namespace vem::util
