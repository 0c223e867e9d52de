#include "recording/recording_index.h"

#include "proto/vem_recording.pb.h"

namespace vem::recording {

std::vector<std::byte> encodeTrailer(std::span<const IndexEntry> entries,
                                     std::uint64_t indexOffset) {
  proto::RecordingIndex message;
  message.mutable_entries()->Reserve(int(entries.size()));
  for (const IndexEntry& entry : entries) {
    proto::IndexEntry* m = message.add_entries();
    m->set_seq(entry.seq);
    m->set_capture_ts_ns(entry.captureTsNs);
    m->set_offset(entry.offset);
  }
  std::vector<std::byte> bytes;
  beginRecord(bytes);
  bytes.resize(kRecordHeaderBytes + message.ByteSizeLong());
  message.SerializeWithCachedSizesToArray(
      reinterpret_cast<std::uint8_t*>(bytes.data() + kRecordHeaderBytes));
  finishRecord(bytes, RecordType::Index);

  std::array<std::byte, kFooterPayloadBytes> footer{};
  storeLe64(footer.data(), indexOffset);
  storeLe64(footer.data() + 8, bytes.size());
  appendRecord(bytes, RecordType::Footer, footer);
  return bytes;
}

std::optional<FooterFields> decodeFooterPayload(std::span<const std::byte> payload) {
  if (payload.size() != kFooterPayloadBytes) return std::nullopt;
  return FooterFields{loadLe64(payload.data()), loadLe64(payload.data() + 8)};
}

std::optional<std::vector<IndexEntry>> decodeIndexPayload(std::span<const std::byte> payload,
                                                          std::uint64_t firstFrameOffset,
                                                          std::uint64_t indexOffset) {
  proto::RecordingIndex message;
  if (payload.size() > std::size_t(INT32_MAX) ||
      !message.ParseFromArray(payload.data(), int(payload.size()))) {
    return std::nullopt;
  }
  std::vector<IndexEntry> entries;
  entries.reserve(std::size_t(message.entries_size()));
  std::uint64_t nextFree = firstFrameOffset;  // the first byte a next record could start at
  for (const proto::IndexEntry& m : message.entries()) {
    const IndexEntry entry{m.seq(), m.capture_ts_ns(), m.offset()};
    if (entry.offset < nextFree || entry.offset >= indexOffset ||
        indexOffset - entry.offset < kRecordHeaderBytes) {
      return std::nullopt;
    }
    nextFree = entry.offset + kRecordHeaderBytes;
    entries.push_back(entry);
  }
  return entries;
}

std::optional<std::size_t> seekEntry(std::span<const IndexEntry> entries, std::uint64_t seq) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].seq < seq) continue;
    if (!best || entries[i].seq < entries[*best].seq) best = i;
    if (entries[i].seq == seq) break;  // the least possible: none later can be better
  }
  return best;
}

}  // namespace vem::recording
