#include "cameras/bracketing/virtual_hdr_sensor.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace vem::cameras {
namespace {

constexpr double kCodeSpan = double(kVirtualTopCode) - 1.0;  // codes 1 .. 65535
constexpr double kNoiseFloorCode8Bit = 10.0;
constexpr double kSaturationMarginCode8Bit = 4.0;

}  // namespace

double VirtualHdrSensor::relativeStep() const {
  double step = 0.0;
  for (int c = 0; c < format.channels; ++c) {
    step = std::max(step, std::expm1(1.0 / response.bCodePerLn[std::size_t(c)]));
  }
  return step;
}

calib::PhotometricCalibration VirtualHdrSensor::photometric() const {
  return calib::PhotometricCalibration{response, 0.0, double(kVirtualTopCode)};
}

calib::BracketWeighting bracketWeightingFor(PixelFormat ldrFormat) {
  const double scale = std::exp2(ldrFormat.bits - 8);
  return calib::BracketWeighting{kNoiseFloorCode8Bit * scale, kSaturationMarginCode8Bit * scale};
}

std::expected<VirtualHdrSensor, std::string> makeVirtualHdrSensor(
    const calib::PhotometricCalibration& ldr, PixelFormat ldrFormat,
    std::span<const double> effectiveExposuresUs, const calib::BracketWeighting& weighting) {
  const auto [shortest, longest] =
      std::minmax_element(effectiveExposuresUs.begin(), effectiveExposuresUs.end());
  const double darkestCode = std::floor(ldr.blackLevelCode + weighting.blackMarginCode) + 1.0;
  if (!(darkestCode < ldr.saturationCode - weighting.saturationMarginCode)) {
    return std::unexpected(fmt::format(
        "the camera's response weighs no code: the noise floor ends at code {} and clipping starts "
        "at code {}",
        darkestCode - 1.0, ldr.saturationCode - weighting.saturationMarginCode));
  }
  VirtualHdrSensor sensor;
  sensor.format = PixelFormat{ldrFormat.channels, 16};
  for (int c = 0; c < 3; ++c) {
    const int from = c < ldrFormat.channels ? c : 0;
    const double lo = calib::luminanceFromCode(ldr, from, darkestCode, *longest, 1.0);
    const double hi = calib::luminanceFromCode(ldr, from, ldr.saturationCode, *shortest, 1.0);
    if (!(lo > 0.0 && hi > lo && std::isfinite(hi))) {
      return std::unexpected(fmt::format(
          "the camera's response in channel {} gives no luminance range ({} to {} cd/m2 between "
          "code {} of the longest exposure and saturation of the shortest)",
          from, lo, hi, darkestCode));
    }
    const auto i = std::size_t(c);
    sensor.minCdM2[i] = lo;
    sensor.maxCdM2[i] = hi;
    sensor.response.bCodePerLn[i] = kCodeSpan / std::log(hi / lo);
    sensor.response.aCode[i] = 1.0 - sensor.response.bCodePerLn[i] * std::log(lo);
  }
  return sensor;
}

calib::CameraCalibration virtualCameraCalibration(const calib::CameraCalibration& ldrCamera,
                                                  const VirtualHdrSensor& sensor) {
  calib::CameraCalibration virtualCamera = ldrCamera;
  virtualCamera.camera.pixelFormat = sensor.format;
  virtualCamera.photometric = sensor.photometric();
  return virtualCamera;
}

}  // namespace vem::cameras
