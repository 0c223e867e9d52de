// CameraSettings and DeviceInfo: what vemd asks of a live camera (the [camera] section of
// config/vemd.toml, docs/cameras.md) and what a backend reports about the cameras it can see.
// The same for every backend (aravis/, v4l2/, libcamera/).
//
// Conventions:
// - pixelFormat names what the pipeline receives, in calib's names ("Mono8", "Mono12", "Mono16",
//   "RGB8", ...; daemon/frames/raw_frame.h); each backend picks the native format that yields it
//   (V4L2 "Y16 " gives Mono16, GenICam "Mono12" gives Mono12). "" lets the backend choose the
//   deepest format the camera offers.
// - exposureUs in microseconds, gain as a linear factor (1 = unity; backends convert to the
//   camera's own unit, e.g. GenICam Gain in dB), frameRateHz in frames per second. nullopt leaves
//   the camera's own value (and its automatic control, if on, untouched).
// - A next() that waits longer than timeoutMs returns SourceErrorCause::Timeout.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vem::cameras {

struct CameraSettings {
  std::string pixelFormat;            // "" = the deepest the camera offers
  int widthPx = 0;                    // 0 = the camera's full (or current) size
  int heightPx = 0;
  std::optional<double> exposureUs;   // manual exposure
  std::optional<double> gain;         // linear
  std::optional<double> frameRateHz;  // requested acquisition rate
  int buffers = 4;                    // capture buffers queued with the driver (at least 2)
  std::int64_t timeoutMs = 1000;
  std::string calibrationToml;  // the camera file in force (its text), handed to describe()
  friend bool operator==(const CameraSettings&, const CameraSettings&) = default;
};

// One camera a backend can open, for `vemd --list-devices`.
struct DeviceInfo {
  std::string spec;    // what --source takes: "aravis:Fake-GV01", "v4l2:/dev/video0", ...
  std::string model;   // vendor and model as the device names itself
  std::string serial;  // "" when the device has none
  std::vector<std::string> modes;  // "Mono16 1280x1024", "YUYV 640x480 (as RGB8)", ...
};

}  // namespace vem::cameras
