#include "mapio/opencv_codec.h"

#include <iostream>

#include <cctype>
#include <cstdint>
#include <exception>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <sstream>
#include <utility>

#include "util/quiet_std_err.h"

namespace vem::mapio::detail {
namespace {

const char* formatName(MapFormat format) {
  return format == MapFormat::Pfm ? "PFM" : "Radiance HDR";
}

// The same signatures OpenCV's decoders look for.
bool hasSignature(MapFormat format, std::string_view start) {
  if (format == MapFormat::RadianceHdr)
    return start.starts_with("#?RADIANCE") || start.starts_with("#?RGBE");
  return start.size() >= 3 && (start.starts_with("PF") || start.starts_with("Pf")) &&
         std::isspace(static_cast<unsigned char>(start[2])) != 0;
}

// Width and height from the header, when its first bytes hold them.
std::optional<std::pair<std::int64_t, std::int64_t>> peekSize(MapFormat format,
                                                              std::string_view start) {
  std::string axisA, axisB;
  std::int64_t a = 0, b = 0;
  if (format == MapFormat::Pfm) {
    std::istringstream header{std::string(start)};
    if (header >> axisA >> a >> b) return std::pair{a, b};
    return std::nullopt;
  }
  // A blank line ends the RGBE header; the resolution line ("-Y H +X W") follows it.
  const std::size_t blank = start.find("\n\n");
  if (blank == std::string_view::npos) return std::nullopt;
  std::istringstream resolution{std::string(start.substr(blank + 2, 64))};
  if (!(resolution >> axisA >> a >> axisB >> b) || axisA.size() != 2) return std::nullopt;
  return axisA[1] == 'Y' ? std::pair{b, a} : std::pair{a, b};
}

RgbImage rgbFromBgr(const cv::Mat& mat) {
  RgbImage image{mat.cols, mat.rows, std::vector<float>(mat.total() * 3)};
  const bool grey = mat.channels() == 1;
  for (int y = 0; y < mat.rows; ++y) {
    const float* from = mat.ptr<float>(y);
    float* to = image.rgb.data() + 3 * std::size_t(y) * std::size_t(mat.cols);
    for (std::size_t x = 0; x < std::size_t(mat.cols); ++x) {
      to[3 * x + 0] = grey ? from[x] : from[3 * x + 2];
      to[3 * x + 1] = grey ? from[x] : from[3 * x + 1];
      to[3 * x + 2] = grey ? from[x] : from[3 * x + 0];
    }
  }
  return image;
}

}  // namespace

std::expected<RgbImage, MapFileFailure> readWithOpenCv(const std::filesystem::path& path,
                                                       MapFormat format,
                                                       std::string_view fileStart) {
  const std::string name = formatName(format);
  const auto fail = [&](std::string_view what) {
    return std::unexpected(fileFailure(MapFileError::BadContents, path, what));
  };
  if (!hasSignature(format, fileStart))
    return fail(format == MapFormat::Pfm
                    ? "not a PFM file (expected the 'PF' or 'Pf' signature)"
                    : "not a Radiance HDR file (expected the '#?RADIANCE' or '#?RGBE' signature)");
  if (const auto size = peekSize(format, fileStart))
    if (auto ok = checkMapSize(path, "the map", size->first, size->second); !ok)
      return std::unexpected(ok.error());
  cv::Mat mat;
  try {
    const util::QuietStdErr quiet;
    mat = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  } catch (const std::exception& e) {
    return fail("the " + name + " data could not be decoded (OpenCV: " + e.what() + ")");
  } catch (...) {
    return fail("the " + name + " data could not be decoded");
  }
  if (mat.empty())
    return fail("the " + name + " data is truncated or corrupted (OpenCV could not decode it)");
  if (mat.depth() != CV_32F || (mat.channels() != 3 && mat.channels() != 1))
    return fail("the " + name + " data decoded to " + cv::typeToString(mat.type()) +
                " (expected 32-bit float RGB or grey)");
  return rgbFromBgr(mat);
}

std::expected<std::vector<unsigned char>, std::string> encodeWithOpenCv(const EnvMap& map,
                                                                        MapFormat format) {
  try {
    cv::Mat bgr(map.height, map.width, CV_32FC3);
    for (int y = 0; y < map.height; ++y) {
      float* to = bgr.ptr<float>(y);
      const float* from = map.rgb.data() + 3 * std::size_t(y) * std::size_t(map.width);
      for (std::size_t x = 0; x < std::size_t(map.width); ++x) {
        to[3 * x + 0] = from[3 * x + 2];
        to[3 * x + 1] = from[3 * x + 1];
        to[3 * x + 2] = from[3 * x + 0];
      }
    }
    std::vector<unsigned char> bytes;
    if (!cv::imencode(format == MapFormat::Pfm ? ".pfm" : ".hdr", bgr, bytes))
      return std::unexpected(std::string("OpenCV could not encode it as ") + formatName(format));
    // OpenCV 4.6 encodes both through a temporary file and can hand back a truncated buffer when
    // writing it fails (disk full, file size limit): decode the bytes back to be sure.
    const util::QuietStdErr quiet;
    if (cv::imdecode(bytes, cv::IMREAD_UNCHANGED).size() != bgr.size())
      return std::unexpected(std::string("OpenCV's ") + formatName(format) +
                             " encoding came out truncated");
    return bytes;
  } catch (const std::exception& e) {
    return std::unexpected(std::string("OpenCV: ") + e.what());
  } catch (...) {
    return std::unexpected(std::string("OpenCV failed"));
  }
}

}  // namespace vem::mapio::detail
