#include "recording/record_scanner.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "recording/crc32c.h"

namespace vem::recording {
namespace {

constexpr std::size_t kSearchWindowBytes = std::size_t(1) << 16;

}  // namespace

RecordScanner::RecordScanner(ByteSource& source, PayloadBound bound, std::uint64_t start)
    : source_(&source), bound_(std::move(bound)), size_(source.size()), pos_(start) {}

RecordScanner::Attempt RecordScanner::tryRecordAt(std::uint64_t offset, ScannedRecord& out) {
  const std::uint64_t remaining = size_ - offset;
  std::array<std::byte, kRecordHeaderBytes> head{};
  if (remaining < kRecordHeaderBytes) {
    const std::span<std::byte> part(head.data(), std::size_t(remaining));
    if (!source_->readAt(offset, part)) return Attempt::IoError;
    const std::size_t n = std::min(part.size(), kRecordMagic.size());
    return std::equal(part.begin(), part.begin() + std::ptrdiff_t(n), kRecordMagic.begin())
               ? Attempt::CutShort
               : Attempt::Invalid;
  }
  if (!source_->readAt(offset, head)) return Attempt::IoError;
  const std::optional<RecordHeader> header = parseRecordHeader(head);
  if (!header || header->payloadBytes > bound_(header->type)) return Attempt::Invalid;
  if (header->payloadBytes > remaining - kRecordHeaderBytes) return Attempt::CutShort;
  payload_.resize(header->payloadBytes);
  if (!source_->readAt(offset + kRecordHeaderBytes, payload_)) return Attempt::IoError;
  if (recordCrc(header->type, payload_) != header->crc) return Attempt::Invalid;
  out.type = header->type;
  out.offset = offset;
  out.payload = payload_;
  return Attempt::Valid;
}

bool RecordScanner::findMagic(std::uint64_t from, std::uint64_t& found) {
  std::uint64_t at = from;
  while (at < size_) {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(kSearchWindowBytes, size_ - at));
    window_.resize(n);
    if (!source_->readAt(at, window_)) return false;
    const auto hit = std::search(window_.begin(), window_.end(), kRecordMagic.begin(),
                                 kRecordMagic.end());
    if (hit != window_.end()) {
      found = at + std::uint64_t(hit - window_.begin());
      return true;
    }
    if (at + n >= size_) break;
    at += n - (kRecordMagic.size() - 1);  // overlap: a magic across two windows is still seen
  }
  found = size_;
  return true;
}

void RecordScanner::closeRegion(std::uint64_t end, bool atEnd) {
  if (atEnd && regionCutShort_) {
    stats_.truncatedTailBytes += end - regionStart_;
  } else {
    ++stats_.damagedRecords;
    stats_.damagedBytes += end - regionStart_;
  }
  inRegion_ = false;
}

ScanStep RecordScanner::next(ScannedRecord& out) {
  while (pos_ < size_) {
    const Attempt attempt = tryRecordAt(pos_, out);
    if (attempt == Attempt::IoError) return ScanStep::IoError;
    if (attempt == Attempt::Valid) {
      if (inRegion_) closeRegion(pos_, false);
      pos_ = out.endOffset();
      return ScanStep::Record;
    }
    if (!inRegion_) {
      inRegion_ = true;
      regionStart_ = pos_;
      regionCutShort_ = attempt == Attempt::CutShort;
    }
    if (!findMagic(pos_ + 1, pos_)) return ScanStep::IoError;
  }
  if (inRegion_) closeRegion(size_, true);
  return ScanStep::End;
}

void RecordScanner::seek(std::uint64_t offset) {
  pos_ = std::min(offset, size_);
  inRegion_ = false;
}

void RecordScanner::markDamaged(const ScannedRecord& record) {
  ++stats_.damagedRecords;
  stats_.damagedBytes += record.endOffset() - record.offset;
}

}  // namespace vem::recording
