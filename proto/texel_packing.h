// Texel packing: cube-map texels as they travel in an EnvironmentFrame (proto/vem_stream.proto):
// floats -> IEEE 754 binary16 ("half"), little endian, 2 bytes a value -> one zstd frame.
// Pure functions, no <expected> (the fuzz targets compile this with clang); thread-safe.
//
// Half range: the largest finite half is 65504. Map values are in cd/m^2 once calibrated, and the
// sun's disc (about 1.6e9 cd/m^2) exceeds that range, so the sender divides the texels by a power
// of two first (EnvironmentFrame.texel_scale, stream/frame_encoding.h). packTexels itself clamps
// every value beyond +-65504 (and +-inf) to +-65504 instead of sending inf, and reports how many it
// clamped, so a client never sees inf. NaN is sent as 0. Values below the smallest half subnormal
// (about 6e-8) become 0. Rounding is to nearest, ties to even (relative error <= 2^-11).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vem::stream {

inline constexpr float kMaxHalf = 65504.0F;

// IEEE binary16 bits of `value` (rounded to nearest even; clamped to +-kMaxHalf; NaN -> 0).
[[nodiscard]] std::uint16_t halfFromFloat(float value);
[[nodiscard]] float floatFromHalf(std::uint16_t half);

// `rgb` as halves compressed with zstd at `zstdLevel` (1..19; 3 is zstd's default). When
// `clampedCount` is not null it receives the number of values clamped to +-kMaxHalf (finite values
// beyond the half range and infinities).
[[nodiscard]] std::string packTexels(std::span<const float> rgb, int zstdLevel,
                                     std::size_t* clampedCount = nullptr);

struct UnpackResult {
  std::vector<float> rgb;  // expectedRawBytes / 2 values on success
  std::string error;       // empty on success; one sentence otherwise (rgb is then empty)
  [[nodiscard]] bool ok() const { return error.empty(); }
};

// The floats of `zstd` (the output of packTexels), which must decompress to exactly
// `expectedRawBytes` bytes. Refuses a size that is not a whole number of texels (6 bytes), a size
// over kMaxCubeRawBytes, a corrupt or truncated stream, and a stream holding more or fewer bytes;
// never allocates more than expectedRawBytes for the decompressed bytes (a stream that declares a
// larger size is refused before decoding).
[[nodiscard]] UnpackResult unpackTexels(std::string_view zstd, std::uint64_t expectedRawBytes);

}  // namespace vem::stream
