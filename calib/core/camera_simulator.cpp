#include "calib/core/camera_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/mat3x3.hpp>

#include "calib/core/camera_orientation.h"
#include "core/color.h"
#include "util/contract.h"

namespace vem::calib {
namespace {

// splitmix64: a small, fast, well-mixed generator; the sequence depends only on the seed.
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double uniform01(std::uint64_t& state) {
  return (double(nextRandom(state) >> 11) + 0.5) * 0x1.0p-53;
}

// Bilinear radiance of `map` at continuous pixel coordinates (xc, yc) in [0, W] x [0, H]: wraps
// around the azimuth, clamps at the poles (or at the horizon of a hemisphere).
glm::dvec3 bilinear(const EnvMap& map, double xc, double yc) {
  const double fx = xc - 0.5;
  const double fy = std::clamp(yc - 0.5, 0.0, double(map.height - 1));
  const int x0 = int(std::floor(fx));
  const int y0 = std::min(int(std::floor(fy)), map.height - 1);
  const int y1 = std::min(y0 + 1, map.height - 1);
  const double tx = fx - x0;
  const double ty = fy - y0;
  const int xa = ((x0 % map.width) + map.width) % map.width;
  const int xb = (xa + 1) % map.width;
  const glm::dvec3 top = glm::dvec3(map.at(xa, y0)) * (1.0 - tx) + glm::dvec3(map.at(xb, y0)) * tx;
  const glm::dvec3 bottom =
      glm::dvec3(map.at(xa, y1)) * (1.0 - tx) + glm::dvec3(map.at(xb, y1)) * tx;
  return top * (1.0 - ty) + bottom * ty;
}

}  // namespace

RadianceFunction radianceFromMap(const EnvMap& environment) {
  return [map = environment](const glm::dvec3& dir) -> glm::dvec3 {
    const double theta = std::acos(std::clamp(dir.y, -1.0, 1.0));
    if (theta > thetaMaxRad(map.layout)) return glm::dvec3(0.0);
    double phi = std::atan2(dir.z, dir.x);  // (-pi, pi]
    double xc = 0.0;
    if (map.layout == MapLayout::Sphere) {
      xc = (phi / (2.0 * std::numbers::pi) + 0.5) * map.width;
    } else {
      if (phi < 0.0) phi += 2.0 * std::numbers::pi;
      xc = phi / (2.0 * std::numbers::pi) * map.width;
    }
    const double yc = theta / thetaMaxRad(map.layout) * map.height;
    const glm::dvec3 value = bilinear(map, xc, yc);
    // Sanitise like the core does: NaN and negative radiance read as 0.
    return glm::dvec3(std::isfinite(value.x) && value.x > 0.0 ? value.x : 0.0,
                      std::isfinite(value.y) && value.y > 0.0 ? value.y : 0.0,
                      std::isfinite(value.z) && value.z > 0.0 ? value.z : 0.0);
  };
}

SensorResponseSimulator::SensorResponseSimulator(const CameraCalibration& calibration,
                                                 const SimulationOptions& options)
    : photometric_(*calibration.photometric),
      format_(calibration.camera.pixelFormat),
      options_(options),
      state_(options.noise.seed) {}

double SensorResponseSimulator::gaussian() {
  // Box-Muller; one of the pair is enough here.
  const double u1 = uniform01(state_);
  const double u2 = uniform01(state_);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::uint16_t SensorResponseSimulator::code(int channel, double luminanceCdM2) {
  const double ideal =
      codeFromLuminance(photometric_, channel, luminanceCdM2, options_.exposureUs, options_.gain);
  const double top = std::min(double(format_.maxCode()), photometric_.saturationCode);
  // A saturated pixel is at its full well: it reads the saturation code, without noise.
  if (ideal >= photometric_.saturationCode) return std::uint16_t(top);
  double variance = options_.noise.readNoiseCode * options_.noise.readNoiseCode;
  if (!std::holds_alternative<LogResponse>(photometric_.response)) {
    variance += options_.noise.shotNoiseGain * std::max(0.0, ideal - photometric_.blackLevelCode);
  }
  const double noisy = variance > 0.0 ? ideal + std::sqrt(variance) * gaussian() : ideal;
  return std::uint16_t(std::clamp(std::round(noisy), 0.0, top));
}

RawFrame simulateFrame(const RadianceFunction& radiance, const CameraCalibration& calibration,
                       const SimulationOptions& options) {
  VEM_EXPECTS(calibration.lens && calibration.photometric);
  const KannalaBrandtLens& lens = *calibration.lens;
  const glm::dmat3 worldFromCam = worldFromCamera(calibration.orientation);
  const CameraIdentity& camera = calibration.camera;
  RawFrame frame = RawFrame::blank(camera.sensorWidthPx, camera.sensorHeightPx, camera.pixelFormat);
  frame.exposureUs = options.exposureUs;
  frame.gain = options.gain;
  SensorResponseSimulator sensor(calibration, options);
  const int s = std::max(1, options.supersamples);
  const double weight = options.radianceScale / double(s * s);
  const int channels = camera.pixelFormat.channels;
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          const glm::dvec2 p(u - 0.5 + (i + 0.5) / s, v - 0.5 + (j + 0.5) / s);
          if (const auto dirCamera = lens.cameraFromSensor(p)) {
            sum += radiance(worldFromCam * *dirCamera);
          }
        }
      }
      const glm::dvec3 rgb = sum * weight;
      if (channels == 1) {
        frame.codes[frame.index(u, v)] = sensor.code(0, luminance(rgb));
      } else {
        for (int c = 0; c < 3; ++c) frame.codes[frame.index(u, v, c)] = sensor.code(c, rgb[c]);
      }
    }
  }
  return frame;
}

RawFrame simulatePatchFrame(std::span<const PatchSpec> patches, double backgroundCdM2,
                            const CameraCalibration& calibration,
                            const SimulationOptions& options) {
  VEM_EXPECTS(calibration.photometric);
  const CameraIdentity& camera = calibration.camera;
  RawFrame frame = RawFrame::blank(camera.sensorWidthPx, camera.sensorHeightPx, camera.pixelFormat);
  frame.exposureUs = options.exposureUs;
  frame.gain = options.gain;
  SensorResponseSimulator sensor(calibration, options);
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      double luminance = backgroundCdM2;
      for (const PatchSpec& p : patches) {
        if (u >= p.x && u < p.x + p.width && v >= p.y && v < p.y + p.height) {
          luminance = p.luminanceCdM2;
        }
      }
      for (int c = 0; c < camera.pixelFormat.channels; ++c) {
        frame.codes[frame.index(u, v, c)] = sensor.code(c, luminance * options.radianceScale);
      }
    }
  }
  return frame;
}

}  // namespace vem::calib
