#include "vemd/sinks/preview_image.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace vem::vemd {
namespace {

constexpr double kReinhardKey = 0.18;
constexpr double kLogAverageDelta = 1e-6;
constexpr int kSubpixelBits = 4;  // cv::circle's fixed-point shift: 1/16 pixel
constexpr double kSubpixel = 1 << kSubpixelBits;

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

double cleanChannel(float value) {
  return std::isfinite(value) && value > 0.0F ? double(value) : 0.0;
}

glm::dvec3 cleanRgb(glm::vec3 rgb) {
  return {cleanChannel(rgb.r), cleanChannel(rgb.g), cleanChannel(rgb.b)};
}

double srgbEncode(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::uint8_t toByte(double unit) { return std::uint8_t(std::lround(255.0 * unit)); }

double logAverageLuminance(const EnvMap& map) {
  double sum = 0.0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      sum += std::log(kLogAverageDelta + luminance(cleanRgb(map.at(x, y))));
    }
  }
  return std::exp(sum / double(map.pixelCount()));
}

// A circle centred at `at` (OpenCV's pixel coordinates), repeated one map width left and right so
// it wraps at the seam.
void drawWrapped(cv::Mat& image, glm::dvec2 at, double radiusPx, const cv::Vec3b& bgr,
                 int thickness) {
  const cv::Scalar colour(bgr[0], bgr[1], bgr[2]);
  const int radius = int(std::lround(radiusPx * kSubpixel));
  for (const int shift : {-1, 0, 1}) {
    const cv::Point centre(int(std::lround((at.x + shift * image.cols) * kSubpixel)),
                           int(std::lround(at.y * kSubpixel)));
    cv::circle(image, centre, radius, colour, thickness, cv::LINE_AA, kSubpixelBits);
  }
}

}  // namespace

glm::dvec2 mapCoordsOfDirection(MapLayout layout, int width, int height, glm::dvec3 dir) {
  const double theta = std::atan2(std::hypot(dir.x, dir.z), dir.y);
  double psi = std::atan2(dir.z, dir.x);  // phi in (-pi, pi]
  if (layout == MapLayout::Sphere) psi += std::numbers::pi;
  if (psi < 0.0) psi += 2.0 * std::numbers::pi;
  double xc = psi / (2.0 * std::numbers::pi) * width;
  if (xc >= width) xc -= width;
  return {xc, theta / thetaMaxRad(layout) * height};
}

cv::Mat toneMappedMap(const EnvMap& map, int scale) {
  cv::Mat small(map.height, map.width, CV_8UC3);
  const double exposure = kReinhardKey / logAverageLuminance(map);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 rgb = cleanRgb(map.at(x, y));
      const double lw = luminance(rgb);
      const double l = exposure * lw;
      const double gain = lw > 0.0 ? (l / (1.0 + l)) / lw : 0.0;
      small.at<cv::Vec3b>(y, x) =
          cv::Vec3b(toByte(srgbEncode(gain * rgb.b)), toByte(srgbEncode(gain * rgb.g)),
                    toByte(srgbEncode(gain * rgb.r)));
    }
  }
  if (scale <= 1) return small;
  cv::Mat large;
  cv::resize(small, large, cv::Size(map.width * scale, map.height * scale), 0.0, 0.0,
             cv::INTER_NEAREST);
  return large;
}

cv::Mat previewImage(const EnvMap& map, const LightSet& lights, const Clustering* clustering,
                     const PreviewStyle& style) {
  const int scale = std::max(1, style.scale);
  cv::Mat image = toneMappedMap(map, scale);
  // OpenCV draws pixel (i, j) centred on the integer point (i, j): continuous coordinates - 0.5.
  const auto imageCoords = [&](glm::vec3 dir) {
    return double(scale) *
               mapCoordsOfDirection(map.layout, map.width, map.height, glm::dvec3(dir)) -
           glm::dvec2(0.5);
  };
  if (clustering != nullptr) {
    const double radiusPx = std::max(
        double(scale), clustering->radiusRad / thetaMaxRad(map.layout) * map.height * scale);
    const int thickness = std::max(1, scale / 2);
    for (const Light& cluster : clustering->clusters.lights) {
      drawWrapped(image, imageCoords(cluster.dir), radiusPx, kPreviewClusterBgr, thickness);
    }
  }
  double brightest = 0.0;
  for (const Light& light : lights.lights) {
    brightest = std::max(brightest, luminance(cleanRgb(light.rgb)));
  }
  for (const Light& light : lights.lights) {
    const double share = brightest > 0.0 ? luminance(cleanRgb(light.rgb)) / brightest : 0.0;
    const double radiusPx = scale * (1.5 + 3.5 * std::sqrt(share));
    drawWrapped(image, imageCoords(light.dir), radiusPx, kPreviewLightBgr, cv::FILLED);
  }
  return image;
}

}  // namespace vem::vemd
