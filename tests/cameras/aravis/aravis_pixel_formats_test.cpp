// The wire formats: decoding what pixel_packing.h packs (written from the specifications), by
// hand-made bytes for each layout, and the choice of native format.
#include "cameras/aravis/aravis_pixel_formats.h"

#include <gtest/gtest.h>

#include "pixel_packing.h"

namespace vem::cameras {
namespace {

std::vector<std::uint16_t> decode(std::string_view name, const std::vector<std::uint8_t>& bytes,
                                  int width, int height) {
  std::vector<std::uint16_t> codes;
  EXPECT_TRUE(decodePixels(*nativeFormatByName(name), bytes, width, height, codes)) << name;
  return codes;
}

TEST(AravisPixelFormats, Mono12PackedNibblesGoToTheRightPixel) {
  // p0 = 0xABC, p1 = 0x123: [0xAB][0x3C][0x12] (GigE Vision 2.x, Mono12Packed).
  EXPECT_EQ(decode("Mono12Packed", {0xAB, 0x3C, 0x12}, 2, 1),
            (std::vector<std::uint16_t>{0xABC, 0x123}));
}

TEST(AravisPixelFormats, Mono10PackedLowBitsAtBitsZeroAndFour) {
  // p0 = 0x2F1 (high 8 = 0xBC, low 2 = 01), p1 = 0x0A6 (high 8 = 0x29, low 2 = 10).
  EXPECT_EQ(decode("Mono10Packed", {0xBC, 0x21, 0x29}, 2, 1),
            (std::vector<std::uint16_t>{0x2F1, 0x0A6}));
}

TEST(AravisPixelFormats, Mono12pIsALittleEndianBitStream) {
  // p0 = 0xABC, p1 = 0x123: bits 0..11 and 12..23: bytes 0xBC, 0x3A, 0x12.
  EXPECT_EQ(decode("Mono12p", {0xBC, 0x3A, 0x12}, 2, 1),
            (std::vector<std::uint16_t>{0xABC, 0x123}));
}

TEST(AravisPixelFormats, Mono16IsLittleEndian) {
  EXPECT_EQ(decode("Mono16", {0x34, 0x12, 0xff, 0xff}, 2, 1),
            (std::vector<std::uint16_t>{0x1234, 0xffff}));
}

TEST(AravisPixelFormats, EveryLayoutRoundTripsAnOddSizedFrameThroughTheSpecPacker) {
  for (const NativePixelFormat& native : nativePixelFormats()) {
    const int width = 7, height = 3;
    std::vector<std::uint16_t> codes(std::size_t(width * height * native.format.channels));
    for (std::size_t i = 0; i < codes.size(); ++i)
      codes[i] = std::uint16_t((i * 2654435761u) % (native.format.maxCode() + 1));
    const auto bytes = vem::testing::packPixels(native.genicamName, codes);
    ASSERT_EQ(bytes.size(), payloadBytes(native, width, height)) << native.genicamName;
    EXPECT_EQ(decode(native.genicamName, bytes, width, height), codes) << native.genicamName;
  }
}

TEST(AravisPixelFormats, ShortDataIsRefusedNotOverread) {
  std::vector<std::uint16_t> codes;
  EXPECT_FALSE(
      decodePixels(*nativeFormatByName("Mono16"), std::vector<std::uint8_t>(7), 2, 2, codes));
}

TEST(AravisPixelFormats, EmptyRequestPicksTheDeepestOffered) {
  auto chosen = chooseNativeFormat("", {"Mono8", "Mono12Packed", "BayerRG8"});
  ASSERT_TRUE(chosen);
  EXPECT_EQ((*chosen)->genicamName, "Mono12Packed");
}

TEST(AravisPixelFormats, UnpackedVariantPreferredOverPacked) {
  auto chosen = chooseNativeFormat("Mono12", {"Mono12Packed", "Mono12", "Mono12p"});
  ASSERT_TRUE(chosen);
  EXPECT_EQ((*chosen)->genicamName, "Mono12");
}

TEST(AravisPixelFormats, MissingFormatIsRefusedNamingWhatIsOffered) {
  auto chosen = chooseNativeFormat("Mono12", {"Mono8", "BayerRG8"});
  ASSERT_FALSE(chosen);
  EXPECT_EQ(chosen.error(),
            "the camera offers no pixel format giving Mono12 (it offers Mono8, BayerRG8)");
  EXPECT_FALSE(chooseNativeFormat("RGB12", {"RGB8"}));
}

}  // namespace
}  // namespace vem::cameras
