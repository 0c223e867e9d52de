#include "recording/record_format.h"

#include <algorithm>

#include "recording/crc32c.h"
#include "util/contract.h"

namespace vem::recording {

std::optional<RecordHeader> parseRecordHeader(std::span<const std::byte> bytes) {
  VEM_EXPECTS(bytes.size() >= kRecordHeaderBytes);
  if (!std::equal(kRecordMagic.begin(), kRecordMagic.end(), bytes.begin())) return std::nullopt;
  if (loadLe16(bytes.data() + 6) != 0) return std::nullopt;
  return RecordHeader{loadLe16(bytes.data() + 4), loadLe32(bytes.data() + 8),
                      loadLe32(bytes.data() + 12)};
}

std::uint32_t recordCrc(std::uint16_t type, std::span<const std::byte> payload) {
  std::array<std::byte, 8> fields{};
  storeLe16(fields.data(), type);
  storeLe16(fields.data() + 2, 0);
  storeLe32(fields.data() + 4, std::uint32_t(payload.size()));
  return crc32c(payload, crc32c(fields));
}

void beginRecord(std::vector<std::byte>& out) { out.assign(kRecordHeaderBytes, std::byte{0}); }

void finishRecord(std::vector<std::byte>& out, RecordType type) {
  VEM_EXPECTS(out.size() >= kRecordHeaderBytes && out.size() - kRecordHeaderBytes <= UINT32_MAX);
  const auto payload = std::span<const std::byte>(out).subspan(kRecordHeaderBytes);
  std::copy(kRecordMagic.begin(), kRecordMagic.end(), out.begin());
  storeLe16(out.data() + 4, std::uint16_t(type));
  storeLe16(out.data() + 6, 0);
  storeLe32(out.data() + 8, std::uint32_t(payload.size()));
  storeLe32(out.data() + 12, recordCrc(std::uint16_t(type), payload));
}

void appendRecord(std::vector<std::byte>& out, RecordType type,
                  std::span<const std::byte> payload) {
  std::vector<std::byte> record;
  beginRecord(record);
  record.insert(record.end(), payload.begin(), payload.end());
  finishRecord(record, type);
  out.insert(out.end(), record.begin(), record.end());
}

void storeLe16(std::byte* at, std::uint16_t value) {
  for (int i = 0; i < 2; ++i) at[i] = std::byte(value >> (8 * i));
}
void storeLe32(std::byte* at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) at[i] = std::byte(value >> (8 * i));
}
void storeLe64(std::byte* at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) at[i] = std::byte(value >> (8 * i));
}
std::uint16_t loadLe16(const std::byte* at) {
  return std::uint16_t(std::uint16_t(at[0]) | std::uint16_t(std::uint16_t(at[1]) << 8));
}
std::uint32_t loadLe32(const std::byte* at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | std::uint32_t(at[i]);
  return value;
}
std::uint64_t loadLe64(const std::byte* at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | std::uint64_t(at[i]);
  return value;
}

}  // namespace vem::recording
