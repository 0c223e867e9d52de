#include "recording/recording_reader.h"

#include <cstring>
#include <string>

#include "recording/file_byte_source.h"
#include "util/printable.h"

namespace vem::recording {
namespace {

RecordingFailure openFailure(const std::string& name, OpenStatus status,
                             const RecordingCursor& cursor, int ioErrno) {
  switch (status) {
    case OpenStatus::Empty:
      return {RecordingError::NotVem, name + ": the file is empty (expected a VEM recording)"};
    case OpenStatus::NotVem:
      return {RecordingError::NotVem,
              name + ": not a VEM recording (expected the record magic 8a 56 45 4d at its start)"};
    case OpenStatus::DamagedHeader:
      return {RecordingError::BadHeader,
              name +
                  ": the header record is damaged or incomplete (its CRC32C or length does "
                  "not check), so the frames cannot be interpreted"};
    case OpenStatus::UnknownVersion:
      return {RecordingError::UnknownVersion,
              name + ": VEM format version " + std::to_string(cursor.header().formatVersion) +
                  " is not supported (expected version " + std::to_string(kFormatVersion) +
                  "; a newer vemcast may read it)"};
    case OpenStatus::BadHeader:
      return {RecordingError::BadHeader,
              name + ": the header record is invalid (" +
                  (cursor.headerProblem().empty()
                       ? std::string("it does not parse as a vem.proto.RecordingHeader message")
                       : cursor.headerProblem()) +
                  ")"};
    case OpenStatus::IoError:
    case OpenStatus::Ok: break;
  }
  return {RecordingError::Unreadable,
          name + ": cannot read the file (" + std::strerror(ioErrno) + ")"};
}

}  // namespace

RecordingReader::RecordingReader(std::filesystem::path path, std::unique_ptr<FileByteSource> source)
    : path_(std::move(path)), source_(std::move(source)) {}
RecordingReader::RecordingReader(RecordingReader&&) noexcept = default;
RecordingReader& RecordingReader::operator=(RecordingReader&&) noexcept = default;
RecordingReader::~RecordingReader() = default;

std::expected<RecordingReader, RecordingFailure> RecordingReader::open(
    const std::filesystem::path& path, ReadLimits limits) {
  auto source = FileByteSource::open(path);
  if (!source) return std::unexpected(source.error());
  RecordingReader reader(path, std::make_unique<FileByteSource>(std::move(*source)));
  reader.cursor_ = std::make_unique<RecordingCursor>(*reader.source_, limits);
  const OpenStatus status = reader.cursor_->open();
  if (status != OpenStatus::Ok) {
    return std::unexpected(openFailure(util::printable(path.string()), status, *reader.cursor_,
                                       reader.source_->lastError()));
  }
  return reader;
}

RecordingFailure RecordingReader::readFailure() const {
  return {RecordingError::Unreadable, util::printable(path_.string()) + ": cannot read the file (" +
                                          std::strerror(source_->lastError()) + ")"};
}

const RecordingHeader& RecordingReader::header() const { return cursor_->header(); }
IndexStatus RecordingReader::indexStatus() const { return cursor_->indexStatus(); }
std::span<const IndexEntry> RecordingReader::index() const { return cursor_->index(); }
const DamageStats& RecordingReader::damage() const { return cursor_->stats(); }
void RecordingReader::rewind() { cursor_->rewind(); }

std::expected<bool, RecordingFailure> RecordingReader::next(RecordedFrame& frame) {
  switch (cursor_->next(frame)) {
    case ReadStep::Frame: return true;
    case ReadStep::End: return false;
    case ReadStep::IoError: break;
  }
  return std::unexpected(readFailure());
}

std::expected<std::optional<RecordedFrame>, RecordingFailure> RecordingReader::next() {
  RecordedFrame frame;
  auto got = next(frame);
  if (!got) return std::unexpected(got.error());
  if (!*got) return std::optional<RecordedFrame>();
  return std::optional<RecordedFrame>(std::move(frame));
}

std::expected<bool, RecordingFailure> RecordingReader::seek(std::uint64_t seq) {
  switch (cursor_->seek(seq)) {
    case SeekStep::Found: return true;
    case SeekStep::NotFound: return false;
    case SeekStep::IoError: break;
  }
  return std::unexpected(readFailure());
}

std::expected<FrameScan, RecordingFailure> RecordingReader::scan() {
  FrameScan result = scanFrames(*cursor_);
  if (result.ioError) return std::unexpected(readFailure());
  return result;
}

std::expected<RecordingSummary, RecordingFailure> RecordingReader::summarize() {
  auto result = scan();
  if (!result) return std::unexpected(result.error());
  return summarizeRecording(*cursor_, *result);
}

RecordingSummary RecordingReader::summarize(const FrameScan& scan) const {
  return summarizeRecording(*cursor_, scan);
}

}  // namespace vem::recording
