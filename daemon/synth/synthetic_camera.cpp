#include "synth/synthetic_camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/mat3x3.hpp>

#include "calib/core/camera_orientation.h"
#include "core/color.h"
#include "util/contract.h"

namespace vem::synth {
namespace {

constexpr std::size_t kNormalCount = 65536;  // a power of two: indices are 16 hash bits

// splitmix64: the sequence depends only on the state's start.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<float> gaussianDraws(std::uint64_t seed) {
  std::vector<float> draws(kNormalCount);
  std::uint64_t state = mix(seed);
  const auto uniform = [&state] {
    state = mix(state);
    return (double(state >> 11) + 0.5) * 0x1.0p-53;
  };
  for (float& draw : draws) {  // Box-Muller, one of each pair
    const double u1 = uniform();
    const double u2 = uniform();
    draw = float(std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2));
  }
  return draws;
}

}  // namespace

std::optional<std::string> syntheticCameraProblem(const calib::CameraCalibration& calibration) {
  if (!calibration.photometric) {
    return "the camera has no photometric section (its response turns radiance into codes)";
  }
  if (!calibration.lens) {
    return "the camera has no geometric section (its lens says where each pixel looks)";
  }
  if (calibration.camera.sensorWidthPx <= 0 || calibration.camera.sensorHeightPx <= 0) {
    return "the camera's sensor has no pixels";
  }
  return std::nullopt;
}

SyntheticCamera::SyntheticCamera(calib::CameraCalibration calibration,
                                 SyntheticCameraOptions options)
    : calibration_(std::move(calibration)), options_(options) {
  VEM_EXPECTS(!syntheticCameraProblem(calibration_));
  const calib::PhotometricCalibration& photometric = *calibration_.photometric;
  topCode_ = std::uint16_t(
      std::min(double(calibration_.camera.pixelFormat.maxCode()), photometric.saturationCode));
  shotNoise_ = !std::holds_alternative<calib::LogResponse>(photometric.response) &&
               options_.noise.shotNoiseGain > 0.0;
  if (options_.noise.readNoiseCode > 0.0 || shotNoise_) {
    normals_ = gaussianDraws(options_.noise.seed);
  }
  options_.samplesPerAxis = std::max(1, options_.samplesPerAxis);
  traceSensor();
}

// Every sample's world direction, as simulateFrame traces it: the lens, then the orientation.
void SyntheticCamera::traceSensor() {
  const calib::KannalaBrandtLens& lens = *calibration_.lens;
  const glm::dmat3 worldFromCam = calib::worldFromCamera(calibration_.orientation);
  const int width = calibration_.camera.sensorWidthPx;
  const int height = calibration_.camera.sensorHeightPx;
  const int s = options_.samplesPerAxis;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const std::size_t before = sampleDirs_.size();
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          const glm::dvec2 p(u - 0.5 + (i + 0.5) / s, v - 0.5 + (j + 0.5) / s);
          if (const auto dirCamera = lens.cameraFromSensor(p)) {
            sampleDirs_.emplace_back(worldFromCam * *dirCamera);
          }
        }
      }
      const auto pixel = std::uint32_t(v * width + u);
      if (sampleDirs_.size() > before) {
        litPixels_.push_back(pixel);
        sampleEnd_.push_back(std::uint32_t(sampleDirs_.size()));
      } else {
        darkPixels_.push_back(pixel);
      }
    }
  }
}

const SensorCodeTable& SyntheticCamera::codeTable(double exposureUs, double gain) {
  if (!table_ || table_->exposureUs() != exposureUs || table_->gain() != gain) {
    table_.emplace(*calibration_.photometric, calibration_.camera.pixelFormat, exposureUs, gain);
  }
  return *table_;
}

RawFrame SyntheticCamera::render(const SceneState& state, std::uint64_t frameIndex) {
  RawFrame frame;
  render(state, frameIndex, frame);
  return frame;
}

