// RecordingContext: what vemd knows about its camera when it starts recording, for the header of a
// VEM recording (docs/vem-format.md, recording/recording_header.h): the camera's identity, the
// frames' size and pixel format, the nominal rate and the calibration in force.
//
// Units: sizes in sensor pixels, nominalRateHz in frames per second (0 = unknown); calibrationToml
// is the whole camera file (calib/io/camera_file.h), empty when none is in force.
#pragma once

#include <cstdint>
#include <string>

#include "frames/raw_frame.h"
#include "recording/recording_header.h"

namespace vem::vemd {

struct RecordingContext {
  std::string cameraModel;
  std::string cameraSerial;
  PixelFormat pixelFormat;
  int widthPx = 0;
  int heightPx = 0;
  double nominalRateHz = 0.0;
  std::string calibrationToml;
};

// The header of a recording made by vemd with this context; createdUnixNs is the caller's clock.
[[nodiscard]] recording::RecordingHeader recordingHeader(const RecordingContext& context,
                                                         std::int64_t createdUnixNs);

}  // namespace vem::vemd
