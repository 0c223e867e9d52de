// libcamera's memory layouts, widened into RawFrame codes (libcamera_pixel_layout.h), checked
// against bytes written by hand from the DRM format definitions; and the fake packs the same way.
#include "cameras/libcamera/libcamera_pixel_layout.h"

#include <gtest/gtest.h>

#include "fake_libcamera_port.h"

namespace vem::cameras {
namespace {

TEST(LibcameraPixelLayout, R16WordsAreLittleEndianAndRowPaddingIsSkipped) {
  // 2 x 2 pixels, stride 6 bytes: 2 padding bytes per row that must not be read as pixels.
  const std::vector<std::uint8_t> bytes = {0x34, 0x12, 0xff, 0xff, 0xaa, 0xaa,
                                           0x01, 0x00, 0x00, 0x80, 0xbb, 0xbb};
  vem::RawFrame frame;
  ASSERT_FALSE(unpackLibcameraFrame(kLibcameraR16, {2, 2}, 6, bytes, frame));
  EXPECT_EQ(frame.format, (vem::PixelFormat{1, 16}));
  EXPECT_EQ(frame.codes, (std::vector<std::uint16_t>{0x1234, 0xffff, 0x0001, 0x8000}));
}

TEST(LibcameraPixelLayout, Rgb888IsBlueGreenRedInMemory) {
  const std::vector<std::uint8_t> bytes = {3, 2, 1, 30, 20, 10};
  vem::RawFrame frame;
  ASSERT_FALSE(unpackLibcameraFrame(kLibcameraRGB888, {2, 1}, 6, bytes, frame));
  EXPECT_EQ(frame.format, (vem::PixelFormat{3, 8}));
  EXPECT_EQ(frame.codes, (std::vector<std::uint16_t>{1, 2, 3, 10, 20, 30}));
}

TEST(LibcameraPixelLayout, Bgr888IsRedGreenBlueInMemory) {
  const std::vector<std::uint8_t> bytes = {1, 2, 3};
  vem::RawFrame frame;
  ASSERT_FALSE(unpackLibcameraFrame(kLibcameraBGR888, {1, 1}, 3, bytes, frame));
  EXPECT_EQ(frame.codes, (std::vector<std::uint16_t>{1, 2, 3}));
}

TEST(LibcameraPixelLayout, R8BytesWidenToMono8Codes) {
  const std::vector<std::uint8_t> bytes = {0, 255, 7, 9};
  vem::RawFrame frame;
  ASSERT_FALSE(unpackLibcameraFrame(kLibcameraR8, {1, 2}, 2, bytes, frame));  // stride 2
  EXPECT_EQ(frame.format, (vem::PixelFormat{1, 8}));
  EXPECT_EQ(frame.codes, (std::vector<std::uint16_t>{0, 7}));
}

TEST(LibcameraPixelLayout, R12CodeAboveItsLargestIsRefusedNotPassedOn) {
  const std::vector<std::uint8_t> bytes = {0xff, 0x0f, 0x00, 0x10};  // 4095, then 4096
  vem::RawFrame frame;
  const auto problem = unpackLibcameraFrame(kLibcameraR12, {2, 1}, 4, bytes, frame);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("4095"), std::string::npos) << *problem;
}

TEST(LibcameraPixelLayout, ShortBufferIsRefusedInsteadOfOverread) {
  const std::vector<std::uint8_t> bytes(2 * 64 + 10);  // the last row needs 2 x 8 bytes
  vem::RawFrame frame;
  EXPECT_TRUE(unpackLibcameraFrame(kLibcameraR16, {8, 3}, 64, bytes, frame));
}

TEST(LibcameraPixelLayout, PackedCsi2AndYuvFormatsAreNotTaken) {
  EXPECT_FALSE(calibFormatOf({drmFourcc('R', '1', '0', ' '), (std::uint64_t(11) << 56) | 1}));
  EXPECT_FALSE(calibFormatOf({drmFourcc('Y', 'U', 'Y', 'V'), 0}));
  EXPECT_EQ(libcameraFormatName({drmFourcc('R', '1', '0', ' '), (std::uint64_t(11) << 56) | 1}),
            "R10_CSI2P");
  EXPECT_EQ(calibFormatOf(kLibcameraR10), (vem::PixelFormat{1, 10}));
}

TEST(LibcameraPixelLayout, FakePacksRgb888BlueFirstLikeLibcamera) {
  vem::RawFrame frame = vem::RawFrame::blank(1, 1, {3, 8});
  frame.codes = {1, 2, 3};
  std::vector<std::uint8_t> bytes(3);
  testing::packLibcameraFrame(kLibcameraRGB888, 3, frame, bytes);
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{3, 2, 1}));
  testing::packLibcameraFrame(kLibcameraBGR888, 3, frame, bytes);
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{1, 2, 3}));
}

}  // namespace
}  // namespace vem::cameras
