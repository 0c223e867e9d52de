// The streaming protocol's version and limits (proto/vem_stream.proto, docs/protocol.md), shared by
// vemd's server and the clients. Header only, no <expected> (the fuzz targets compile it with
// clang).
//
// Conventions: sizes in bytes, face sizes in texels a side (Px), rates in Hz. A peer refuses a
// message whose protocol_major is not kProtocolMajor; minor versions only add fields.
#pragma once

#include <cstdint>

namespace vem::stream {

inline constexpr std::uint32_t kProtocolMajor = 1;
inline constexpr std::uint32_t kProtocolMinor = 1;

inline constexpr std::uint32_t kMaxLights = 65536;
inline constexpr std::uint64_t kMaxClientMessageBytes = 64 * 1024;
inline constexpr std::uint64_t kMaxServerMessageBytes = 64ULL * 1024 * 1024;

inline constexpr int kMinCubeFacePx = 8;
inline constexpr int kMaxCubeFacePx = 512;
inline constexpr int kDefaultCubeFacePx = 64;
inline constexpr int kMaxCubeLevels = 8;
inline constexpr double kMaxCubemapRateHz = 60.0;

// One cube-map texel on the wire: RGB as three IEEE half floats.
inline constexpr std::uint64_t kCubeTexelBytes = 6;

// The mip levels a cube map of `facePx` can have, at most `levelsAsked` (clamped to
// [1, kMaxCubeLevels]): level k has facePx >> k texels a side and each level halves the one above
// exactly, so the chain stops at the first odd size (64 -> up to 7 levels, 8 -> 4, 12 -> 3).
[[nodiscard]] constexpr int usableCubeLevels(int facePx, int levelsAsked) {
  const int asked =
      levelsAsked < 1 ? 1 : (levelsAsked > kMaxCubeLevels ? kMaxCubeLevels : levelsAsked);
  int levels = 1;
  for (int px = facePx; levels < asked && px >= 2 && px % 2 == 0; px /= 2) ++levels;
  return levels;
}

// Size of the decompressed texels of a cube map: 6 faces x (facePx >> k)^2 texels x 6 bytes, summed
// over the levels.
[[nodiscard]] constexpr std::uint64_t cubeRawBytes(int facePx, int levels) {
  std::uint64_t bytes = 0;
  for (int k = 0; k < levels; ++k) {
    const std::uint64_t px = std::uint64_t(facePx >> k);
    bytes += 6 * px * px * kCubeTexelBytes;
  }
  return bytes;
}

// The largest raw_bytes an EnvironmentFrame may declare (512 px, every level usable): 12.6 MB.
inline constexpr std::uint64_t kMaxCubeRawBytes =
    cubeRawBytes(kMaxCubeFacePx, usableCubeLevels(kMaxCubeFacePx, kMaxCubeLevels));

static_assert(usableCubeLevels(64, 8) == 7);
static_assert(usableCubeLevels(8, 8) == 4);
static_assert(usableCubeLevels(12, 8) == 3);
static_assert(usableCubeLevels(64, 0) == 1);
static_assert(kMaxCubeRawBytes < kMaxServerMessageBytes);

}  // namespace vem::stream
