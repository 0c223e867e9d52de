// RecordingCursor: reads a VEM recording from a ByteSource, the pure core of RecordingReader
// (docs/vem-format.md). It opens the header record, loads the trailing index when the footer and
// the index are intact, and yields the frames in file order, skipping damaged records (counted in
// stats()) by resynchronising on the record magic. It never trusts a length: each is bounded by
// ReadLimits and by the source's size before anything is allocated.
//
// No files, exceptions for bad input, or logging: errors are status values. (It avoids
// std::expected so that the clang-built fuzzer can compile it.)
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "recording/byte_source.h"
#include "recording/frame_codec.h"
#include "recording/read_limits.h"
#include "recording/record_scanner.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"

namespace vem::recording {

enum class OpenStatus {
  Ok,
  Empty,           // no bytes at all
  NotVem,          // does not start with a record magic
  DamagedHeader,   // starts with a magic, but the header record is cut short or fails its CRC
  UnknownVersion,  // header().formatVersion is not kFormatVersion
  BadHeader,       // the header does not parse, or its values cannot describe frames
  IoError,
};

enum class IndexStatus {
  Valid,    // the footer points at an intact index consistent with the file's layout
  Missing,  // the file does not end with a footer (a crash, a cut, or still being written)
  Damaged,  // a footer is there, but what it points at is not a valid index
};

enum class ReadStep { Frame, End, IoError };
enum class SeekStep { Found, NotFound, IoError };

class RecordingCursor {
 public:
  // Borrows `source`, which must outlive the cursor.
  explicit RecordingCursor(ByteSource& source, ReadLimits limits = {});
  RecordingCursor(const RecordingCursor&) = delete;  // its scanner refers back to it
  RecordingCursor& operator=(const RecordingCursor&) = delete;

  [[nodiscard]] OpenStatus open();
  // After open(): the header as far as it was read (formatVersion for UnknownVersion), and for
  // BadHeader what is wrong with it.
  [[nodiscard]] const RecordingHeader& header() const { return header_.header; }
  [[nodiscard]] const std::string& headerProblem() const { return header_.problem; }

  // After a successful open().
  [[nodiscard]] IndexStatus indexStatus() const { return indexStatus_; }
  [[nodiscard]] std::span<const IndexEntry> index() const { return index_; }
  [[nodiscard]] std::uint64_t firstFrameOffset() const { return firstFrameOffset_; }
  [[nodiscard]] std::uint64_t sourceBytes() const { return source_->size(); }

  // The next intact frame into `out` (its buffers reused).
  [[nodiscard]] ReadStep next(RecordedFrame& out);
  // The next intact frame's metadata (its record CRC checked, pixels not decompressed) and the
  // offset of its record.
  [[nodiscard]] ReadStep nextSummary(FrameSummary& out, std::uint64_t& recordOffset);
  // Positions the cursor so that next() yields the intact frame with the least sequence number
  // >= seq (the first in file order among equals; seekEntry), then the frames after it in file
  // order. Uses the index, or else builds one by scanning the file once.
  [[nodiscard]] SeekStep seek(std::uint64_t seq);
  // Back to the first frame; stats() start again from zero.
  void rewind();

  // What was skipped since open() or the last rewind().
  [[nodiscard]] const DamageStats& stats() const { return scanner_.stats(); }

 private:
  [[nodiscard]] std::uint64_t payloadBound(std::uint16_t type) const;
  [[nodiscard]] RecordScanner makeScanner(std::uint64_t start);
  void loadIndex();
  [[nodiscard]] bool ensureIndexForSeek();

  ByteSource* source_;
  ReadLimits limits_;
  DecodedHeader header_;
  std::uint64_t firstFrameOffset_ = 0;
  IndexStatus indexStatus_ = IndexStatus::Missing;
  std::vector<IndexEntry> index_;
  std::optional<std::vector<IndexEntry>> scannedIndex_;  // built for seek() when there is no index
  RecordScanner scanner_;
  FrameCodec codec_;
};

}  // namespace vem::recording
