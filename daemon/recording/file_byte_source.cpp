#include "recording/file_byte_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/printable.h"

namespace vem::recording {

std::expected<FileByteSource, RecordingFailure> FileByteSource::open(
    const std::filesystem::path& path) {
  const std::string name = util::printable(path.string());
  util::UniqueFd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (!fd.valid()) {
    const int error = errno;
    if (error == ENOENT) {
      return std::unexpected(RecordingFailure{RecordingError::NotFound, name + ": no such file"});
    }
    return std::unexpected(
        RecordingFailure{RecordingError::Unreadable,
                         name + ": cannot open the file (" + std::strerror(error) + ")"});
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0 || !S_ISREG(info.st_mode)) {
    return std::unexpected(RecordingFailure{
        RecordingError::Unreadable,
        name + (S_ISDIR(info.st_mode) ? ": a folder, not a recording" : ": not a regular file")});
  }
  return FileByteSource(std::move(fd), std::uint64_t(info.st_size));
}

bool FileByteSource::readAt(std::uint64_t offset, std::span<std::byte> out) {
  while (!out.empty()) {
    const ssize_t got = ::pread(fd_.get(), out.data(), out.size(), off_t(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      lastError_ = got < 0 ? errno : EIO;  // 0: the file shrank under us
      return false;
    }
    out = out.subspan(std::size_t(got));
    offset += std::uint64_t(got);
  }
  return true;
}

}  // namespace vem::recording
