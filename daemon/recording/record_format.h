// The record framing of VEM recordings (docs/vem-format.md): a recording is a sequence of
// self-delimiting records, each a 16-byte header followed by its payload.
//
//   offset  size  field
//   0       4     magic 8A 56 45 4D ("\x8A" "VEM")
//   4       2     record type (RecordType), little-endian
//   6       2     reserved, 0
//   8       4     payload length in bytes, little-endian
//   12      4     CRC32C of bytes 4..11 followed by the payload, little-endian
//   16      ...   payload
//
// A reader that meets anything else resynchronises on the next magic. Pure: bytes in, bytes out.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vem::recording {

inline constexpr std::array<std::byte, 4> kRecordMagic{std::byte{0x8A}, std::byte{'V'},
                                                       std::byte{'E'}, std::byte{'M'}};
inline constexpr std::size_t kRecordHeaderBytes = 16;

enum class RecordType : std::uint16_t { Header = 1, Frame = 2, Index = 3, Footer = 4 };

struct RecordHeader {
  std::uint16_t type = 0;
  std::uint32_t payloadBytes = 0;
  std::uint32_t crc = 0;
};

// The header's fields when `bytes` starts with the magic and a zero reserved field, else nullopt.
// `bytes` must hold at least kRecordHeaderBytes.
[[nodiscard]] std::optional<RecordHeader> parseRecordHeader(std::span<const std::byte> bytes);

// The CRC a record of this type and payload carries.
[[nodiscard]] std::uint32_t recordCrc(std::uint16_t type, std::span<const std::byte> payload);

// Writes a record around a payload built in place: beginRecord leaves room for the header in
// `out` (cleared) and the caller appends the payload; finishRecord fills in the header.
void beginRecord(std::vector<std::byte>& out);
void finishRecord(std::vector<std::byte>& out, RecordType type);

// A whole record (header and a copy of `payload`) appended to `out`.
void appendRecord(std::vector<std::byte>& out, RecordType type, std::span<const std::byte> payload);

// Little-endian integers, as every fixed field of the format is stored.
void storeLe16(std::byte* at, std::uint16_t value);
void storeLe32(std::byte* at, std::uint32_t value);
void storeLe64(std::byte* at, std::uint64_t value);
[[nodiscard]] std::uint16_t loadLe16(const std::byte* at);
[[nodiscard]] std::uint32_t loadLe32(const std::byte* at);
[[nodiscard]] std::uint64_t loadLe64(const std::byte* at);

}  // namespace vem::recording
