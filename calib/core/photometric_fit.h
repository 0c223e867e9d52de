// Photometric calibration from grey patches of known luminance (paper 004 section 5.1): the mean
// code of each patch, a least-squares fit of the response per channel, and the errors of the
// patches left out of the fit ("check" patches), with the refusals that keep a bad fit from
// replacing a good calibration.
//
// Conventions: patch regions are in sensor pixels (raw_frame.h), luminance in cd/m^2, residuals in
// percent of the patch's known luminance: 100 (L_fit / L_known - 1), where L_fit is the
// luminance the fitted response reads from the patch's mean code.
#pragma once

#include <array>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include "calib/core/camera_calibration.h"
#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct PatchSpec {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;  // region, sensor pixels
  double luminanceCdM2 = 0.0;
  bool check = false;  // left out of the fit, used to assess it
};

struct PatchMeasurement {
  PatchSpec spec;
  int channels = 1;
  std::array<double, 3> meanCode{};
  std::array<double, 3> stdDevCode{};  // over the region's pixels and the frames
  double clippedFraction = 0.0;        // share of samples at or above saturation
  double underBlackFraction = 0.0;     // share of samples at or below the black level
  double exposureUs = 0.0;
  double gain = 0.0;
};

// Averages the patch's region over every frame (all frames must share size, format, exposure and
// gain; the region must lie on the sensor: the caller validates both against its inputs).
[[nodiscard]] PatchMeasurement measurePatch(std::span<const RawFrame> frames,
                                            const PatchSpec& patch, double blackLevelCode,
                                            double saturationCode);

enum class FitModel { Log, Linear };

struct PhotometricFitOptions {
  FitModel model = FitModel::Log;
  double blackLevelCode = 0.0;
  double saturationCode = 65535.0;
  double maxResidualPercent = 3.0;    // largest fit-patch residual accepted
  double maxCheckErrorPercent = 5.0;  // largest check-patch error accepted
  double maxClippedFraction = 0.01;   // a patch with more clipped or black samples is unusable
  double minLuminanceRatio = 4.0;     // brightest / darkest fit patch
};

struct PatchResult {
  std::string name;
  bool check = false;
  double luminanceCdM2 = 0.0;
  std::array<double, 3> meanCode{};
  std::array<double, 3> fittedLuminanceCdM2{};
  std::array<double, 3> errorPercent{};
};

struct PhotometricFit {
  PhotometricCalibration calibration;
  PhotometricQuality quality;
  std::vector<PatchResult> patches;  // in the order given
};

enum class PhotometricRefusal {
  TooFewPatches,
  PatchClipped,
  NotIncreasing,
  LuminanceSpanTooSmall,
  ResidualTooHigh,
  CheckErrorTooHigh,
};

struct PhotometricFitFailure {
  PhotometricRefusal cause;
  std::string message;  // one sentence naming the patch and the limit
  std::vector<PatchResult> patches;  // filled when the fit ran (residual refusals), else empty
};

[[nodiscard]] std::expected<PhotometricFit, PhotometricFitFailure> fitPhotometric(
    std::span<const PatchMeasurement> patches, const PhotometricFitOptions& options);

}  // namespace vem::calib
