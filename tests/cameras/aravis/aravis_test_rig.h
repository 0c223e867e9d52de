// Helpers shared by the Aravis source tests: settings for the fake camera, frames that must come,
// and which drawn frame a delivered one is.
#pragma once

#include <expected>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cameras/aravis/aravis_source.h"
#include "cameras/camera_settings.h"

namespace vem::testing {

inline constexpr const char* kFakeAddress = "127.0.0.1";

inline cameras::CameraSettings fakeSettings(const std::string& pixelFormat, int width, int height,
                                            double rateHz) {
  cameras::CameraSettings s;
  s.pixelFormat = pixelFormat;
  s.widthPx = width;
  s.heightPx = height;
  s.frameRateHz = rateHz;
  s.buffers = 4;
  s.timeoutMs = 1000;
  return s;
}

// The next frame, riding over up to `attempts` - 1 Timeout or BadFrame errors (the first frames
// after a start); the last error otherwise.
inline std::expected<vem::CapturedFrame, vem::SourceError> nextFrame(vem::FrameSource& source,
                                                                     int attempts = 5) {
  std::expected<vem::CapturedFrame, vem::SourceError> got = source.next();
  for (int i = 1; i < attempts && !got &&
                  (got.error().cause == vem::SourceErrorCause::Timeout ||
                   got.error().cause == vem::SourceErrorCause::BadFrame);
       ++i) {
    got = source.next();
  }
  return got;
}

// Index of the drawn frame whose codes `frame` has exactly, or -1.
inline int drawnIndex(const vem::RawFrame& frame, const std::vector<vem::RawFrame>& drawn) {
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    if (drawn[i].width == frame.width && drawn[i].height == frame.height &&
        drawn[i].codes == frame.codes) {
      return int(i);
    }
  }
  return -1;
}

}  // namespace vem::testing
