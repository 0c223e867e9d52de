// RecordingReader: reads a VEM recording file (docs/vem-format.md): its header, then its intact
// frames in file order with their stored lights, skipping and counting damaged records. A shell
// around RecordingCursor: it owns the file, and turns statuses into error values.
//
// Conventions: frames come back as recorded, bit for bit (codes, exposureUs, gain, lights);
// seq and captureTsNs are the writer's. Reading never writes. A file still being written is read
// up to its size when opened.
#pragma once

#include <expected>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include "recording/frame_codec.h"
#include "recording/read_limits.h"
#include "recording/record_scanner.h"
#include "recording/recording_cursor.h"
#include "recording/recording_failure.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"
#include "recording/recording_summary.h"

namespace vem::recording {

class FileByteSource;

class RecordingReader {
 public:
  // Reads the header and, when intact, the trailing index. Fails with NotFound, Unreadable,
  // NotVem (empty or another kind of file), UnknownVersion or BadHeader.
  [[nodiscard]] static std::expected<RecordingReader, RecordingFailure> open(
      const std::filesystem::path& path, ReadLimits limits = {});

  RecordingReader(RecordingReader&&) noexcept;
  RecordingReader& operator=(RecordingReader&&) noexcept;
  ~RecordingReader();

  [[nodiscard]] const RecordingHeader& header() const;
  [[nodiscard]] IndexStatus indexStatus() const;
  [[nodiscard]] bool hasIndex() const { return indexStatus() == IndexStatus::Valid; }
  [[nodiscard]] std::span<const IndexEntry> index() const;  // empty without an intact index

  // The next intact frame, nullopt after the last; an error only when the file cannot be read.
  [[nodiscard]] std::expected<std::optional<RecordedFrame>, RecordingFailure> next();
  // The same into `frame`, reusing its buffers (no allocation per frame); false after the last.
  [[nodiscard]] std::expected<bool, RecordingFailure> next(RecordedFrame& frame);
  // Makes next() yield the first intact frame with a sequence number >= seq; false when there is
  // none. Uses the index, or builds one by reading the file once.
  [[nodiscard]] std::expected<bool, RecordingFailure> seek(std::uint64_t seq);
  // Back to the first frame; damage() starts again from zero.
  void rewind();
  // What next() has skipped since open() or rewind().
  [[nodiscard]] const DamageStats& damage() const;

  // Reads every frame's metadata (not its pixels) and rewinds: the info summary, or the intact
  // frames' index entries.
  [[nodiscard]] std::expected<RecordingSummary, RecordingFailure> summarize();
  [[nodiscard]] std::expected<FrameScan, RecordingFailure> scan();
  [[nodiscard]] RecordingSummary summarize(const FrameScan& scan) const;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  RecordingReader(std::filesystem::path path, std::unique_ptr<FileByteSource> source);
  [[nodiscard]] RecordingFailure readFailure() const;

  std::filesystem::path path_;
  std::unique_ptr<FileByteSource> source_;
  std::unique_ptr<RecordingCursor> cursor_;
};

}  // namespace vem::recording
