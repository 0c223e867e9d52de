// The trailing index of a VEM recording (docs/vem-format.md): an Index record listing where each
// frame record starts (vem.proto.RecordingIndex), then a fixed 32-byte Footer record at the very
// end of the file pointing back to it:
//
//   Footer payload (16 bytes): u64 little-endian offset of the Index record,
//                              u64 little-endian size of the Index record (header + payload)
//
// The index only speeds up seeking and counting: every frame can be found without it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "recording/record_format.h"

namespace vem::recording {

inline constexpr std::size_t kFooterPayloadBytes = 16;
inline constexpr std::size_t kFooterRecordBytes = kRecordHeaderBytes + kFooterPayloadBytes;

struct IndexEntry {
  std::uint64_t seq = 0;
  std::int64_t captureTsNs = 0;
  std::uint64_t offset = 0;  // of the frame record's first byte

  friend bool operator==(const IndexEntry&, const IndexEntry&) = default;
};

// The Index record for `entries` followed by the Footer record, for a file in which the Index
// record will start at byte `indexOffset`.
[[nodiscard]] std::vector<std::byte> encodeTrailer(std::span<const IndexEntry> entries,
                                                   std::uint64_t indexOffset);

struct FooterFields {
  std::uint64_t indexOffset = 0;
  std::uint64_t indexRecordBytes = 0;
};

// The footer's fields when `payload` is a Footer record's 16-byte payload.
[[nodiscard]] std::optional<FooterFields> decodeFooterPayload(std::span<const std::byte> payload);

// The entries of an Index record's payload, when it parses and is consistent with a file whose
// frame records lie in [firstFrameOffset, indexOffset): offsets increasing, each entry leaving
// room for a record before the next. Sequence numbers need not increase: the index lists every
// intact frame in file order, a frame out of order or a counter that wrapped included.
[[nodiscard]] std::optional<std::vector<IndexEntry>> decodeIndexPayload(
    std::span<const std::byte> payload, std::uint64_t firstFrameOffset, std::uint64_t indexOffset);

// Where seeking to `seq` lands among `entries` (in file order): the entry with the least sequence
// number at or above `seq`, the first in file order among equals; nullopt when every entry's is
// below. With increasing numbers that is the first entry at or after `seq`; with a frame out of
// order it is still the frame numbered `seq` when there is one. Linear in the entries.
[[nodiscard]] std::optional<std::size_t> seekEntry(std::span<const IndexEntry> entries,
                                                   std::uint64_t seq);

}  // namespace vem::recording
