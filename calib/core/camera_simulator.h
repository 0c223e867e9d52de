// The camera simulator: the raw frame a calibrated camera would deliver in front of a known
// environment, for tests, benchmarks and synthetic recordings. Ground truth in, sensor codes out:
// each sensor pixel's direction (kannala_brandt.h, camera_orientation.h) looks up the environment,
// the response (photometric_model.h) turns luminance into a code, noise is added and the code is
// quantised and clipped like a real sensor's.
//
// Conventions: the environment is an EnvMap of daemon/core/env_map.h (any layout; directions
// outside it read 0) whose values are luminance in cd/m^2 per channel, times radianceScale.
// Pixels outside the lens circle read the black level plus noise. Noise: Gaussian read noise of
// readNoiseCode codes, plus photon shot noise for linear and tabulated responses (variance
// shotNoiseGain * (code - black)); a log sensor gets read noise only. A pixel at or beyond saturation
// reads the saturation code exactly (a full well has no noise left). All randomness comes from
// `seed`: the same inputs give the same frame.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include <glm/vec3.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/core/photometric_fit.h"
#include "core/env_map.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct SensorNoise {
  double readNoiseCode = 0.0;
  double shotNoiseGain = 0.0;  // codes per electron-equivalent: variance = gain * signal codes
  std::uint64_t seed = 1;
};

struct SimulationOptions {
  double exposureUs = 1000.0;
  double gain = 1.0;
  double radianceScale = 1.0;
  int supersamples = 2;  // per pixel and axis: the pixel's area, not its centre
  SensorNoise noise;
};

// Radiance (cd/m^2 per channel) arriving from a world direction.
using RadianceFunction = std::function<glm::dvec3(const glm::dvec3& dirWorld)>;

// Bilinear lookup into an environment map (by direction), for simulateFrame.
[[nodiscard]] RadianceFunction radianceFromMap(const EnvMap& environment);

// Needs calibration.lens and calibration.photometric; frame size and format from calibration.camera.
[[nodiscard]] RawFrame simulateFrame(const RadianceFunction& radiance,
                                     const CameraCalibration& calibration,
                                     const SimulationOptions& options);

// A calibration target in front of the camera: each patch's region filled with its luminance (grey,
// every channel), the rest with backgroundCdM2, through the same response and noise (no lens).
[[nodiscard]] RawFrame simulatePatchFrame(std::span<const PatchSpec> patches,
                                          double backgroundCdM2,
                                          const CameraCalibration& calibration,
                                          const SimulationOptions& options);

// Applies the sensor to a luminance value: response, noise, quantisation and clipping (shared by
// every simulated frame, and by the bracket and checkerboard simulations).
class SensorResponseSimulator {
 public:
  SensorResponseSimulator(const CameraCalibration& calibration, const SimulationOptions& options);
  [[nodiscard]] std::uint16_t code(int channel, double luminanceCdM2);

 private:
  PhotometricCalibration photometric_;
  PixelFormat format_;
  SimulationOptions options_;
  std::uint64_t state_;
  [[nodiscard]] double gaussian();
};

}  // namespace vem::calib
