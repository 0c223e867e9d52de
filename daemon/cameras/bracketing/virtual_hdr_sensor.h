// VirtualHdrSensor: how a merged exposure bracket is handed on, as the frame of an HDR log sensor
// (paper 004's HDRC kind: code = a + b ln L), so that vemd's pipeline, recordings and replay treat
// a bracketing LDR camera like any HDR camera (photometric_model.h's LogResponse).
//
// Conventions and units:
// - Format: 16 bits, the LDR camera's channels (Mono16 or RGB16); black level code 0, saturation
//   code 65535. Luminance in cd/m^2 per channel (or the LDR response's relative unit when its
//   scale is 1).
// - Range per channel c: from minCdM2 = the luminance of the darkest weighed code of the LONGEST
//   exposure (the first code above the noise floor, blackLevel + blackMargin; bracket_merge.h) to
//   maxCdM2 = the luminance of the saturation code at the SHORTEST exposure: everything the merged
//   bracket can tell. Codes 1 .. 65535 span it logarithmically:
//       code = a + b ln L,  b = 65534 / ln(max / min),  a = 1 - b ln(min),
//   so L = min reads code 1 and L = max reads 65535 (the virtual saturation: "at least max").
// - Encoding: rounded to the nearest code; L below min (including 0) reads code 0, the black level
//   (L = 0: the noise floor of every exposure); L above max reads 65535. Both are counted.
// - Quantisation: one code is a relative step of exp(1 / b) - 1 ~ ln(max / min) / 65534 in
//   luminance, and rounding errs by half that: for calib's 8-bit LDR response bracketed 5 x 2
//   stops (10.5 stops per exposure from code 11 to 255, 18.5 in all, ln range 12.9) a step of
//   2.0e-4 (0.02 %); at the settings' widest (9 exposures 8 stops apart: 74.5 stops, ln range 52)
//   7.9e-4 (0.08 %). relativeStep() gives the figure of a sensor.
// - Exposure and gain do not enter a log response; the frames carry exposureUs = the sum of the
//   bracket's nominal exposures (the group's total integration time) and gain 1, constant for a
//   given bracket so the pipeline's code table is built once.
#pragma once

#include <array>
#include <cstdint>
#include <expected>
#include <span>
#include <string>

#include "calib/core/bracket_merge.h"
#include "calib/core/camera_calibration.h"
#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::cameras {

inline constexpr std::uint16_t kVirtualTopCode = 65535;

struct VirtualHdrSensor {
  PixelFormat format{1, 16};
  calib::LogResponse response;      // channels beyond format.channels copy channel 0
  std::array<double, 3> minCdM2{};  // reads code 1
  std::array<double, 3> maxCdM2{};  // reads code 65535

  // The largest relative luminance step of one code over the channels: exp(1 / b) - 1.
  [[nodiscard]] double relativeStep() const;
  // The response as a photometric calibration: log, black level 0, saturation 65535.
  [[nodiscard]] calib::PhotometricCalibration photometric() const;
};

// The merge weighting for an LDR format: the calib defaults (4 codes of margin at either end, for
// 8 bits) scaled by 2^(bits - 8) on the saturation side; the noise floor is 10 codes at 8 bits
// (scaled likewise), where the sRGB-like toe of an 8-bit response has relative steps of 10 %: a
// rounded code then errs by at most 1 / (2 x 11) = 4.5 %.
[[nodiscard]] calib::BracketWeighting bracketWeightingFor(PixelFormat ldrFormat);

// The sensor that spans what exposures `effectiveExposuresUs` (exposure x gain, any order) of the
// LDR camera `ldr` can tell, with `weighting`'s noise floor. One sentence when the response gives
// no usable range (no code above the noise floor below saturation, or a non-increasing response).
[[nodiscard]] std::expected<VirtualHdrSensor, std::string> makeVirtualHdrSensor(
    const calib::PhotometricCalibration& ldr, PixelFormat ldrFormat,
    std::span<const double> effectiveExposuresUs, const calib::BracketWeighting& weighting);

// The LDR camera's calibration turned into the virtual sensor's: the same identity, lens,
// orientation and fit records, its pixel format 16 bits and its response `sensor`'s.
[[nodiscard]] calib::CameraCalibration virtualCameraCalibration(
    const calib::CameraCalibration& ldrCamera, const VirtualHdrSensor& sensor);

}  // namespace vem::cameras
