// Raw frame files (calib/io/raw_frame_file.h): codes and channel order survive a save and a load in
// every format, colour is RGB in the file as the formats define it (checked against bytes written
// by hand, so a swap shared by reader and writer still fails), and images that are not raw frames
// are refused in one sentence.
#include "calib/io/raw_frame_file.h"

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vem::calib::io {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("vem_raw_frame_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Every code different, using the whole range of the format.
RawFrame rampFrame(int width, int height, PixelFormat format) {
  RawFrame frame = RawFrame::blank(width, height, format);
  for (std::size_t i = 0; i < frame.codes.size(); ++i)
    frame.codes[i] = std::uint16_t((i * 2654435761u) % (format.maxCode() + 1u));
  frame.codes.back() = std::uint16_t(format.maxCode());
  return frame;
}

TEST(RawFrameFile, EveryFormatRoundTripsEveryCodeInEveryContainer) {
  const TempDir dir;
  for (const char* name :
       {"Mono8", "Mono10", "Mono12", "Mono16", "RGB8", "RGB10", "RGB12", "RGB16"}) {
    const PixelFormat format = *parsePixelFormat(name);
    for (const std::string ext : {".png", ".tif", format.channels == 1 ? ".pgm" : ".ppm"}) {
      SCOPED_TRACE(std::string(name) + ext);
      const RawFrame frame = rampFrame(7, 5, format);
      const fs::path path = dir / (std::string(name) + ext);
      const auto saved = saveRawFrame(frame, path);
      ASSERT_TRUE(saved) << saved.error().message;
      const auto back = loadRawFrame(path, format.bits);
      ASSERT_TRUE(back.has_value()) << back.error().message;
      EXPECT_EQ(back->width, 7);
      EXPECT_EQ(back->height, 5);
      EXPECT_EQ(back->format, format);
      EXPECT_EQ(back->codes, frame.codes);
    }
  }
}

TEST(RawFrameFile, WithoutBitsTheContainerDepthIsTheFormat) {
  const TempDir dir;
  ASSERT_TRUE(saveRawFrame(rampFrame(4, 3, {3, 12}), dir / "f.png"));
  const auto back = loadRawFrame(dir / "f.png");
  ASSERT_TRUE(back.has_value()) << back.error().message;
  EXPECT_EQ(back->format, (PixelFormat{3, 16}));
}

TEST(RawFrameFile, SavedColourIsRgbInTheFileNotOpenCvsBgr) {
  const TempDir dir;
  RawFrame frame = RawFrame::blank(2, 1, {3, 8});
  frame.codes = {200, 10, 3, 7, 8, 9};  // (R, G, B) of two pixels
  ASSERT_TRUE(saveRawFrame(frame, dir / "red.ppm"));
  const std::string bytes = readFile(dir / "red.ppm");
  ASSERT_GE(bytes.size(), 6U);
  EXPECT_EQ(bytes.substr(0, 2), "P6");
  const std::string pixels = bytes.substr(bytes.size() - 6);  // P6 stores R, G, B per pixel
  EXPECT_EQ(std::vector<unsigned char>(pixels.begin(), pixels.end()),
            (std::vector<unsigned char>{200, 10, 3, 7, 8, 9}));
}

TEST(RawFrameFile, LoadedColourFromAHandWrittenFileIsRgb) {
  const TempDir dir;
  // P6, 1 x 1, 16-bit (big-endian): R = 0x0123, G = 0x0456, B = 0x0789.
  writeFile(dir / "one.ppm",
            std::string("P6\n1 1\n65535\n") + std::string("\x01\x23\x04\x56\x07\x89", 6));
  const auto frame = loadRawFrame(dir / "one.ppm", 12);
  ASSERT_TRUE(frame.has_value()) << frame.error().message;
  EXPECT_EQ(frame->codes, (std::vector<std::uint16_t>{0x123, 0x456, 0x789}));
}

TEST(RawFrameFile, CodeAboveTheBitsIsRefusedNamingThePixel) {
  const TempDir dir;
  RawFrame frame = RawFrame::blank(3, 2, {1, 16});
  frame.codes[4] = 5000;  // pixel (1, 1)
  ASSERT_TRUE(saveRawFrame(frame, dir / "f.png"));
  const auto loaded = loadRawFrame(dir / "f.png", 12);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().cause, CalibFileError::BadValue);
  EXPECT_NE(loaded.error().message.find("f.png: pixel (1, 1) holds code 5000, above 4095"),
            std::string::npos)
      << loaded.error().message;
}

TEST(RawFrameFile, EightBitImageCannotHoldTwelveBitCodes) {
  const TempDir dir;
  ASSERT_TRUE(saveRawFrame(rampFrame(3, 2, {1, 8}), dir / "f.pgm"));
  const auto loaded = loadRawFrame(dir / "f.pgm", 12);
  ASSERT_FALSE(loaded);
  EXPECT_NE(loaded.error().message.find("8-bit image, too small for 12-bit codes"),
            std::string::npos)
      << loaded.error().message;
}

// A minimal PNG (stored, uncompressed zlib data) of one row per scanline, for images our writer
// never makes.
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string bigEndian(std::uint32_t v) {
  return {char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
}

std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian(std::uint32_t(data.size())) + type + data + bigEndian(crc32(type + data));
}

std::string pngBytes(int width, int height, int colourType, const std::string& scanlines) {
  std::uint32_t a = 1, b = 0;  // Adler-32 of the scanlines
  for (const char c : scanlines) {
    a = (a + static_cast<unsigned char>(c)) % 65521u;
    b = (b + a) % 65521u;
  }
  const auto n = std::uint16_t(scanlines.size());
  const std::string zlib = std::string("\x78\x01\x01", 3) + char(n & 0xff) + char(n >> 8) +
                           char(~n & 0xff) + char((~n >> 8) & 0xff) + scanlines +
                           bigEndian((b << 16) | a);
  const std::string header = bigEndian(std::uint32_t(width)) + bigEndian(std::uint32_t(height)) +
                             std::string{char(8), char(colourType), 0, 0, 0};
  return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) +
         pngChunk("IEND", "");
}

