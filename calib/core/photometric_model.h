// The camera's photometric response: how a sensor code relates to the luminance in front of it
// (paper 004 section 5.1; paper 002 for LDR cameras), and its inverse, used to turn raw codes into
// radiance.
//
// Conventions and units:
// - Luminance L is in cd/m^2, per channel (a grey patch has the same L in every channel). Codes are
//   the sensor's integers (raw_frame.h), exposure in microseconds, gain linear.
// - LogResponse (HDR log sensors, e.g. the HDRC of paper 004): code = a + b ln(L / 1 cd/m^2), per
//   channel; exposure and gain do not enter (the sensor has neither).
// - LinearResponse: code = black + g * L * exposureUs * gain, per channel (g in codes per cd/m^2 us).
// - TabulatedResponse (LDR cameras, Debevec-Malik): for each code, the exposure X = L * exposureUs *
//   gain that produces it, in relative units times scaleCdM2 (1 when only the curve's shape is
//   known). Strictly increasing over the codes that carry information.
// - Codes at or below blackLevelCode read as L = 0; codes at or above saturationCode read as the
//   luminance of saturationCode (the brightest the sensor can tell), and are flagged as clipped where
//   it matters (calibration fits, bracket merging).
#pragma once

#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "frames/raw_frame.h"

namespace vem::calib {

struct LogResponse {
  std::array<double, 3> aCode{};       // code at L = 1 cd/m^2
  std::array<double, 3> bCodePerLn{};  // codes per natural-log unit of luminance (> 0)
};

struct LinearResponse {
  std::array<double, 3> gainCodePerCdM2Us{};  // > 0
};

struct TabulatedResponse {
  // exposureByCode[c][code]: relative exposure X of channel c at that code, size 2^bits.
  std::array<std::vector<double>, 3> exposureByCode;
  double scaleCdM2 = 1.0;  // cd/m^2 us per relative exposure unit
};

using ResponseModel = std::variant<LogResponse, LinearResponse, TabulatedResponse>;

struct PhotometricCalibration {
  ResponseModel response = LogResponse{};
  double blackLevelCode = 0.0;
  double saturationCode = 65535.0;
};

[[nodiscard]] const char* responseModelName(const ResponseModel& model);  // log, linear, table

// Luminance (cd/m^2) that channel `channel` reads as `code` (fractional codes allowed).
[[nodiscard]] double luminanceFromCode(const PhotometricCalibration& calibration, int channel,
                                       double code, double exposureUs, double gain);

// The noiseless, unquantised code a luminance produces, clamped to [black, saturation] (for the
// camera simulator and for fit residuals).
[[nodiscard]] double codeFromLuminance(const PhotometricCalibration& calibration, int channel,
                                       double luminanceCdM2, double exposureUs, double gain);

// A per-channel table from code to luminance for one exposure and gain: built once per change of
// exposure or gain, then one load per pixel.
struct CodeToLuminanceLut {
  int channels = 1;
  std::uint32_t size = 0;              // 2^bits
  std::vector<float> luminanceCdM2;  // channel-major: [channel * size + code]
  double exposureUs = 0.0;
  double gain = 0.0;
};

[[nodiscard]] CodeToLuminanceLut buildCodeToLuminanceLut(const PhotometricCalibration& calibration,
                                                         PixelFormat format, double exposureUs,
                                                         double gain);

}  // namespace vem::calib
