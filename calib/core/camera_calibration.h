// A camera's whole calibration as vemcalib writes it and vemd applies it: the camera's identity and
// sensor, its photometric response, its lens and its orientation in the world. The file format
// (TOML, versioned) is calib/io/camera_file.h; docs/calibration.md describes both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "calib/core/camera_orientation.h"
#include "calib/core/kannala_brandt.h"
#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct CameraIdentity {
  std::string model = "unknown";
  std::string serial = "unknown";
  int sensorWidthPx = 0;
  int sensorHeightPx = 0;
  PixelFormat pixelFormat;
};

// How well a photometric fit matched its patches (percent of luminance).
struct PhotometricQuality {
  double rmsResidualPercent = 0.0;
  double maxResidualPercent = 0.0;
  double maxCheckErrorPercent = 0.0;  // 0 when no check patches were given
  int fitPatches = 0;
  int checkPatches = 0;
  std::string date;  // ISO 8601, UTC, when the fit was made
};

struct GeometricQuality {
  double rmsReprojectionPx = 0.0;
  int views = 0;
  int corners = 0;
  std::string date;
};

struct CameraCalibration {
  CameraIdentity camera;
  std::optional<PhotometricCalibration> photometric;
  PhotometricQuality photometricQuality;
  std::optional<KannalaBrandtLens> lens;
  GeometricQuality geometricQuality;
  CameraOrientation orientation;
};

}  // namespace vem::calib