TEST(RawFrameFile, FourAndTwoChannelImagesAreRefused) {
  const TempDir dir;
  writeFile(dir / "rgba.png", pngBytes(1, 1, 6, std::string("\0\x10\x20\x30\x40", 5)));
  writeFile(dir / "grey-alpha.png", pngBytes(1, 1, 4, std::string("\0\x10\x20", 3)));
  // OpenCV expands grey with alpha to 4 channels.
  for (const auto& [name, channels] :
       {std::pair{"rgba.png", "4"}, std::pair{"grey-alpha.png", "4"}}) {
    const auto loaded = loadRawFrame(dir / name);
    ASSERT_FALSE(loaded) << name;
    EXPECT_EQ(loaded.error().cause, CalibFileError::BadValue);
    EXPECT_NE(loaded.error().message.find(std::string(name) + ": decodes to " + channels +
                                          " channels (expected 1, grey, or 3, colour"),
              std::string::npos)
        << loaded.error().message;
  }
}

// A little-endian TIFF of one 32-bit float grey pixel.
std::string floatTiff(float value) {
  std::string t("II*\0\x08\0\0\0", 8);
  const auto u16 = [](unsigned v) { return std::string{char(v & 0xff), char(v >> 8)}; };
  const auto u32 = [&](unsigned v) { return u16(v & 0xffff) + u16(v >> 16); };
  const std::array<std::array<unsigned, 3>, 9> tags{{{256, 3, 1},
                                                     {257, 3, 1},
                                                     {258, 3, 32},
                                                     {259, 3, 1},
                                                     {262, 3, 1},
                                                     {273, 4, 8 + 2 + 9 * 12 + 4},
                                                     {277, 3, 1},
                                                     {279, 4, 4},
                                                     {339, 3, 3}}};
  t += u16(unsigned(tags.size()));
  for (const auto& [tag, type, v] : tags) t += u16(tag) + u16(type) + u32(1) + u32(v);
  t += u32(0);
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  return t + std::string(bytes, 4);
}

TEST(RawFrameFile, FloatImagesAreRefused) {
  const TempDir dir;
  writeFile(dir / "float.tif", floatTiff(0.5f));
  const auto loaded = loadRawFrame(dir / "float.tif");
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().cause, CalibFileError::BadValue);
  EXPECT_NE(loaded.error().message.find("float.tif: holds CV_32FC1 pixels (expected 8- or 16-bit"),
            std::string::npos)
      << loaded.error().message;
}

TEST(RawFrameFile, UnknownExtensionMissingEmptyAndCorruptFilesAreRefusedByCause) {
  const TempDir dir;
  writeFile(dir / "empty.png", "");
  const std::string png = pngBytes(2, 2, 0, std::string("\0\1\2\0\3\4", 6));
  writeFile(dir / "cut.png", png.substr(0, 40));
  writeFile(dir / "bad-crc.png", png.substr(0, 45) + "\xff" + png.substr(46));  // in IDAT
  writeFile(dir / "text.png", "hello");
  const std::vector<std::tuple<std::string, CalibFileError, std::string>> cases{
      {"frame.jpg", CalibFileError::Unreadable, "the extension '.jpg' is not a raw frame format"},
      {"absent.png", CalibFileError::NotFound, "no such file"},
      {"empty.png", CalibFileError::BadSyntax, "the file is empty"},
      {"cut.png", CalibFileError::BadSyntax, "the image is truncated"},
      {"bad-crc.png", CalibFileError::BadSyntax, "the image is truncated or corrupted"},
      {"text.png", CalibFileError::BadSyntax, "not a PNG file"}};
  for (const auto& [name, cause, expected] : cases) {
    const auto loaded = loadRawFrame(dir / name);
    ASSERT_FALSE(loaded) << name;
    EXPECT_EQ(loaded.error().cause, cause) << loaded.error().message;
    EXPECT_NE(loaded.error().message.find(name + ": " + expected), std::string::npos)
        << loaded.error().message;
  }
}

TEST(RawFrameFile, RefusedSaveLeavesTheOldFileByteIdentical) {
  const TempDir dir;
  ASSERT_TRUE(saveRawFrame(rampFrame(4, 4, {1, 12}), dir / "f.pgm"));
  const std::string before = readFile(dir / "f.pgm");
  RawFrame tooHigh = rampFrame(4, 4, {1, 12});
  tooHigh.codes[3] = 4096;
  for (const RawFrame& bad : {tooHigh, rampFrame(4, 4, {3, 12}), RawFrame::blank(0, 0, {1, 12})}) {
    const auto saved = saveRawFrame(bad, dir / "f.pgm");
    ASSERT_FALSE(saved);
    EXPECT_NE(saved.error().message.find("f.pgm: "), std::string::npos) << saved.error().message;
    EXPECT_EQ(readFile(dir / "f.pgm"), before);
  }
}

}  // namespace
}  // namespace vem::calib::io
