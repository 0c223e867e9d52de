#include "client/render/image_files.h"

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "mapio/map_file.h"
#include "util/atomic_file.h"

namespace vem::render {

std::expected<void, std::string> saveLinearExr(const LinearImage& image,
                                               const std::filesystem::path& path) {
  EnvMap map;
  map.layout = MapLayout::Sphere;  // only a container here: the EXR holds the picture as is
  map.width = image.widthPx;
  map.height = image.heightPx;
  map.rgb = image.rgb;
  if (auto saved = mapio::saveMap(map, path); !saved) {
    return std::unexpected(saved.error().message);
  }
  return {};
}

std::expected<void, std::string> saveSrgbPng(std::span<const std::uint8_t> srgb8, int widthPx,
                                             int heightPx, const std::filesystem::path& path) {
  if (srgb8.size() != std::size_t(widthPx) * std::size_t(heightPx) * 3) {
    return std::unexpected(fmt::format("{}: cannot save {} bytes as a {} x {} RGB picture",
                                       path.string(), srgb8.size(), widthPx, heightPx));
  }
  // OpenCV wants BGR; a copy (cv::Mat over const data would need a cast).
  cv::Mat rgb(heightPx, widthPx, CV_8UC3);
  std::copy(srgb8.begin(), srgb8.end(), rgb.data);
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<unsigned char> bytes;
  try {
    if (!cv::imencode(".png", bgr, bytes)) {
      return std::unexpected(fmt::format("{}: OpenCV could not encode the PNG", path.string()));
    }
  } catch (const cv::Exception& e) {
    return std::unexpected(fmt::format("{}: cannot encode the PNG ({})", path.string(), e.what()));
  }
  if (auto done = util::replaceFileAtomically(path, std::as_bytes(std::span(bytes))); !done) {
    return std::unexpected(
        fmt::format("{}: cannot write the PNG ({}), so any earlier file there "
                    "is unchanged",
                    path.string(), done.error().reason()));
  }
  return {};
}

std::expected<Srgb8Image, std::string> loadSrgb8(const std::filesystem::path& path) {
  cv::Mat bgr;
  try {
    bgr = cv::imread(path.string(), cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    return std::unexpected(
        fmt::format("{}: cannot read the picture ({})", path.string(), e.what()));
  }
  if (bgr.empty()) {
    return std::unexpected(fmt::format("{}: not a readable picture", path.string()));
  }
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  Srgb8Image image{rgb.cols, rgb.rows, {}};
  image.rgb.assign(rgb.data, rgb.data + rgb.total() * 3);
  return image;
}

std::expected<LinearImage, std::string> loadLinearExr(const std::filesystem::path& path) {
  auto map = mapio::loadMap(path, MapLayout::Sphere);
  if (!map) {
    return std::unexpected(map.error().message);
  }
  LinearImage image = LinearImage::black(map->width, map->height);
  image.rgb = std::move(map->rgb);
  image.covered.assign(image.pixelCount(), 1);
  return image;
}

}  // namespace vem::render
