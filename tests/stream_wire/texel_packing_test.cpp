// packTexels / unpackTexels: half precision round trip, known bit patterns, clamping beyond the
// half range, and refusal of bad streams and sizes without allocating what they declare.
#include "proto/texel_packing.h"

#include <gtest/gtest.h>
#include <zstd.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "proto/stream_protocol.h"
#include "stream_wire/allocation_tracker.h"

namespace vem::stream {
namespace {

std::size_t largestAllocationDuring(const auto& call) {
  testing::startTrackingAllocations();
  call();
  return testing::stopTrackingAllocations();
}

std::vector<float> testTexels(std::size_t count) {
  std::mt19937 random(42);
  std::uniform_real_distribution<float> exponent(-12.0F, 15.9F);
  std::vector<float> rgb(count);
  for (float& v : rgb) v = std::exp2(exponent(random));
  return rgb;
}

TEST(TexelPacking, RoundTripKeepsValuesWithinHalfPrecision) {
  const std::vector<float> rgb = testTexels(3 * 6 * 32 * 32);
  const std::string packed = packTexels(rgb, 3);
  const UnpackResult unpacked = unpackTexels(packed, rgb.size() * 2);
  ASSERT_TRUE(unpacked.ok()) << unpacked.error;
  ASSERT_EQ(unpacked.rgb.size(), rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    ASSERT_NEAR(unpacked.rgb[i], rgb[i], 1e-3 * double(rgb[i])) << i;
  }
}

TEST(TexelPacking, HalfBitsMatchIeeeBinary16) {
  EXPECT_EQ(halfFromFloat(1.0F), 0x3C00);
  EXPECT_EQ(halfFromFloat(-2.0F), 0xC000);
  EXPECT_EQ(halfFromFloat(0.1F), 0x2E66);
  EXPECT_EQ(halfFromFloat(65504.0F), 0x7BFF);
  EXPECT_EQ(halfFromFloat(std::ldexp(1.0F, -14)), 0x0400);  // smallest normal
  EXPECT_EQ(halfFromFloat(std::ldexp(1.0F, -24)), 0x0001);  // smallest subnormal
  EXPECT_EQ(halfFromFloat(std::ldexp(1.0F, -25)), 0x0000);  // tie: to even (0)
  EXPECT_EQ(halfFromFloat(std::ldexp(1.5F, -25)), 0x0001);
  EXPECT_EQ(halfFromFloat(1.0F + std::ldexp(1.0F, -11)), 0x3C00);      // tie: to even
  EXPECT_EQ(halfFromFloat(1.0F + 3 * std::ldexp(1.0F, -11)), 0x3C02);  // tie: to even
  EXPECT_EQ(halfFromFloat(2047.5F), 0x6800);  // mantissa carry into the exponent (2048)
  for (const std::uint16_t bits :
       {0x0000, 0x0001, 0x03FF, 0x0400, 0x3C00, 0x3555, 0x7BFF, 0xBC00}) {
    EXPECT_EQ(halfFromFloat(floatFromHalf(bits)), bits) << bits;
  }
  EXPECT_FLOAT_EQ(floatFromHalf(0x3555), 0.333251953125F);
  EXPECT_FLOAT_EQ(floatFromHalf(0x0001), std::ldexp(1.0F, -24));
}

TEST(TexelPacking, ValuesBeyondHalfRangeClampToTheLargestFiniteHalfNotInfinity) {
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> rgb{1e5F, inf, -1e9F, 65504.0F, std::numeric_limits<float>::quiet_NaN(),
                               1.0F};
  std::size_t clamped = 99;
  const UnpackResult unpacked = unpackTexels(packTexels(rgb, 3, &clamped), rgb.size() * 2);
  ASSERT_TRUE(unpacked.ok()) << unpacked.error;
  EXPECT_EQ(clamped, 3U);
  EXPECT_EQ(unpacked.rgb,
            (std::vector<float>{65504.0F, 65504.0F, -65504.0F, 65504.0F, 0.0F, 1.0F}));
}

TEST(TexelPacking, SizeMismatchIsRefused) {
  const std::vector<float> rgb = testTexels(300);
  const std::string packed = packTexels(rgb, 3);
  EXPECT_FALSE(unpackTexels(packed, rgb.size() * 2 + 6).ok());
  EXPECT_FALSE(unpackTexels(packed, rgb.size() * 2 - 6).ok());
  EXPECT_TRUE(unpackTexels(packed, rgb.size() * 2).ok());
}

TEST(TexelPacking, SizeMismatchIsRefusedWhenTheFrameDoesNotDeclareItsSize) {
  // A streamed frame without a content size in its header: the decoder itself must notice.
  const std::vector<float> rgb = testTexels(300);
  std::string raw(rgb.size() * 2, '\0');
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = char(i * 31);
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_contentSizeFlag, 0);
  std::string packed(ZSTD_compressBound(raw.size()), '\0');
  ZSTD_outBuffer out{packed.data(), packed.size(), 0};
  ZSTD_inBuffer in{raw.data(), raw.size(), 0};
  ASSERT_EQ(ZSTD_compressStream2(context, &out, &in, ZSTD_e_end), 0U);
  ZSTD_freeCCtx(context);
  packed.resize(out.pos);
  ASSERT_EQ(ZSTD_getFrameContentSize(packed.data(), packed.size()), ZSTD_CONTENTSIZE_UNKNOWN);
  EXPECT_FALSE(unpackTexels(packed, raw.size() - 6).ok());
  EXPECT_FALSE(unpackTexels(packed, raw.size() + 6).ok());
  EXPECT_TRUE(unpackTexels(packed, raw.size()).ok());
}

TEST(TexelPacking, TruncatedStreamIsRefused) {
  const std::vector<float> rgb = testTexels(3000);
  const std::string packed = packTexels(rgb, 3);
  for (const std::size_t cut :
       {std::size_t(1), std::size_t(4), packed.size() / 2, packed.size() - 1}) {
    const UnpackResult unpacked =
        unpackTexels(std::string_view(packed).substr(0, cut), rgb.size() * 2);
    EXPECT_FALSE(unpacked.ok()) << cut;
    EXPECT_TRUE(unpacked.rgb.empty());
  }
}

TEST(TexelPacking, CorruptStreamIsRefused) {
  const std::vector<float> rgb = testTexels(3000);
  std::string packed = packTexels(rgb, 3);
  EXPECT_FALSE(unpackTexels("", rgb.size() * 2).ok());
  EXPECT_FALSE(unpackTexels("not a zstd stream at all", rgb.size() * 2).ok());
  std::string badMagic = packed;
  badMagic[0] = char(badMagic[0] ^ 0x55);
  EXPECT_FALSE(unpackTexels(badMagic, rgb.size() * 2).ok());
  std::string trailing = packed + "xyz";
  EXPECT_FALSE(unpackTexels(trailing, rgb.size() * 2).ok());
}

TEST(TexelPacking, RawSizeThatIsNotWholeTexelsIsRefused) {
  const std::string packed = packTexels(std::vector<float>(4, 1.0F), 3);  // 8 bytes
  const UnpackResult unpacked = unpackTexels(packed, 8);
  EXPECT_FALSE(unpacked.ok());
  EXPECT_NE(unpacked.error.find("whole number"), std::string::npos) << unpacked.error;
}

TEST(TexelPacking, RawSizeOverTheLimitIsRefusedWithoutAllocatingIt) {
  const std::string packed = packTexels(std::vector<float>(6, 1.0F), 3);
  for (const std::uint64_t huge :
       {kMaxCubeRawBytes + 6, std::uint64_t(6) << 40, std::uint64_t(6) << 60}) {
    UnpackResult unpacked;
    const std::size_t largest =
        largestAllocationDuring([&] { unpacked = unpackTexels(packed, huge); });
    EXPECT_FALSE(unpacked.ok()) << huge;
    EXPECT_NE(unpacked.error.find("limit"), std::string::npos) << unpacked.error;
    EXPECT_LT(largest, std::size_t(1) << 16);
  }
}

TEST(TexelPacking, StreamDeclaringAHugeSizeIsRefusedWithoutAllocatingIt) {
  // A hand-made frame: magic, a header declaring 2^40 bytes (8-byte content size, single segment),
  // then one last RLE block of 1000 bytes of 0x2A.
  std::string frame = {'\x28', '\xB5', '\x2F', '\xFD', '\xE0'};
  for (int i = 0; i < 8; ++i) frame += char(i == 5 ? 0x01 : 0x00);
  const std::uint32_t block = (1000U << 3) | (1U << 1) | 1U;
  frame += {char(block & 0xFF), char((block >> 8) & 0xFF), char(block >> 16), '\x2A'};
  const std::uint64_t expected = kMaxCubeRawBytes - kMaxCubeRawBytes % 6;
  UnpackResult unpacked;
  const std::size_t largest =
      largestAllocationDuring([&] { unpacked = unpackTexels(frame, expected); });
  EXPECT_FALSE(unpacked.ok());
  EXPECT_LT(largest, std::size_t(1) << 16) << unpacked.error;
}

}  // namespace
}  // namespace vem::stream
