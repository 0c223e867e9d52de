#include "proto/texel_packing.h"

#include <zstd.h>
#include <zstd_errors.h>

#include <bit>
#include <cmath>
#include <string>

#include "proto/stream_protocol.h"
#include "util/contract.h"

namespace vem::stream {
namespace {

constexpr std::uint32_t kFloatAbsMask = 0x7FFFFFFFU;
constexpr std::uint32_t kFloatInfBits = 0x7F800000U;
constexpr std::uint32_t kMaxHalfAsFloatBits = 0x477FE000U;        // 65504
constexpr std::uint32_t kMinNormalHalfAsFloatBits = 0x38800000U;  // 2^-14
constexpr std::uint32_t kHalfOfMinSubnormalBits = 0x33000000U;    // 2^-25: rounds to 0 (tie, even)
constexpr std::uint16_t kMaxHalfBits = 0x7BFF;

// Rounds `value >> shift` to nearest, ties to even.
std::uint32_t shiftRoundEven(std::uint32_t value, int shift) {
  const std::uint32_t kept = value >> shift;
  const std::uint32_t rest = value & ((1U << shift) - 1U);
  const std::uint32_t halfway = 1U << (shift - 1);
  return kept + ((rest > halfway || (rest == halfway && (kept & 1U) != 0)) ? 1U : 0U);
}

// Half bits of a finite |value| within the half range, given its float bits.
std::uint16_t halfMagnitude(std::uint32_t absBits) {
  if (absBits >= kMinNormalHalfAsFloatBits) {
    // Rebias the exponent (127 -> 15) and round the mantissa from 23 to 10 bits; a carry out of
    // the mantissa correctly bumps the exponent.
    return std::uint16_t(shiftRoundEven(absBits - ((127U - 15U) << 23), 13));
  }
  if (absBits <= kHalfOfMinSubnormalBits) return 0;
  // Subnormal half: value = m 2^-24 with m = mantissa24 2^(e - 150 + 24).
  const std::uint32_t exponent = absBits >> 23;
  const std::uint32_t mantissa = (absBits & 0x7FFFFFU) | 0x800000U;
  return std::uint16_t(shiftRoundEven(mantissa, int(126U - exponent)));
}

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
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const std::uint16_t sign = std::uint16_t((bits >> 16) & 0x8000U);
  const std::uint32_t absBits = bits & kFloatAbsMask;
  if (absBits > kFloatInfBits) return 0;  // NaN
  if (absBits > kMaxHalfAsFloatBits) return std::uint16_t(sign | kMaxHalfBits);
  return std::uint16_t(sign | halfMagnitude(absBits));
}

float floatFromHalf(std::uint16_t half) {
  const std::uint32_t sign = std::uint32_t(half & 0x8000U) << 16;
  const std::uint32_t exponent = (half >> 10) & 0x1FU;
  const std::uint32_t mantissa = half & 0x3FFU;
  if (exponent == 0) {
    const float magnitude = std::ldexp(float(mantissa), -24);
    return sign != 0 ? -magnitude : magnitude;
  }
  const std::uint32_t floatExponent = exponent == 0x1FU ? 0xFFU : exponent + (127U - 15U);
  return std::bit_cast<float>(sign | (floatExponent << 23) | (mantissa << 13));
}

std::string packTexels(std::span<const float> rgb, int zstdLevel, std::size_t* clampedCount) {
  std::string raw(rgb.size() * 2, '\0');
  std::size_t clamped = 0;
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    const std::uint32_t absBits = std::bit_cast<std::uint32_t>(rgb[i]) & kFloatAbsMask;
    if (absBits > kMaxHalfAsFloatBits && absBits <= kFloatInfBits) ++clamped;
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
