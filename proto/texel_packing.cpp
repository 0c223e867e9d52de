#include "proto/texel_packing.h"

#include <Imath/half.h>
#include <zstd.h>
#include <zstd_errors.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "proto/stream_protocol.h"
#include "util/contract.h"

namespace vem::stream {
namespace {

struct DeclaredSize {
  bool corrupt = false;
  bool known = true;        // every frame declares its content size
  std::uint64_t bytes = 0;  // their sum, saturated at 2^64 - 1
};

// Walks the frames' headers (no decoding, no allocation).
DeclaredSize declaredSize(std::string_view zstd) {
  DeclaredSize out;
  out.corrupt = zstd.empty();
  for (std::size_t offset = 0; offset < zstd.size();) {
    const char* frame = zstd.data() + offset;
    const std::size_t rest = zstd.size() - offset;
    const unsigned long long content = ZSTD_getFrameContentSize(frame, rest);
    const std::size_t frameBytes = ZSTD_findFrameCompressedSize(frame, rest);
    if (content == ZSTD_CONTENTSIZE_ERROR || ZSTD_isError(frameBytes) != 0U || frameBytes == 0) {
      out.corrupt = true;
      return out;
    }
    if (content == ZSTD_CONTENTSIZE_UNKNOWN) {
      out.known = false;
    } else {
      out.bytes = content > UINT64_MAX - out.bytes ? UINT64_MAX : out.bytes + content;
    }
    offset += frameBytes;
  }
  return out;
}

}  // namespace

std::uint16_t halfFromFloat(float value) {
  if (std::isnan(value)) return 0;
  // Imath rounds to nearest even (subnormals included); clamping first keeps infinities and
  // values beyond the half range at the largest finite half instead of Imath's infinity.
  return Imath::half(std::clamp(value, -kMaxHalf, kMaxHalf)).bits();
}

float floatFromHalf(std::uint16_t half) {
  Imath::half value;
  value.setBits(half);
  return float(value);
}

std::string packTexels(std::span<const float> rgb, int zstdLevel, std::size_t* clampedCount) {
  std::string raw(rgb.size() * 2, '\0');
  std::size_t clamped = 0;
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    if (std::abs(rgb[i]) > kMaxHalf) ++clamped;  // NaN compares false: not counted
    const std::uint16_t half = halfFromFloat(rgb[i]);
    raw[2 * i] = char(half & 0xFFU);
    raw[2 * i + 1] = char(half >> 8);
  }
  if (clampedCount != nullptr) *clampedCount = clamped;
  std::string packed(ZSTD_compressBound(raw.size()), '\0');
  const std::size_t size =
      ZSTD_compress(packed.data(), packed.size(), raw.data(), raw.size(), zstdLevel);
  // Compressing into a buffer of ZSTD_compressBound bytes cannot fail but for a broken contract.
  VEM_EXPECTS(ZSTD_isError(size) == 0U);
  packed.resize(size);
  return packed;
}

UnpackResult unpackTexels(std::string_view zstd, std::uint64_t expectedRawBytes) {
  UnpackResult result;
  const std::string expected = std::to_string(expectedRawBytes);
  if (expectedRawBytes % kCubeTexelBytes != 0) {
    result.error = "cube-map texels: raw_bytes " + expected +
                   " is not a whole number of 6-byte RGB half texels";
    return result;
  }
  if (expectedRawBytes > kMaxCubeRawBytes) {
    result.error = "cube-map texels: raw_bytes " + expected + " exceeds the limit of " +
                   std::to_string(kMaxCubeRawBytes) + " bytes";
    return result;
  }
  // The frame headers' declared sizes, checked before allocating.
  const DeclaredSize declared = declaredSize(zstd);
  if (declared.corrupt) {
    result.error = "cube-map texels: the zstd stream is empty, corrupt or truncated";
    return result;
  }
  if (declared.known && declared.bytes != expectedRawBytes) {
    result.error = "cube-map texels: the zstd stream declares " + std::to_string(declared.bytes) +
                   " bytes, raw_bytes says " + expected;
    return result;
  }
  std::string raw(expectedRawBytes, '\0');
  const std::size_t size = ZSTD_decompress(raw.data(), raw.size(), zstd.data(), zstd.size());
  if (ZSTD_isError(size) != 0U) {
    const bool tooBig = ZSTD_getErrorCode(size) == ZSTD_error_dstSize_tooSmall;
    result.error =
        tooBig ? "cube-map texels: the zstd stream holds more than raw_bytes " + expected + " bytes"
               : std::string("cube-map texels: the zstd stream is corrupt (") +
                     ZSTD_getErrorName(size) + ")";
    return result;
  }
  if (size != expectedRawBytes) {
    result.error = "cube-map texels: the zstd stream holds " + std::to_string(size) +
                   " bytes, raw_bytes says " + expected;
    return result;
  }
  result.rgb.resize(raw.size() / 2);
  for (std::size_t i = 0; i < result.rgb.size(); ++i) {
    const auto lo = std::uint16_t(static_cast<unsigned char>(raw[2 * i]));
    const auto hi = std::uint16_t(static_cast<unsigned char>(raw[2 * i + 1]));
    result.rgb[i] = floatFromHalf(std::uint16_t(lo | (hi << 8)));
  }
  return result;
}

}  // namespace vem::stream
