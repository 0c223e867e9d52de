#include "client/render/tone_mapping.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/color.h"

namespace vem::render {
namespace {

constexpr double kLowPercentile = 0.01;
constexpr double kHighPercentile = 0.99;

bool usable(float value) { return std::isfinite(value) && value >= 0.0F; }

std::vector<float> pixelLuminances(const LinearImage& image) {
  const bool anyCovered = std::ranges::any_of(image.covered, [](std::uint8_t c) { return c != 0; });
  std::vector<float> values;
  values.reserve(image.pixelCount());
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    if (anyCovered && image.covered[p] == 0) {
      continue;
    }
    const glm::vec3 rgb(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]);
    const auto y = float(luminance(rgb));
    values.push_back(usable(y) ? y : 0.0F);
  }
  return values;
}

double percentile(std::vector<float>& values, double fraction) {
  const auto k = std::size_t(fraction * double(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return double(values[k]);
}

}  // namespace

FrameLuminance measureLuminance(const LinearImage& image) {
  std::vector<float> values = pixelLuminances(image);
  if (values.empty()) {
    return FrameLuminance{kLogDelta, kLogDelta, kLogDelta};
  }
  double sumLog = 0.0;
  for (float y : values) {
    sumLog += std::log(kLogDelta + double(y));
  }
  FrameLuminance frame;
  frame.logAverage = std::exp(sumLog / double(values.size()));
  frame.low = std::max(percentile(values, kLowPercentile), kLogDelta);
  frame.high = std::max(percentile(values, kHighPercentile), frame.low);
  return frame;
}

double automaticKey(const FrameLuminance& frame) {
  const double logMin = std::log2(frame.low + kLogDelta);
  const double logMax = std::log2(frame.high + kLogDelta);
  const double logAvg = std::log2(frame.logAverage);
  if (logMax - logMin < 1e-6) {
    return 0.18;
  }
  const double key = 0.18 * std::pow(4.0, (2.0 * logAvg - logMin - logMax) / (logMax - logMin));
  return std::clamp(key, kMinKey, kMaxKey);
}

ToneParams ToneSmoother::update(const FrameLuminance& frame, double dtSec) {
  const double logWorld = std::log(frame.logAverage);
  const double key = automaticKey(frame);
  const double logWhite = std::log(std::max(frame.high, frame.logAverage));
  if (!current_) {
    logWorld_ = logWorld;
    key_ = key;
    logWhite_ = logWhite;
  } else {
    const double w = tauSec_ > 0.0 ? 1.0 - std::exp(-std::max(dtSec, 0.0) / tauSec_) : 1.0;
    logWorld_ += w * (logWorld - logWorld_);
    key_ += w * (key - key_);
    logWhite_ += w * (logWhite - logWhite_);
  }
  ToneParams params;
  params.worldLuminance = std::exp(logWorld_);
  params.key = key_;
  params.whiteLuminance = std::max(1.0, key_ / params.worldLuminance * std::exp(logWhite_));
  current_ = params;
  return params;
}

glm::vec3 toneMap(glm::vec3 rgb, const ToneParams& params) {
  const auto y = float(luminance(rgb));
  if (!usable(y) || y <= 0.0F || !usable(rgb.x) || !usable(rgb.y) || !usable(rgb.z)) {
    return glm::vec3(0.0F);
  }
  const auto scale = float(params.key / params.worldLuminance);
  const auto white2 = float(params.whiteLuminance * params.whiteLuminance);
  const float ls = scale * y;
  const float ld = ls * (1.0F + ls / white2) / (1.0F + ls);
  return glm::clamp(rgb * (ld / y), glm::vec3(0.0F), glm::vec3(1.0F));
}

float srgbEncode(float linear01) {
  const float c = std::clamp(linear01, 0.0F, 1.0F);
  return c <= 0.0031308F ? 12.92F * c : 1.055F * std::pow(c, 1.0F / 2.4F) - 0.055F;
}

float srgbDecode(float encoded01) {
  const float c = std::clamp(encoded01, 0.0F, 1.0F);
  return c <= 0.04045F ? c / 12.92F : std::pow((c + 0.055F) / 1.055F, 2.4F);
}

std::vector<std::uint8_t> displaySrgb8(const LinearImage& image) {
  std::vector<std::uint8_t> out(image.pixelCount() * 3);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = std::uint8_t(std::lround(255.0F * srgbEncode(image.rgb[i])));
  }
  return out;
}

std::vector<std::uint8_t> toneMappedSrgb8(const LinearImage& image, const ToneParams& params) {
  std::vector<std::uint8_t> out(image.pixelCount() * 3);
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const glm::vec3 rgb(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]);
    const glm::vec3 display = toneMap(rgb, params);
    for (int c = 0; c < 3; ++c) {
      out[3 * p + std::size_t(c)] = std::uint8_t(std::lround(255.0F * srgbEncode(display[c])));
    }
  }
  return out;
}

}  // namespace vem::render
