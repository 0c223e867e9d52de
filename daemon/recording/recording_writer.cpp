#include "recording/recording_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <string>

#include "util/printable.h"
#include "util/write_all.h"

namespace vem::recording {
namespace {

std::string errnoText(int error) { return std::strerror(error); }

// fdatasync, accepting files that cannot be synced (pipes, /dev/full): nothing to make durable.
bool syncData(int fd) {
  if (::fdatasync(fd) == 0) return true;
  return errno == EINVAL || errno == EROFS;
}

}  // namespace

RecordingWriter::RecordingWriter(std::filesystem::path path, util::UniqueFd fd,
                                 RecordingHeader header, WriterOptions options)
    : path_(std::move(path)),
      name_(util::printable(path_.string())),
      fd_(std::move(fd)),
      header_(std::move(header)),
      options_(options),
      codec_(options.zstdLevel) {}

RecordingWriter::RecordingWriter(RecordingWriter&&) noexcept = default;
RecordingWriter& RecordingWriter::operator=(RecordingWriter&&) noexcept = default;

RecordingWriter::~RecordingWriter() {
  if (fd_.valid()) (void)close();
}

std::expected<RecordingWriter, RecordingFailure> RecordingWriter::create(
    const std::filesystem::path& path, const RecordingHeader& header, WriterOptions options) {
  const std::string name = util::printable(path.string());
  RecordingHeader h = header;
  h.formatVersion = kFormatVersion;
  if (const std::string problem = headerProblem(h, ReadLimits{}); !problem.empty()) {
    return std::unexpected(
        RecordingFailure{RecordingError::BadHeader, name + ": cannot record: " + problem});
  }
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (options.replaceExisting ? O_TRUNC : O_EXCL);
  util::UniqueFd fd(::open(path.c_str(), flags, 0644));
  if (!fd.valid()) {
    const int error = errno;
    return std::unexpected(RecordingFailure{
        RecordingError::WriteFailed,
        name + (error == EEXIST ? ": a file is already there (refusing to overwrite it)"
                                : ": cannot create the recording (" + errnoText(error) + ")")});
  }
  RecordingWriter writer(path, std::move(fd), std::move(h), options);
  if (auto written = writer.writeAtEnd(encodeHeaderRecord(writer.header_)); !written) {
    writer.fd_ = util::UniqueFd();
    if (!options.replaceExisting) ::unlink(path.c_str());  // ours, and holding no frame
    // No frame can stay readable without a header: say that nothing was recorded.
    return std::unexpected(RecordingFailure{
        RecordingError::WriteFailed, name + ": cannot write the header (" +
                                         errnoText(written.error()) + "); no recording was made"});
  }
  if (!syncData(writer.fd_.get())) {
    const int error = errno;
    writer.fd_ = util::UniqueFd();
    return std::unexpected(
        RecordingFailure{RecordingError::WriteFailed,
                         name + ": cannot flush the header (" + errnoText(error) + ")"});
  }
  return writer;
}

std::expected<void, int> RecordingWriter::writeAtEnd(const std::vector<std::byte>& bytes) {
  // One pwrite() for the whole record; writeAllAt only continues a write a signal interrupted
  // part-way.
  const auto written = util::writeAllAt(fd_.get(), bytes, end_);
  if (written) {
    end_ += bytes.size();
    return {};
  }
  // Best effort: drop the partial record.
  if (written.error().written > 0) (void)::ftruncate(fd_.get(), off_t(end_));
  return std::unexpected(written.error().error);
}

RecordingFailure RecordingWriter::writeFailure(const std::string& what, int error) const {
  return {RecordingError::WriteFailed, name_ + ": cannot write " + what + " (" + errnoText(error) +
                                           "); the " + std::to_string(entries_.size()) +
                                           " frames before it stay readable"};
}

std::string RecordingWriter::frameProblem(std::uint64_t seq, const RawFrame& frame) const {
  if (frame.width != header_.sensorWidthPx || frame.height != header_.sensorHeightPx ||
      frame.format != header_.pixelFormat) {
    return "the frame is " + std::to_string(frame.width) + " x " + std::to_string(frame.height) +
           " " + pixelFormatName(frame.format) + " (expected the header's " +
           std::to_string(header_.sensorWidthPx) + " x " + std::to_string(header_.sensorHeightPx) +
           " " + pixelFormatName(header_.pixelFormat) + ")";
  }
  if (frame.codes.size() != frameBytes(header_) / 2) {
    return "the frame holds " + std::to_string(frame.codes.size()) + " codes (expected " +
           std::to_string(frameBytes(header_) / 2) + ")";
  }
  if (!entries_.empty() && seq <= entries_.back().seq) {
    return "sequence number " + std::to_string(seq) + " does not follow " +
           std::to_string(entries_.back().seq) + " (expected increasing numbers)";
  }
  return {};
}

std::expected<void, RecordingFailure> RecordingWriter::append(std::uint64_t seq,
                                                              std::int64_t captureTsNs,
                                                              const RawFrame& frame,
                                                              const LightSet* lights) {
  if (!fd_.valid()) {
    return std::unexpected(RecordingFailure{
        RecordingError::Closed, name_ + ": cannot append a frame to a closed recording"});
  }
  if (const std::string problem = frameProblem(seq, frame); !problem.empty()) {
    return std::unexpected(RecordingFailure{RecordingError::InvalidFrame,
                                            name_ + ": cannot record the frame: " + problem});
  }
  try {
    codec_.encodeRecord(seq, captureTsNs, frame, lights, record_);
  } catch (const std::exception& e) {
    return std::unexpected(RecordingFailure{
        RecordingError::WriteFailed,
        name_ + ": cannot compress frame " + std::to_string(seq) + " (" + e.what() + ")"});
  }
  const std::uint64_t offset = end_;
  if (auto written = writeAtEnd(record_); !written) {
    return std::unexpected(writeFailure("frame " + std::to_string(seq), written.error()));
  }
  entries_.push_back({seq, captureTsNs, offset});
  if (options_.syncEveryFrames > 0 && ++framesSinceSync_ >= options_.syncEveryFrames) {
    framesSinceSync_ = 0;
    if (!syncData(fd_.get())) {
      const int error = errno;
      return std::unexpected(RecordingFailure{
          RecordingError::WriteFailed, name_ + ": cannot flush frame " + std::to_string(seq) +
                                           " to disk (" + errnoText(error) + ")"});
    }
  }
  return {};
}

std::expected<void, RecordingFailure> RecordingWriter::close() {
  if (!fd_.valid()) {
    return std::unexpected(
        RecordingFailure{RecordingError::Closed, name_ + ": the recording is closed"});
  }
  std::expected<void, RecordingFailure> result;
  if (auto written = writeAtEnd(encodeTrailer(entries_, end_)); !written) {
    result = std::unexpected(writeFailure("the index", written.error()));
  }
  if (result && !syncData(fd_.get())) {
    result = std::unexpected(RecordingFailure{
        RecordingError::WriteFailed,
        name_ + ": cannot flush the recording to disk (" + errnoText(errno) + ")"});
  }
  if (!fd_.close() && result) {
    result = std::unexpected(
        RecordingFailure{RecordingError::WriteFailed,
                         name_ + ": cannot close the recording (" + errnoText(errno) + ")"});
  }
  return result;
}

}  // namespace vem::recording