void SyntheticCamera::render(const SceneState& state, std::uint64_t frameIndex, RawFrame& frame) {
  const calib::CameraIdentity& camera = calibration_.camera;
  frame.width = camera.sensorWidthPx;
  frame.height = camera.sensorHeightPx;
  frame.format = camera.pixelFormat;
  frame.exposureUs = state.exposureUs;
  frame.gain = state.gain;
  frame.codes.resize(std::size_t(frame.width) * std::size_t(frame.height) *
                     std::size_t(camera.pixelFormat.channels));
  const SensorCodeTable& table = codeTable(state.exposureUs, state.gain);
  const bool mono = camera.pixelFormat.channels == 1;
  if (normals_.empty()) {
    mono ? renderCodes<false, 1>(state, table, frameIndex, frame)
         : renderCodes<false, 3>(state, table, frameIndex, frame);
  } else {
    mono ? renderCodes<true, 1>(state, table, frameIndex, frame)
         : renderCodes<true, 3>(state, table, frameIndex, frame);
  }
}

template <bool kNoisy, int kChannels>
void SyntheticCamera::renderCodes(const SceneState& state, const SensorCodeTable& table,
                                  std::uint64_t frameIndex, RawFrame& frame) const {
  const calib::PhotometricCalibration& photometric = *calibration_.photometric;
  const auto saturation = float(photometric.saturationCode);
  const auto black = float(photometric.blackLevelCode);
  const auto top = float(topCode_);
  const auto readVariance = float(options_.noise.readNoiseCode * options_.noise.readNoiseCode);
  const auto shotGain = shotNoise_ ? float(options_.noise.shotNoiseGain) : 0.0F;
  // Noise: three 16-bit indices into the Gaussian draws per pixel, from a hash of the pixel and a
  // key of (seed, frame index).
  const std::uint64_t frameKey = mix(options_.noise.seed ^ mix(frameIndex));
  const auto write = [&](std::uint32_t pixel, const std::array<float, kChannels>& ideal) {
    std::uint16_t* codes = frame.codes.data() + std::size_t(pixel) * kChannels;
    [[maybe_unused]] std::uint64_t hash = 0;
    if constexpr (kNoisy) hash = mix(frameKey + std::uint64_t(pixel) * 0xd1342543de82ef95ull);
    for (int c = 0; c < kChannels; ++c) {
      float code = ideal[std::size_t(c)];
      // A saturated pixel is at its full well: it reads the saturation code, without noise.
      if (code >= saturation) {
        codes[c] = topCode_;
        continue;
      }
      if constexpr (kNoisy) {
        const float normal = normals_[(hash >> (16 * c)) & (kNormalCount - 1)];
        code += std::sqrt(readVariance + shotGain * std::max(0.0F, code - black)) * normal;
      }
      codes[c] = std::uint16_t(std::clamp(code, 0.0F, top) + 0.5F);  // rounded: code >= 0
    }
  };

  std::array<float, kChannels> dark{};
  for (int c = 0; c < kChannels; ++c) dark[std::size_t(c)] = table.idealCode(c, 0.0F);
  for (const std::uint32_t pixel : darkPixels_) write(pixel, dark);

  const double weight = 1.0 / double(options_.samplesPerAxis * options_.samplesPerAxis);
  std::uint32_t sample = 0;
  std::array<float, kChannels> ideal{};
  for (std::size_t k = 0; k < litPixels_.size(); ++k) {
    glm::dvec3 sum(0.0);
    for (; sample < sampleEnd_[k]; ++sample) sum += state.radiance(glm::dvec3(sampleDirs_[sample]));
    const glm::dvec3 rgb = sum * weight;
    if constexpr (kChannels == 1) {
      ideal[0] = table.idealCode(0, float(luminance(rgb)));
    } else {
      for (int c = 0; c < 3; ++c) ideal[std::size_t(c)] = table.idealCode(c, float(rgb[c]));
    }
    write(litPixels_[k], ideal);
  }
}

}  // namespace vem::synth
