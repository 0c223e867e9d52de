// Writing a whole buffer to a file descriptor: write(2) and pwrite(2) may write less than asked
// (a signal, a pipe, a nearly full disk) or fail with EINTR; these continue until every byte is
// written or a real error comes. The failure says which errno (EIO for a write of 0 bytes) and how
// many bytes did reach the file first, so a caller can cut a partial record off again.
#pragma once

#include <sys/types.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <span>

namespace vem::util {

struct WriteFailure {
  int error = 0;            // errno of the failed call; EIO when a call wrote nothing
  std::size_t written = 0;  // bytes written before it
};

// write(2) until all of `bytes` is written.
[[nodiscard]] std::expected<void, WriteFailure> writeAll(int fd, std::span<const std::byte> bytes);
// pwrite(2) of `bytes` at `offsetBytes` until all of it is written (the file offset is unchanged).
[[nodiscard]] std::expected<void, WriteFailure> writeAllAt(int fd, std::span<const std::byte> bytes,
                                                           std::uint64_t offsetBytes);

// The loop both use, over any call shaped like write(2): `writeSome(rest, doneBytes)` writes a
// prefix of `rest` and returns its length, or -1 with errno set. (Tests pass a fake.)
template <typename WriteSome>
[[nodiscard]] std::expected<void, WriteFailure> writeAllWith(WriteSome&& writeSome,
                                                             std::span<const std::byte> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = writeSome(bytes.subspan(done), done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::unexpected(WriteFailure{n < 0 ? errno : EIO, done});
    done += std::size_t(n);
  }
  return {};
}

}  // namespace vem::util
