// Unpacking every V4L2 format the backend reads: hand-written buffers from the kernel's format
// documentation (exact pixels), and round trips through the fake's independent writer at padded
// bytesperline.
#include <gtest/gtest.h>

#include <random>

#include "cameras/v4l2/fake_v4l2_frames.h"
#include "cameras/v4l2/v4l2_formats.h"
#include "cameras/v4l2/v4l2_unpack.h"

namespace vem::cameras {
namespace {

using Bytes = std::vector<std::uint8_t>;

vem::RawFrame unpack(const Bytes& bytes, std::uint32_t fourcc, int w, int h, std::size_t bpl,
                     vem::PixelFormat output) {
  vem::RawFrame frame;
  unpackV4l2Frame(std::as_bytes(std::span(bytes)), {fourcc, w, h, bpl, output}, frame);
  return frame;
}

std::vector<std::uint16_t> codes(const vem::RawFrame& f) { return f.codes; }

TEST(V4l2Unpack, Y16IsLittleEndianAndY16BeBigEndian) {
  EXPECT_EQ(codes(unpack({0x34, 0x12, 0xff, 0xff}, V4L2_PIX_FMT_Y16, 2, 1, 4, {1, 16})),
            (std::vector<std::uint16_t>{0x1234, 0xffff}));
  EXPECT_EQ(codes(unpack({0x12, 0x34, 0x00, 0x01}, V4L2_PIX_FMT_Y16_BE, 2, 1, 4, {1, 16})),
            (std::vector<std::uint16_t>{0x1234, 0x0001}));
}

TEST(V4l2Unpack, Y12AndY10KeepOnlyTheirLowBits) {
  EXPECT_EQ(codes(unpack({0xbc, 0xfa}, V4L2_PIX_FMT_Y12, 1, 1, 2, {1, 12})),
            (std::vector<std::uint16_t>{0x0abc}));
  EXPECT_EQ(codes(unpack({0xff, 0xff}, V4L2_PIX_FMT_Y10, 1, 1, 2, {1, 10})),
            (std::vector<std::uint16_t>{0x03ff}));
}

// pixfmt-yuv-luma.rst: Y10P is 4 high bytes then the 4 pairs of low bits, pixel 0 lowest.
TEST(V4l2Unpack, Y10pLowBitsComeFifthWithPixelZeroLowest) {
  EXPECT_EQ(codes(unpack({0xff, 0x00, 0x55, 0xaa, 0x93}, V4L2_PIX_FMT_Y10P, 4, 1, 5, {1, 10})),
            (std::vector<std::uint16_t>{0x3ff, 0x000, 0x155, 0x2aa}));
}

TEST(V4l2Unpack, Y12pLowNibblesComeThirdWithPixelZeroLowest) {
  EXPECT_EQ(codes(unpack({0xab, 0x12, 0x3c}, kV4l2PixFmtY12P, 2, 1, 3, {1, 12})),
            (std::vector<std::uint16_t>{0xabc, 0x123}));
}

// Y10BPACK: one big-endian bit stream, 10 bits per pixel.
TEST(V4l2Unpack, Y10bpackIsABigEndianBitStream) {
  EXPECT_EQ(codes(unpack({0xff, 0xc0, 0x05, 0x56, 0xaa}, V4L2_PIX_FMT_Y10BPACK, 4, 1, 5, {1, 10})),
            (std::vector<std::uint16_t>{0x3ff, 0x000, 0x155, 0x2aa}));
}

// BT.601 limited range: Y 16 black, 235 white; (81, 90, 240) is pure red.
TEST(V4l2Unpack, YuyvBecomesBt601LimitedRangeRgb) {
  const vem::RawFrame f =
      unpack({16, 128, 235, 128, 81, 90, 81, 240}, V4L2_PIX_FMT_YUYV, 4, 1, 8, {3, 8});
  EXPECT_EQ(f.codes, (std::vector<std::uint16_t>{0, 0, 0, 255, 255, 255, 255, 0, 0, 255, 0, 0}));
}

TEST(V4l2Unpack, YuyvAsMono8TakesLumaOnly) {
  const vem::RawFrame f = unpack({16, 128, 235, 128}, V4L2_PIX_FMT_YUYV, 2, 1, 4, {1, 8});
  EXPECT_EQ(f.codes, (std::vector<std::uint16_t>{16, 235}));
}

TEST(V4l2Unpack, Rgb24AndGreyAreCopied) {
  EXPECT_EQ(codes(unpack({1, 2, 3, 4, 5, 6}, V4L2_PIX_FMT_RGB24, 2, 1, 6, {3, 8})),
            (std::vector<std::uint16_t>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(codes(unpack({9, 200}, V4L2_PIX_FMT_GREY, 2, 1, 2, {1, 8})),
            (std::vector<std::uint16_t>{9, 200}));
}

// Row padding: the second row starts at bytesperline, not right after the first row's pixels.
TEST(V4l2Unpack, PaddedRowsAreSkippedByBytesPerLine) {
  const Bytes bytes = {0x01, 0x00, 0x02, 0x00, 0xee, 0xee, 0x03, 0x00, 0x04, 0x00};
  EXPECT_EQ(codes(unpack(bytes, V4L2_PIX_FMT_Y16, 2, 2, 6, {1, 16})),
            (std::vector<std::uint16_t>{1, 2, 3, 4}));
}

struct RoundTrip {
  std::uint32_t fourcc;
  vem::PixelFormat output;
  int widthPx;
};

class V4l2UnpackRoundTrip : public ::testing::TestWithParam<RoundTrip> {};

TEST_P(V4l2UnpackRoundTrip, WriterAndReaderAgreeOnEveryPixelAtPaddedStride) {
  const RoundTrip p = GetParam();
  const int h = 5;
  v4l2_pix_format format{};
  format.pixelformat = p.fourcc;
  format.width = std::uint32_t(p.widthPx);
  format.height = std::uint32_t(h);
  format.bytesperline = std::uint32_t(packedRowBytes(p.fourcc, p.widthPx) + 13);
  std::mt19937 random(p.fourcc);
  std::vector<std::uint16_t> in(std::size_t(p.widthPx * h * p.output.channels));
  for (auto& c : in) c = std::uint16_t(random() & p.output.maxCode());
  const Bytes bytes = testing::encodeFakeFrame(in, format);
  const vem::RawFrame out = unpack(bytes, p.fourcc, p.widthPx, h, format.bytesperline, p.output);
  EXPECT_EQ(out.format, p.output);
  EXPECT_EQ(out.width, p.widthPx);
  EXPECT_EQ(out.height, h);
  EXPECT_EQ(out.codes, in);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, V4l2UnpackRoundTrip,
    ::testing::Values(
        RoundTrip{V4L2_PIX_FMT_Y16, {1, 16}, 7}, RoundTrip{V4L2_PIX_FMT_Y16_BE, {1, 16}, 7},
        RoundTrip{V4L2_PIX_FMT_Y12, {1, 12}, 7}, RoundTrip{kV4l2PixFmtY12P, {1, 12}, 8},
        RoundTrip{kV4l2PixFmtY12P, {1, 12}, 7},  // a last group of one pixel
        RoundTrip{V4L2_PIX_FMT_Y10, {1, 10}, 7}, RoundTrip{V4L2_PIX_FMT_Y10P, {1, 10}, 12},
        RoundTrip{V4L2_PIX_FMT_Y10P, {1, 10}, 10},  // a last group of two
        RoundTrip{V4L2_PIX_FMT_Y10BPACK, {1, 10}, 12}, RoundTrip{V4L2_PIX_FMT_Y10BPACK, {1, 10}, 9},
        RoundTrip{V4L2_PIX_FMT_GREY, {1, 8}, 7}, RoundTrip{V4L2_PIX_FMT_RGB24, {3, 8}, 7}),
    [](const auto& param) {
      std::string name =
          fourccName(param.param.fourcc) + "_w" + std::to_string(param.param.widthPx);
      for (char& c : name) {
        if (c == '-') c = '_';
      }
      return name;
    });

TEST(V4l2Formats, DeepestOfferedFormatIsChosenWhenNoneIsAsked) {
  EXPECT_EQ(chooseNativeFormat({V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_Y12, V4L2_PIX_FMT_GREY}, ""),
            std::optional<std::uint32_t>(V4L2_PIX_FMT_Y12));
  EXPECT_EQ(chooseNativeFormat({V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_GREY}, "Mono8"),
            std::optional<std::uint32_t>(V4L2_PIX_FMT_GREY));
  EXPECT_EQ(chooseNativeFormat({V4L2_PIX_FMT_YUYV}, "Mono8"),
            std::optional<std::uint32_t>(V4L2_PIX_FMT_YUYV));
  EXPECT_EQ(chooseNativeFormat({V4L2_PIX_FMT_YUYV}, "Mono16"), std::nullopt);
  EXPECT_EQ(fourccName(V4L2_PIX_FMT_Y16_BE), "Y16-BE");
}

}  // namespace
}  // namespace vem::cameras
