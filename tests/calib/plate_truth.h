// Known ("truth") plate cameras for the plate-camera tests: a small pinhole camera with
// Brown-Conrady distortion and a Kannala-Brandt one, each looking down at the floor board.
#pragma once

#include "calib/core/checkerboard.h"
#include "calib/core/plate_camera.h"

namespace vem::calib::testing {

inline constexpr Checkerboard kPlateBoard{9, 6, 60.0};
// The board on the floor: larger, as it is seen from further away and obliquely.
inline constexpr Checkerboard kFloorBoard{9, 6, 100.0};

inline PlateCamera plateTruth(PlateLensModel model = PlateLensModel::BrownConrady) {
  PlateCamera truth;
  truth.camera = {"Plate-Test", "T-1", 960, 540, PixelFormat{1, 8}};
  truth.intrinsics.widthPx = 960;
  truth.intrinsics.heightPx = 540;
  truth.intrinsics.model = model;
  if (model == PlateLensModel::BrownConrady) {
    truth.intrinsics.fxPx = 820.0;
    truth.intrinsics.fyPx = 818.5;
    truth.intrinsics.distortion = {-0.12, 0.05, 0.0008, -0.0005, 0.0};
  } else {
    truth.intrinsics.fxPx = 520.0;
    truth.intrinsics.fyPx = 519.0;
    truth.intrinsics.distortion = {0.03, -0.01, 0.004, -0.001, 0.0};
  }
  truth.intrinsics.cxPx = 483.25;
  truth.intrinsics.cyPx = 266.75;
  // Above the floor, back from the board's middle and a little to its side: 1.1 m up and 1.3 m
  // back for the pinhole, nearer for the wider Kannala-Brandt lens, so that the board fills
  // about the same part of the image.
  const glm::dvec3 boardMiddleM(0.4, 0.0, 0.25);
  const double nearer = truth.intrinsics.fxPx / 820.0;
  truth.pose = plateLookingAt(boardMiddleM + nearer * glm::dvec3(0.35, 1.1, -1.3), boardMiddleM);
  truth.probeYawRad = 0.6;
  return truth;
}

}  // namespace vem::calib::testing
