#include "recording/recover_index.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "recording/recording_index.h"
#include "recording/recording_reader.h"
#include "util/printable.h"
#include "util/unique_fd.h"
#include "util/write_all.h"

namespace vem::recording {
namespace {

RecordingFailure writeFailure(const std::filesystem::path& path, const std::string& what) {
  const int error = errno;
  return {RecordingError::WriteFailed, util::printable(path.string()) + ": cannot " + what + " (" +
                                           std::strerror(error) +
                                           "); the frames in the file are unchanged"};
}

std::expected<void, RecordingFailure> appendTrailer(const std::filesystem::path& path,
                                                    std::uint64_t expectedSize,
                                                    const std::vector<std::byte>& trailer) {
  util::UniqueFd fd(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
  if (!fd.valid()) return std::unexpected(writeFailure(path, "open the file for writing"));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) return std::unexpected(writeFailure(path, "stat the file"));
  if (std::uint64_t(info.st_size) != expectedSize) {
    return std::unexpected(
        RecordingFailure{RecordingError::WriteFailed,
                         util::printable(path.string()) +
                             ": the file changed while it was read (is it still being recorded?); "
                             "nothing was written"});
  }
  if (auto appended = util::writeAllAt(fd.get(), trailer, expectedSize); !appended) {
    errno = appended.error().error;
    return std::unexpected(writeFailure(path, "append the index"));
  }
  if (::fdatasync(fd.get()) != 0) return std::unexpected(writeFailure(path, "flush the index"));
  if (!fd.close()) return std::unexpected(writeFailure(path, "close the file"));
  return {};
}

}  // namespace

std::expected<RecoverReport, RecordingFailure> recoverIndex(const std::filesystem::path& path) {
  auto reader = RecordingReader::open(path);
  if (!reader) return std::unexpected(reader.error());
  auto scan = reader->scan();
  if (!scan) return std::unexpected(scan.error());
  const RecordingSummary summary = reader->summarize(*scan);

  RecoverReport report;
  report.indexBefore = summary.index;
  report.damage = scan->damage;
  // Every intact frame, in file order, out-of-order ones included: exactly what info counts and
  // what makes the index valid, so a second run finds it valid and writes nothing.
  report.framesIndexed = scan->entries.size();
  if (summary.index == IndexState::Valid) return report;

  const std::uint64_t size = summary.fileBytes;
  const std::vector<std::byte> trailer = encodeTrailer(scan->entries, size);
  if (auto appended = appendTrailer(path, size, trailer); !appended) {
    return std::unexpected(appended.error());
  }
  report.appendedBytes = trailer.size();
  return report;
}

}  // namespace vem::recording
