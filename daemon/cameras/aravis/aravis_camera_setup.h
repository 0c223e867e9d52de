// Applying CameraSettings (daemon/cameras/camera_settings.h) to an open ArvCamera, and reading
// back what is in force. Private to the Aravis backend (it includes arv.h).
//
// - Pixel format by GenICam name (aravis_pixel_formats.h picks it); offsets 0, then Width and
//   Height (0 = the largest the camera allows); a size out of the camera's bounds or off its
//   increment is refused with one sentence naming the bounds.
// - ExposureTime in microseconds (arv_camera_set_exposure_time: ExposureTime or ExposureTimeAbs),
//   ExposureAuto set Off first when present.
// - Gain: the linear factor is converted to the camera's "Gain" feature by its unit: "dB" or no
//   unit (SFNC's Gain is in dB) takes 20 log10(gain); "x"/"times" takes the factor itself. A
//   camera without a float Gain feature (only GainRaw, unitless) refuses any gain but 1 and
//   reports gain 1. GainAuto set Off first when present.
// - AcquisitionFrameRate in Hz. Values outside the feature's bounds are refused, not clamped.
// All refusals are one sentence without the source's name (the caller prefixes it).
#pragma once

#include <expected>
#include <optional>
#include <string>

#include <arv.h>

#include "cameras/aravis/aravis_pixel_formats.h"
#include "cameras/camera_settings.h"

namespace vem::cameras {

struct CameraGeometry {
  const NativePixelFormat* native = nullptr;
  int widthPx = 0;
  int heightPx = 0;
};

// Pixel format, size and frame rate (not exposure or gain: applyExposureGain does those).
[[nodiscard]] std::expected<CameraGeometry, std::string> applyGeometry(
    ArvCamera* camera, const CameraSettings& settings);

// Sets what is given (nullopt leaves the camera's value and its automatic control alone).
[[nodiscard]] std::expected<void, std::string> applyExposureGain(ArvCamera* camera,
                                                                 std::optional<double> exposureUs,
                                                                 std::optional<double> gain);

struct ExposureReadback {
  double exposureUs = 0.0;  // 0 when the camera has no exposure feature
  double gain = 1.0;        // linear
  bool automatic = false;   // ExposureAuto or GainAuto is not Off: values change on their own
};

[[nodiscard]] ExposureReadback readExposureGain(ArvCamera* camera);

// AcquisitionFrameRate in Hz, or 0 when not readable.
[[nodiscard]] double readFrameRateHz(ArvCamera* camera);

}  // namespace vem::cameras
