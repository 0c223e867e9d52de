// An LDR camera for tests and synthetic recordings: a plausible 8-bit response curve (the "truth"
// that response recovery must find again) and exposure brackets of one scene taken through it
// (paper 002: cameras without an HDR sensor bracket exposures and merge them; Debevec & Malik 1997,
// "Recovering High Dynamic Range Radiance Maps from Photographs", section 2, for the curve's role).
//
// Conventions and units (photometric_model.h, camera_simulator.h):
// - The curve is a TabulatedResponse over the 256 codes of an 8-bit sensor, the same in every
//   channel: exposureByCode[c][code] is the relative exposure X = L * exposureUs * gain / scaleCdM2
//   that reads as `code`, normalised so that code 128 reads X = 1. Code 0 reads X = 0.
// - Its shape is a camera's: the sRGB transfer function (a linear toe below code 10, then a 2.4
//   power) with a soft shoulder that compresses the top codes (X / (1 - 0.8 y^8), y = code / 255),
//   about 9.5 stops between codes 10 and 245; strictly increasing.
// - Black level 0, saturation 255.
#pragma once

#include <span>
#include <vector>

#include "calib/core/camera_calibration.h"
#include "calib/core/camera_simulator.h"
#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::calib {

inline constexpr int kLdrMidCode = 128;

// The built-in LDR curve (every channel), scaleCdM2 as given.
[[nodiscard]] TabulatedResponse ldrCameraResponse(double scaleCdM2 = 1.0);

// The built-in curve as a whole photometric calibration: black level 0, saturation 255.
[[nodiscard]] PhotometricCalibration ldrCameraPhotometric(double scaleCdM2 = 1.0);

// The scale (cd/m^2 us per relative exposure unit) that makes `luminanceCdM2` read as `code` in
// channel 0 at `exposureUs` and unit gain: used to place a scene's typical luminance mid-curve.
[[nodiscard]] double scaleForCode(const TabulatedResponse& response, int code, double luminanceCdM2,
                                  double exposureUs);

// Noise of a typical 8-bit camera's gamma-encoded output: about one code at every level (read
// noise 0.8 code, shot noise variance 0.004 x signal codes: 1.3 codes at saturation).
[[nodiscard]] SensorNoise ldrSensorNoise(std::uint64_t seed);

// One frame per exposure, in the order given: simulateFrame with options.exposureUs set to each
// exposure and a noise seed derived from options.noise.seed and the frame's index (so no two frames
// share their noise). Needs truth.lens and truth.photometric, like simulateFrame.
[[nodiscard]] std::vector<RawFrame> simulateBracket(const RadianceFunction& radiance,
                                                    const CameraCalibration& truth,
                                                    std::span<const double> exposuresUs,
                                                    const SimulationOptions& options);

}  // namespace vem::calib
