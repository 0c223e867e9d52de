#include "recording/frame_codec.h"

#include <bit>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include <zstd.h>

#include "proto/vem_recording.pb.h"
#include "recording/record_format.h"

namespace vem::recording {

struct FrameCodec::Contexts {
  ZSTD_CCtx* compress = nullptr;
  ZSTD_DCtx* decompress = nullptr;
  Contexts() = default;
  Contexts(const Contexts&) = delete;
  Contexts& operator=(const Contexts&) = delete;
  ~Contexts() {
    ZSTD_freeCCtx(compress);
    ZSTD_freeDCtx(decompress);
  }
};

namespace {

constexpr proto::SampleEncoding kWrittenEncoding = proto::SAMPLE_ENCODING_U16LE_BYTE_PLANES;

// The frame's codes as the encoding's bytes, into `bytes` (resized).
void codesToBytes(std::span<const std::uint16_t> codes, proto::SampleEncoding encoding,
                  std::vector<std::byte>& bytes) {
  const std::size_t n = codes.size();
  bytes.resize(2 * n);
  if (encoding == proto::SAMPLE_ENCODING_U16LE_BYTE_PLANES) {
    std::byte* low = bytes.data();
    std::byte* high = bytes.data() + n;
    for (std::size_t i = 0; i < n; ++i) {
      low[i] = std::byte(codes[i] & 0xFFu);
      high[i] = std::byte(codes[i] >> 8);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) storeLe16(bytes.data() + 2 * i, codes[i]);
  }
}

void bytesToCodes(std::span<const std::byte> bytes, proto::SampleEncoding encoding,
                  std::span<std::uint16_t> codes) {
  const std::size_t n = codes.size();
  if (encoding == proto::SAMPLE_ENCODING_U16LE_BYTE_PLANES) {
    const std::byte* low = bytes.data();
    const std::byte* high = bytes.data() + n;
    for (std::size_t i = 0; i < n; ++i) {
      codes[i] = std::uint16_t(std::uint16_t(low[i]) | std::uint16_t(std::uint16_t(high[i]) << 8));
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) codes[i] = loadLe16(bytes.data() + 2 * i);
  }
}

void lightsToMessage(const LightSet& lights, proto::LightSet& message) {
  message.set_luminance_sr(lights.luminanceSr);
  message.set_black(lights.black);
  message.mutable_lights()->Reserve(int(lights.lights.size()));
  for (const Light& light : lights.lights) {
    proto::Light* m = message.add_lights();
    m->set_id(light.id);
    for (int i = 0; i < 3; ++i) m->add_dir(light.dir[i]);
    for (int i = 0; i < 3; ++i) m->add_rgb(light.rgb[i]);
  }
}

bool lightsFromMessage(const proto::LightSet& message, LightSet& lights) {
  lights.luminanceSr = message.luminance_sr();
  lights.black = message.black();
  lights.lights.clear();
  lights.lights.reserve(std::size_t(message.lights_size()));
  for (const proto::Light& m : message.lights()) {
    if (m.dir_size() != 3 || m.rgb_size() != 3) return false;
    Light& light = lights.lights.emplace_back();
    light.id = m.id();
    for (int i = 0; i < 3; ++i) light.dir[i] = m.dir(i);
    for (int i = 0; i < 3; ++i) light.rgb[i] = m.rgb(i);
  }
  return true;
}

// A payload split into its checked metadata and its compressed codes.
struct ParsedPayload {
  proto::FrameMeta meta;
  std::span<const std::byte> compressed;
};

bool parsePayload(std::span<const std::byte> payload, const RecordingHeader& header,
                  const ReadLimits& limits, ParsedPayload& parsed) {
  if (payload.size() < 4) return false;
  const std::uint32_t metaBytes = loadLe32(payload.data());
  if (metaBytes > limits.maxFrameMetaBytes || metaBytes > payload.size() - 4) return false;
  if (!parsed.meta.ParseFromArray(payload.data() + 4, int(metaBytes))) return false;
  const proto::FrameMeta& meta = parsed.meta;
  parsed.compressed = payload.subspan(4 + std::size_t(metaBytes));
  const std::uint64_t expectedBytes = frameBytes(header);
  if (meta.width_px() != std::uint32_t(header.sensorWidthPx) ||
      meta.height_px() != std::uint32_t(header.sensorHeightPx) ||
      meta.pixel_format() != pixelFormatName(header.pixelFormat) ||
      meta.uncompressed_bytes() != expectedBytes ||
      meta.compressed_bytes() != parsed.compressed.size()) {
    return false;
  }
  if (meta.sample_encoding() != proto::SAMPLE_ENCODING_U16LE &&
      meta.sample_encoding() != proto::SAMPLE_ENCODING_U16LE_BYTE_PLANES) {
    return false;
  }
  // Exactly one zstd frame that announces exactly one frame of codes.
  const void* src = parsed.compressed.data();
  const std::size_t srcBytes = parsed.compressed.size();
  return ZSTD_getFrameContentSize(src, srcBytes) == expectedBytes &&
         ZSTD_findFrameCompressedSize(src, srcBytes) == srcBytes;
}

}  // namespace

FrameCodec::FrameCodec(int zstdLevel) : contexts_(std::make_unique<Contexts>()), level_(zstdLevel) {}
FrameCodec::~FrameCodec() = default;
FrameCodec::FrameCodec(FrameCodec&&) noexcept = default;
FrameCodec& FrameCodec::operator=(FrameCodec&&) noexcept = default;

void FrameCodec::encodeRecord(std::uint64_t seq, std::int64_t captureTsNs, const RawFrame& frame,
                              const LightSet* lights, std::vector<std::byte>& record) {
  if (contexts_->compress == nullptr) contexts_->compress = ZSTD_createCCtx();
  if (contexts_->compress == nullptr) throw std::bad_alloc();
  codesToBytes(frame.codes, kWrittenEncoding, scratch_);
  compressed_.resize(ZSTD_compressBound(scratch_.size()));
  const std::size_t compressedBytes =
      ZSTD_compressCCtx(contexts_->compress, compressed_.data(), compressed_.size(),
                        scratch_.data(), scratch_.size(), level_);
  if (ZSTD_isError(compressedBytes) != 0u) {
    // Only a bug (an output buffer of compressBound always suffices) or memory exhaustion.
    throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(compressedBytes));
  }
  proto::FrameMeta meta;
  meta.set_capture_ts_ns(captureTsNs);
  meta.set_seq(seq);
  meta.set_exposure_us(frame.exposureUs);
  meta.set_gain(frame.gain);
  meta.set_width_px(std::uint32_t(frame.width));
  meta.set_height_px(std::uint32_t(frame.height));
  meta.set_pixel_format(pixelFormatName(frame.format));
  meta.set_sample_encoding(kWrittenEncoding);
  meta.set_compressed_bytes(compressedBytes);
  meta.set_uncompressed_bytes(scratch_.size());
  if (lights != nullptr) lightsToMessage(*lights, *meta.mutable_lights());
  const std::size_t metaBytes = meta.ByteSizeLong();

