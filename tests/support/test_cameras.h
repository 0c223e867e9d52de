// Cameras for the calibration tests: a log-sensor (HDRC-like) photometric truth, a 190-degree
// Kannala-Brandt lens with every coefficient in use, and a grey-patch chart.
#pragma once

#include <vector>

#include "calib/core/camera_calibration.h"
#include "calib/core/photometric_fit.h"

namespace vem::testing {

// 12-bit log sensor: black 64, saturation 4095, about eight decades (1e-3 .. 1e5 cd/m^2).
[[nodiscard]] calib::PhotometricCalibration logSensorTruth(int channels);
// A 190-degree lens on a width x height sensor: k2..k5 non-zero, principal point off centre,
// aspect 1.0008.
[[nodiscard]] calib::KannalaBrandtLens wideLensTruth(int width, int height);
// A whole camera: identity, photometric truth, lens truth, reference orientation.
[[nodiscard]] calib::CameraCalibration cameraTruth(int width, int height, int channels);
// Six fit patches from 0.5 to 2e4 cd/m^2 and two check patches, 24 x 24 px, on a row of the frame.
[[nodiscard]] std::vector<calib::PatchSpec> greyChart(int width, int height);

}  // namespace vem::testing
