// Frame records: one RawFrame with its capture time, sequence number and optional computed
// lights, as the payload of a RecordType::Frame record (docs/vem-format.md):
//
//   u32 little-endian M | M bytes vem.proto.FrameMeta | one zstd frame holding the codes
//
// The codes are 16-bit little-endian integers, row-major, channels interleaved, split into a
// low-byte plane then a high-byte plane before compression (SAMPLE_ENCODING_U16LE_BYTE_PLANES,
// which compresses smooth sensor images better); the plain interleaved encoding is also read.
// Lossless: decoding gives back the same codes, exposure, gain and light floats bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/light.h"
#include "frames/raw_frame.h"
#include "recording/read_limits.h"
#include "recording/recording_header.h"

namespace vem::recording {

// zstd level of new recordings: see docs/vem-format.md for the measured trade-off.
inline constexpr int kDefaultZstdLevel = 1;

struct RecordedFrame {
  std::uint64_t seq = 0;          // the camera's frame sequence number
  std::int64_t captureTsNs = 0;   // capture time, ns on the writer's clock
  RawFrame frame;
  std::optional<LightSet> lights;
};

// A frame record's metadata, without its pixels.
struct FrameSummary {
  std::uint64_t seq = 0;
  std::int64_t captureTsNs = 0;
  bool hasLights = false;
  std::uint64_t compressedBytes = 0;
};

// Encodes and decodes frame payloads, keeping zstd's contexts and scratch buffers between frames.
class FrameCodec {
 public:
  explicit FrameCodec(int zstdLevel = kDefaultZstdLevel);
  ~FrameCodec();
  FrameCodec(FrameCodec&&) noexcept;
  FrameCodec& operator=(FrameCodec&&) noexcept;

  // The whole frame record into `record` (replaced). The frame must match the header's size and
  // pixel format, with width x height x channels codes (checked by the caller).
  void encodeRecord(std::uint64_t seq, std::int64_t captureTsNs, const RawFrame& frame,
                    const LightSet* lights, std::vector<std::byte>& record);

  // The metadata of a frame payload whose record CRC matched; nullopt when it does not fit
  // `header` (size, pixel format, byte counts). Does not decompress.
  [[nodiscard]] std::optional<FrameSummary> decodeSummary(std::span<const std::byte> payload,
                                                          const RecordingHeader& header,
                                                          const ReadLimits& limits) const;

  // The whole frame into `out` (its buffers are reused); false when the payload does not fit the
  // header or does not decompress to exactly one frame of codes.
  [[nodiscard]] bool decode(std::span<const std::byte> payload, const RecordingHeader& header,
                            const ReadLimits& limits, RecordedFrame& out);

 private:
  struct Contexts;
  std::unique_ptr<Contexts> contexts_;
  int level_;
  std::vector<std::byte> scratch_;     // the codes as bytes (planes) before compression
  std::vector<std::byte> compressed_;  // zstd's output before it is copied into the record
};

}  // namespace vem::recording