  beginRecord(record);
  record.resize(kRecordHeaderBytes + 4 + metaBytes + compressedBytes);
  std::byte* payload = record.data() + kRecordHeaderBytes;
  storeLe32(payload, std::uint32_t(metaBytes));
  meta.SerializeWithCachedSizesToArray(reinterpret_cast<std::uint8_t*>(payload + 4));
  std::memcpy(payload + 4 + metaBytes, compressed_.data(), compressedBytes);
  finishRecord(record, RecordType::Frame);
}

std::optional<FrameSummary> FrameCodec::decodeSummary(std::span<const std::byte> payload,
                                                      const RecordingHeader& header,
                                                      const ReadLimits& limits) const {
  ParsedPayload parsed;
  if (!parsePayload(payload, header, limits, parsed)) return std::nullopt;
  const proto::FrameMeta& m = parsed.meta;
  if (m.has_lights()) {
    for (const proto::Light& light : m.lights().lights()) {
      if (light.dir_size() != 3 || light.rgb_size() != 3) return std::nullopt;
    }
  }
  return FrameSummary{m.seq(), m.capture_ts_ns(), m.has_lights(), m.compressed_bytes()};
}

bool FrameCodec::decode(std::span<const std::byte> payload, const RecordingHeader& header,
                        const ReadLimits& limits, RecordedFrame& out) {
  ParsedPayload parsed;
  if (!parsePayload(payload, header, limits, parsed)) return false;
  const proto::FrameMeta& m = parsed.meta;
  if (m.has_lights()) {
    if (!lightsFromMessage(m.lights(), out.lights.emplace())) return false;
  } else {
    out.lights.reset();
  }
  out.seq = m.seq();
  out.captureTsNs = m.capture_ts_ns();
  RawFrame& frame = out.frame;
  frame.width = header.sensorWidthPx;
  frame.height = header.sensorHeightPx;
  frame.format = header.pixelFormat;
  frame.exposureUs = m.exposure_us();
  frame.gain = m.gain();
  const std::size_t bytes = std::size_t(frameBytes(header));
  frame.codes.resize(bytes / 2);

  if (contexts_->decompress == nullptr) contexts_->decompress = ZSTD_createDCtx();
  if (contexts_->decompress == nullptr) throw std::bad_alloc();
  const bool direct = m.sample_encoding() == proto::SAMPLE_ENCODING_U16LE &&
                      std::endian::native == std::endian::little;
  void* target = direct ? static_cast<void*>(frame.codes.data()) : nullptr;
  if (!direct) {
    scratch_.resize(bytes);
    target = scratch_.data();
  }
  const std::size_t got = ZSTD_decompressDCtx(contexts_->decompress, target, bytes,
                                              parsed.compressed.data(), parsed.compressed.size());
  if (ZSTD_isError(got) != 0u || got != bytes) return false;
  if (!direct) bytesToCodes(scratch_, m.sample_encoding(), frame.codes);
  return true;
}

}  // namespace vem::recording
