// A fitted calibration beside the truth (`vemcalib show --compare TRUTH.toml`), in the units that
// matter: for the lens, pixels on the sensor (projecting the same directions through both lenses)
// and degrees of direction (reading the same pixels through both); for the response, per cent of
// luminance over the code range. Pure: no files, no printing.
#pragma once

#include <ostream>
#include <string>

#include "calib/core/camera_calibration.h"

namespace vem::calibtool {

// How far two lenses are apart over what they see.
struct LensDifference {
  double maxPx = 0.0;   // |sensorFromCamera(fitted) - sensorFromCamera(truth)| over directions
  double rmsPx = 0.0;   //   from the axis to the smaller of the two half fields of view
  double maxDeg = 0.0;  // angle between cameraFromSensor(fitted) and (truth) over pixels
  double rmsDeg = 0.0;  //   within the smaller of the two image circles
  int directions = 0;
  int pixels = 0;
};

// How far two responses are apart: (L_fitted - L_truth) / L_truth in per cent, for every code from
// above the higher black level to below the lower saturation, every channel, at 1000 us, gain 1.
struct ResponseDifference {
  double maxPercent = 0.0;  // largest |difference|
  double rmsPercent = 0.0;
  int firstCode = 0;
  int lastCode = 0;
  int channels = 0;
};

[[nodiscard]] LensDifference compareLenses(const calib::KannalaBrandtLens& fitted,
                                           const calib::KannalaBrandtLens& truth);
[[nodiscard]] ResponseDifference compareResponses(const calib::PhotometricCalibration& fitted,
                                                  const calib::PhotometricCalibration& truth,
                                                  PixelFormat format);

// The table: one line per value, fitted, truth and their difference, then the differences above.
void printComparison(std::ostream& out, const calib::CameraCalibration& fitted,
                     const std::string& fittedPath, const calib::CameraCalibration& truth,
                     const std::string& truthPath);

}  // namespace vem::calibtool
