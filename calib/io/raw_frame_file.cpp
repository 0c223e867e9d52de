#include "calib/io/raw_frame_file.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "calib/io/file_access.h"
#include "util/quiet_std_err.h"

namespace vem::calib::io {
namespace {

using detail::fileFailure;

enum class ImageType { Png, Tiff, Pgm, Ppm };

std::expected<ImageType, CalibFileFailure> imageTypeOf(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::ranges::transform(ext, ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".png") return ImageType::Png;
  if (ext == ".tif" || ext == ".tiff") return ImageType::Tiff;
  if (ext == ".pgm") return ImageType::Pgm;
  if (ext == ".ppm") return ImageType::Ppm;
  const std::string given = path.extension().string();
  return std::unexpected(
      fileFailure(CalibFileError::Unreadable, path,
                  (given.empty() ? std::string("the name has no extension")
                                 : "the extension '" + given + "' is not a raw frame format") +
                      " (expected .png, .tif, .tiff, .pgm or .ppm)"));
}

// The pixel format of a decoded image, or why it is not a raw frame.
std::expected<PixelFormat, CalibFileFailure> formatOf(const std::filesystem::path& path,
                                                      const cv::Mat& image,
                                                      std::optional<int> bits) {
  const auto fail = [&](const std::string& what) {
    return std::unexpected(fileFailure(CalibFileError::BadValue, path, what));
  };
  if (image.depth() != CV_8U && image.depth() != CV_16U)
    return fail("holds " + cv::typeToString(image.type()) +
                " pixels (expected 8- or 16-bit unsigned integer codes)");
  if (image.channels() != 1 && image.channels() != 3)
    return fail("decodes to " + std::to_string(image.channels()) +
                " channels (expected 1, grey, or 3, colour, without alpha)");
  const int depth = image.depth() == CV_8U ? 8 : 16;
  const PixelFormat format{image.channels(), bits.value_or(depth)};
  if (!parsePixelFormat(pixelFormatName(format)))
    return fail("cannot hold " + std::to_string(format.bits) +
                "-bit codes (expected 8, 10, 12 or 16 bits)");
  if (format.bits > depth)
    return fail("is an 8-bit image, too small for " + std::to_string(format.bits) +
                "-bit codes (expected a 16-bit image)");
  return format;
}

// Copies the image's codes (RGB order) into `frame`, refusing codes above the format's largest.
std::expected<void, CalibFileFailure> copyCodes(const std::filesystem::path& path,
                                                const cv::Mat& image, RawFrame& frame) {
  cv::Mat wide;
  image.convertTo(wide, CV_16U);
  const int channels = frame.format.channels;
  for (int v = 0; v < frame.height; ++v) {
    const std::uint16_t* row = wide.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      for (int c = 0; c < channels; ++c) {
        const std::uint16_t code = row[u * channels + (channels == 3 ? 2 - c : c)];
        if (code > frame.format.maxCode())
          return std::unexpected(fileFailure(
              CalibFileError::BadValue, path,
              "pixel (" + std::to_string(u) + ", " + std::to_string(v) + ") holds code " +
                  std::to_string(code) + ", above " + std::to_string(frame.format.maxCode()) +
                  " (expected " + std::to_string(frame.format.bits) + "-bit codes)"));
        frame.codes[frame.index(u, v, c)] = code;
      }
    }
  }
  return {};
}

// libpng reports a truncated file on stderr itself, past QuietStdErr (C stdio): the usual damage,
// a cut-off copy, is caught here first. A PNG ends with the IEND chunk, whose CRC is fixed.
std::optional<std::string> pngDefect(const std::string& bytes) {
  if (!bytes.starts_with("\x89PNG\r\n\x1a\n")) return "not a PNG file (expected the PNG signature)";
  if (bytes.rfind("IEND\xae\x42\x60\x82") == std::string::npos)
    return "the image is truncated (the PNG data does not end with its IEND chunk)";
  return std::nullopt;
}

std::expected<cv::Mat, CalibFileFailure> decode(const std::filesystem::path& path, ImageType type,
                                                const std::string& bytes) {
  const auto fail = [&](const std::string& what) {
    return std::unexpected(fileFailure(CalibFileError::BadSyntax, path, what));
  };
  if (bytes.empty()) return fail("the file is empty");
  if (type == ImageType::Png)
    if (const std::optional<std::string> defect = pngDefect(bytes)) return fail(*defect);
  try {
    const util::QuietStdErr quiet;
    const cv::Mat encoded(1, int(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
    cv::Mat image = cv::imdecode(encoded, cv::IMREAD_UNCHANGED);
    if (image.empty())
      return fail("the image is truncated or corrupted (OpenCV could not decode it)");
    return image;
  } catch (const std::exception& e) {
    return fail(std::string("the image could not be decoded (OpenCV: ") + e.what() + ")");
  }
}

std::optional<std::string> frameDefect(const RawFrame& frame) {
  const std::size_t expected = std::size_t(std::max(frame.width, 0)) *
                               std::size_t(std::max(frame.height, 0)) *
                               std::size_t(std::max(frame.format.channels, 0));
  if (frame.width < 1 || frame.height < 1 || frame.codes.size() != expected)
    return "cannot save a " + std::to_string(frame.width) + " x " + std::to_string(frame.height) +
           " frame holding " + std::to_string(frame.codes.size()) +
           " codes (expected at least 1 x 1 and one code per pixel and channel)";
  if (!parsePixelFormat(pixelFormatName(frame.format)))
    return "cannot save a frame of " + std::to_string(frame.format.channels) + " channels of " +
           std::to_string(frame.format.bits) +
           " bits (expected Mono or RGB of 8, 10, 12 or 16 bits)";
  const auto above = std::ranges::find_if(
      frame.codes, [&](std::uint16_t code) { return code > frame.format.maxCode(); });
  if (above != frame.codes.end())
    return "cannot save code " + std::to_string(*above) + " in a " + pixelFormatName(frame.format) +
           " frame (expected at most " + std::to_string(frame.format.maxCode()) + ")";
  return std::nullopt;
}

// The frame as an OpenCV image: BGR for colour, 8-bit for 8-bit formats, else 16-bit.
cv::Mat imageOf(const RawFrame& frame) {
  const int channels = frame.format.channels;
  cv::Mat wide(frame.height, frame.width, CV_MAKETYPE(CV_16U, channels));
  for (int v = 0; v < frame.height; ++v) {
    std::uint16_t* row = wide.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u)
      for (int c = 0; c < channels; ++c)
        row[u * channels + (channels == 3 ? 2 - c : c)] = frame.at(u, v, c);
  }
  if (frame.format.bits > 8) return wide;
  cv::Mat narrow;
  wide.convertTo(narrow, CV_MAKETYPE(CV_8U, channels));
  return narrow;
}

// Encodes and decodes back: OpenCV's TIFF encoder goes through a temporary file of its own and
// could hand back a short buffer; the bytes are written only if they hold the frame exactly.
std::expected<std::vector<unsigned char>, std::string> encode(const cv::Mat& image,
                                                              ImageType type) {
  const char* extension = type == ImageType::Png    ? ".png"
                          : type == ImageType::Tiff ? ".tiff"
                          : type == ImageType::Pgm  ? ".pgm"
                                                    : ".ppm";
  try {
    std::vector<unsigned char> bytes;
    if (!cv::imencode(extension, image, bytes))
      return std::unexpected("OpenCV could not encode it");
    const util::QuietStdErr quiet;
    const cv::Mat back = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
    if (back.size() != image.size() || back.type() != image.type() ||
        cv::norm(back, image, cv::NORM_INF) != 0.0)
      return std::unexpected("OpenCV's encoding did not read back as the same frame");
    return bytes;
  } catch (const std::exception& e) {
    return std::unexpected(std::string("OpenCV: ") + e.what());
  }
}

}  // namespace

std::expected<RawFrame, CalibFileFailure> loadRawFrame(const std::filesystem::path& path,
                                                       std::optional<int> bits) {
  const auto type = imageTypeOf(path);
  if (!type) return std::unexpected(type.error());
  const auto bytes = detail::readWholeFile(path, "raw frame");
  if (!bytes) return std::unexpected(bytes.error());
  const auto image = decode(path, *type, *bytes);
  if (!image) return std::unexpected(image.error());
  const auto format = formatOf(path, *image, bits);
  if (!format) return std::unexpected(format.error());
  RawFrame frame = RawFrame::blank(image->cols, image->rows, *format);
  if (auto copied = copyCodes(path, *image, frame); !copied) return std::unexpected(copied.error());
  return frame;
}

std::expected<void, CalibFileFailure> saveRawFrame(const RawFrame& frame,
                                                   const std::filesystem::path& path) {
  const auto type = imageTypeOf(path);
  if (!type)
    return std::unexpected(CalibFileFailure{CalibFileError::WriteFailed, type.error().message});
  if (const std::optional<std::string> defect = frameDefect(frame))
    return std::unexpected(fileFailure(CalibFileError::BadValue, path, *defect));
  const bool colour = frame.format.channels == 3;
  if ((*type == ImageType::Pgm && colour) || (*type == ImageType::Ppm && !colour))
    return std::unexpected(fileFailure(CalibFileError::WriteFailed, path,
                                       "a " + pixelFormatName(frame.format) +
                                           " frame cannot be stored in a " +
                                           path.extension().string() + " file (expected " +
                                           (colour ? ".ppm" : ".pgm") + ", .png or .tif)"));
  const auto bytes = encode(imageOf(frame), *type);
  if (!bytes)
    return std::unexpected(fileFailure(
        CalibFileError::WriteFailed, path,
        "cannot encode the frame (" + bytes.error() + "), so any earlier file there is unchanged"));
  return detail::writeWholeFile(path, *bytes, "raw frame");
}

}  // namespace vem::calib::io
