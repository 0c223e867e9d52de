#include "recording/recording_cursor.h"

#include <algorithm>

#include <zstd.h>

namespace vem::recording {

RecordingCursor::RecordingCursor(ByteSource& source, ReadLimits limits)
    : source_(&source), limits_(limits), scanner_(makeScanner(0)) {}

std::uint64_t RecordingCursor::payloadBound(std::uint16_t type) const {
  switch (RecordType(type)) {
    case RecordType::Header: return limits_.maxHeaderBytes;
    case RecordType::Index: return limits_.maxIndexBytes;
    case RecordType::Footer: return kFooterPayloadBytes;
    case RecordType::Frame: break;
  }
  // Frames, and records of unknown types: at most one frame's worth.
  const std::uint64_t frame =
      header_.status == HeaderStatus::Ok ? frameBytes(header_.header) : limits_.maxFrameBytes;
  return 4 + std::uint64_t(limits_.maxFrameMetaBytes) + ZSTD_compressBound(std::size_t(frame));
}

RecordScanner RecordingCursor::makeScanner(std::uint64_t start) {
  return RecordScanner(
      *source_, [this](std::uint16_t type) { return payloadBound(type); }, start);
}

OpenStatus RecordingCursor::open() {
  const std::uint64_t size = source_->size();
  if (size == 0) return OpenStatus::Empty;
  std::array<std::byte, kRecordMagic.size()> magic{};
  if (size < magic.size()) return OpenStatus::NotVem;
  if (!source_->readAt(0, magic)) return OpenStatus::IoError;
  if (magic != kRecordMagic) return OpenStatus::NotVem;

  RecordScanner first = makeScanner(0);
  ScannedRecord record;
  const ScanStep step = first.next(record);
  if (step == ScanStep::IoError) return OpenStatus::IoError;
  if (step == ScanStep::End || record.offset != 0 ||
      record.type != std::uint16_t(RecordType::Header)) {
    return OpenStatus::DamagedHeader;
  }
  header_ = decodeHeaderPayload(record.payload, limits_);
  switch (header_.status) {
    case HeaderStatus::Ok: break;
    case HeaderStatus::UnknownVersion: return OpenStatus::UnknownVersion;
    case HeaderStatus::Malformed:
    case HeaderStatus::BadValues: return OpenStatus::BadHeader;
  }
  firstFrameOffset_ = record.endOffset();
  loadIndex();
  scanner_ = makeScanner(firstFrameOffset_);
  return OpenStatus::Ok;
}

void RecordingCursor::loadIndex() {
  indexStatus_ = IndexStatus::Missing;
  index_.clear();
  const std::uint64_t size = source_->size();
  if (size < firstFrameOffset_ + kRecordHeaderBytes + kFooterRecordBytes) return;
  const std::uint64_t footerOffset = size - kFooterRecordBytes;
  RecordScanner footerScanner = makeScanner(footerOffset);
  ScannedRecord footer;
  if (footerScanner.next(footer) != ScanStep::Record || footer.offset != footerOffset ||
      footer.type != std::uint16_t(RecordType::Footer)) {
    return;
  }
  indexStatus_ = IndexStatus::Damaged;
  const std::optional<FooterFields> fields = decodeFooterPayload(footer.payload);
  if (!fields || fields->indexOffset < firstFrameOffset_ || fields->indexOffset > footerOffset ||
      fields->indexRecordBytes != footerOffset - fields->indexOffset) {
    return;
  }
  RecordScanner indexScanner = makeScanner(fields->indexOffset);
  ScannedRecord index;
  if (indexScanner.next(index) != ScanStep::Record || index.offset != fields->indexOffset ||
      index.type != std::uint16_t(RecordType::Index) || index.endOffset() != footerOffset) {
    return;
  }
  auto entries = decodeIndexPayload(index.payload, firstFrameOffset_, fields->indexOffset);
  if (!entries) return;
  index_ = std::move(*entries);
  indexStatus_ = IndexStatus::Valid;
}

ReadStep RecordingCursor::next(RecordedFrame& out) {
  ScannedRecord record;
  for (;;) {
    const ScanStep step = scanner_.next(record);
    if (step == ScanStep::End) return ReadStep::End;
    if (step == ScanStep::IoError) return ReadStep::IoError;
    switch (RecordType(record.type)) {
      case RecordType::Frame:
        if (codec_.decode(record.payload, header_.header, limits_, out)) return ReadStep::Frame;
        scanner_.markDamaged(record);
        break;
      case RecordType::Header:  // only the first record may be a header
        scanner_.markDamaged(record);
        break;
      case RecordType::Index:
      case RecordType::Footer: break;
      default: scanner_.countUnknown();
    }
  }
}

ReadStep RecordingCursor::nextSummary(FrameSummary& out, std::uint64_t& recordOffset) {
  ScannedRecord record;
  for (;;) {
    const ScanStep step = scanner_.next(record);
    if (step == ScanStep::End) return ReadStep::End;
    if (step == ScanStep::IoError) return ReadStep::IoError;
    switch (RecordType(record.type)) {
      case RecordType::Frame:
        if (auto summary = codec_.decodeSummary(record.payload, header_.header, limits_)) {
          out = *summary;
          recordOffset = record.offset;
          return ReadStep::Frame;
        }
        scanner_.markDamaged(record);
        break;
      case RecordType::Header: scanner_.markDamaged(record); break;
      case RecordType::Index:
      case RecordType::Footer: break;
      default: scanner_.countUnknown();
    }
  }
}

bool RecordingCursor::ensureIndexForSeek() {
  if (indexStatus_ == IndexStatus::Valid || scannedIndex_) return true;
  RecordScanner saved = std::move(scanner_);
  scanner_ = makeScanner(firstFrameOffset_);
  std::vector<IndexEntry> entries;
  FrameSummary summary;
  std::uint64_t offset = 0;
  ReadStep step;
  while ((step = nextSummary(summary, offset)) == ReadStep::Frame) {
    entries.push_back({summary.seq, summary.captureTsNs, offset});
  }
  scanner_ = std::move(saved);
  if (step == ReadStep::IoError) return false;
  scannedIndex_ = std::move(entries);
  return true;
}

SeekStep RecordingCursor::seek(std::uint64_t seq) {
  if (!ensureIndexForSeek()) return SeekStep::IoError;
  const std::vector<IndexEntry>& entries =
      indexStatus_ == IndexStatus::Valid ? index_ : *scannedIndex_;
  const std::optional<std::size_t> at = seekEntry(entries, seq);
  if (!at) {
    scanner_.seek(source_->size());
    return SeekStep::NotFound;
  }
  scanner_.seek(entries[*at].offset);
  return SeekStep::Found;
}

void RecordingCursor::rewind() { scanner_ = makeScanner(firstFrameOffset_); }

}  // namespace vem::recording
