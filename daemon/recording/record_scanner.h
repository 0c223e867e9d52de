// RecordScanner: walks the records of a recording in file order, checking each one's magic, length
// and CRC32C, and resynchronising after damage (docs/vem-format.md, "Reading after damage").
//
// A record is valid when its header parses, its type's length bound holds, it lies wholly inside
// the source and its CRC matches. Anything else starts a damaged region, which ends at the next
// offset holding a valid record, found by searching for the magic one byte further on. Each
// region counts as one damaged record. A region that reaches the end of the source and starts with
// a record cut short (a plausible header whose record runs past the end, or a prefix of one) is a
// truncated tail instead: what a crash while writing the last record leaves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "recording/byte_source.h"
#include "recording/record_format.h"

namespace vem::recording {

struct DamageStats {
  std::uint64_t damagedRecords = 0;      // damaged regions, and valid records with bad contents
  std::uint64_t damagedBytes = 0;        // bytes in them, all skipped
  std::uint64_t truncatedTailBytes = 0;  // bytes of a last record cut short by the end of file
  std::uint64_t unknownRecords = 0;      // valid records of a type this version does not know

  friend bool operator==(const DamageStats&, const DamageStats&) = default;
};

struct ScannedRecord {
  std::uint16_t type = 0;
  std::uint64_t offset = 0;             // of the record's first byte
  std::span<const std::byte> payload;   // valid until the scanner's next call
  [[nodiscard]] std::uint64_t endOffset() const {
    return offset + kRecordHeaderBytes + payload.size();
  }
};

enum class ScanStep { Record, End, IoError };

class RecordScanner {
 public:
  // Largest payload a record of a type may have; records claiming more are damaged.
  using PayloadBound = std::function<std::uint64_t(std::uint16_t type)>;

  RecordScanner(ByteSource& source, PayloadBound bound, std::uint64_t start = 0);

  [[nodiscard]] ScanStep next(ScannedRecord& out);
  // Continues from `offset` (a record boundary), ending any damaged region without counting it.
  void seek(std::uint64_t offset);
  // Counts a record with a valid CRC whose contents turned out unusable as damaged.
  void markDamaged(const ScannedRecord& record);
  void countUnknown() { ++stats_.unknownRecords; }

  [[nodiscard]] const DamageStats& stats() const { return stats_; }
  [[nodiscard]] std::uint64_t position() const { return pos_; }

 private:
  enum class Attempt { Valid, Invalid, CutShort, IoError };
  Attempt tryRecordAt(std::uint64_t offset, ScannedRecord& out);
  // The next offset after `from` holding the magic, or the source's size; nullopt on I/O error.
  [[nodiscard]] bool findMagic(std::uint64_t from, std::uint64_t& found);
  void closeRegion(std::uint64_t end, bool atEnd);

  ByteSource* source_;
  PayloadBound bound_;
  std::uint64_t size_;
  std::uint64_t pos_;
  bool inRegion_ = false;
  bool regionCutShort_ = false;
  std::uint64_t regionStart_ = 0;
  std::vector<std::byte> payload_;
  std::vector<std::byte> window_;
  DamageStats stats_;
};

}  // namespace vem::recording
