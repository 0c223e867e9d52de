#include "calib/core/polar_remap.h"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>

#include "util/contract.h"

namespace vem::calib {
namespace {

void prepareMap(const PolarRemap& remap, EnvMap& map) {
  map.layout = remap.layout;
  map.width = remap.mapWidth;
  map.height = remap.mapHeight;
  map.rgb.resize(std::size_t(remap.mapWidth) * std::size_t(remap.mapHeight) * 3);
}

// The inner loops: one map pixel from its four taps. `Load` turns a sensor sample index into a
// luminance (a code through the LUT, or a float already in luminance).
template <int kChannels, class Load>
void remapPixels(const PolarRemap& remap, int sensorChannels, Load load, float* out) {
  const std::size_t count = remap.topLeftTap.size();
  const std::size_t rowStep = std::size_t(remap.sensorWidth) * std::size_t(sensorChannels);
  const std::size_t colStep = std::size_t(sensorChannels);
  for (std::size_t i = 0; i < count; ++i, out += 3) {
    const std::uint32_t tap = remap.topLeftTap[i];
    if (tap == PolarRemap::kInvalid) {
      out[0] = out[1] = out[2] = 0.0f;
      continue;
    }
    const float fu = remap.fractionU[i];
    const float fv = remap.fractionV[i];
    const float w00 = (1.0f - fu) * (1.0f - fv), w10 = fu * (1.0f - fv);
    const float w01 = (1.0f - fu) * fv, w11 = fu * fv;
    const std::size_t base = std::size_t(tap) * colStep;
    for (int c = 0; c < kChannels; ++c) {
      const std::size_t s = base + std::size_t(c);
      out[c] = w00 * load(c, s) + w10 * load(c, s + colStep) + w01 * load(c, s + rowStep) +
               w11 * load(c, s + rowStep + colStep);
    }
    if constexpr (kChannels == 1) out[1] = out[2] = out[0];
  }
}

// Row y of the table: each map pixel's direction through the lens onto the sensor.
void mapRow(const KannalaBrandtLens& lens, const glm::dmat3& cameraFromWorld, int y,
            PolarRemap& remap) {
  const double theta = thetaFromRowCoord(remap.layout, remap.mapHeight, y + 0.5);
  for (int x = 0; x < remap.mapWidth; ++x) {
    const double phi = phiFromColumnCoord(remap.layout, remap.mapWidth, x + 0.5);
    const auto sensor = lens.sensorFromCamera(cameraFromWorld * directionFromAngles(theta, phi));
    if (!sensor) continue;
    const double u0 = std::floor(sensor->x);
    const double v0 = std::floor(sensor->y);
    if (!(u0 >= 0.0 && v0 >= 0.0 && u0 + 1.0 < remap.sensorWidth &&
          v0 + 1.0 < remap.sensorHeight)) {
      continue;
    }
    const std::size_t i = std::size_t(y) * std::size_t(remap.mapWidth) + std::size_t(x);
    remap.topLeftTap[i] = std::uint32_t(v0) * std::uint32_t(remap.sensorWidth) + std::uint32_t(u0);
    remap.fractionU[i] = float(sensor->x - u0);
    remap.fractionV[i] = float(sensor->y - v0);
  }
}

}  // namespace

std::vector<std::uint8_t> PolarRemap::validMask() const {
  std::vector<std::uint8_t> mask(topLeftTap.size());
  std::ranges::transform(topLeftTap, mask.begin(),
                         [](std::uint32_t tap) { return std::uint8_t(tap != kInvalid ? 1 : 0); });
  return mask;
}

double PolarRemap::validFraction() const {
  if (topLeftTap.empty()) return 0.0;
  const auto valid =
      std::ranges::count_if(topLeftTap, [](std::uint32_t t) { return t != kInvalid; });
  return double(valid) / double(topLeftTap.size());
}

PolarRemap buildPolarRemap(const KannalaBrandtLens& lens, const CameraOrientation& orientation,
                           int sensorWidth, int sensorHeight, MapLayout layout, int mapWidth,
                           int mapHeight) {
  return *buildPolarRemap(lens, orientation, sensorWidth, sensorHeight, layout, mapWidth, mapHeight,
                          [] { return false; });
}

std::optional<PolarRemap> buildPolarRemap(const KannalaBrandtLens& lens,
                                          const CameraOrientation& orientation, int sensorWidth,
                                          int sensorHeight, MapLayout layout, int mapWidth,
                                          int mapHeight,
                                          const std::function<bool()>& stopRequested) {
  PolarRemap remap;
  remap.layout = layout;
  remap.mapWidth = mapWidth;
  remap.mapHeight = mapHeight;
  remap.sensorWidth = sensorWidth;
  remap.sensorHeight = sensorHeight;
  const std::size_t count = std::size_t(mapWidth) * std::size_t(mapHeight);
  remap.topLeftTap.assign(count, PolarRemap::kInvalid);
  remap.fractionU.assign(count, 0.0f);
  remap.fractionV.assign(count, 0.0f);
  const glm::dmat3 cameraFromWorld = glm::transpose(worldFromCamera(orientation));
  for (int y = 0; y < mapHeight; ++y) {
    if (stopRequested && stopRequested()) return std::nullopt;
    mapRow(lens, cameraFromWorld, y, remap);
  }
  return remap;
}

void applyPolarRemap(const PolarRemap& remap, const RawFrame& frame, const CodeToLuminanceLut& lut,
                     EnvMap& map) {
  VEM_EXPECTS(frame.width == remap.sensorWidth && frame.height == remap.sensorHeight);
  VEM_EXPECTS(lut.channels == frame.format.channels && lut.size == frame.format.maxCode() + 1u);
  prepareMap(remap, map);
  const std::uint16_t* codes = frame.codes.data();
  const float* table = lut.luminanceCdM2.data();
  const std::size_t size = lut.size;
  if (frame.format.channels == 1) {
    remapPixels<1>(
        remap, 1, [&](int, std::size_t s) { return table[codes[s]]; }, map.rgb.data());
  } else {
    remapPixels<3>(
        remap, 3, [&](int c, std::size_t s) { return table[std::size_t(c) * size + codes[s]]; },
        map.rgb.data());
  }
}

void applyPolarRemap(const PolarRemap& remap, std::span<const float> luminanceCdM2, int channels,
                     EnvMap& map) {
  VEM_EXPECTS(luminanceCdM2.size() == std::size_t(remap.sensorWidth) *
                                          std::size_t(remap.sensorHeight) * std::size_t(channels));
  prepareMap(remap, map);
  const float* values = luminanceCdM2.data();
  if (channels == 1) {
    remapPixels<1>(
        remap, 1, [&](int, std::size_t s) { return values[s]; }, map.rgb.data());
  } else {
    remapPixels<3>(
        remap, 3, [&](int, std::size_t s) { return values[s]; }, map.rgb.data());
  }
}

}  // namespace vem::calib
