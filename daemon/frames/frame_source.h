// FrameSource: where vemd's frames come from (a replayed recording, a synthetic scene, a camera),
// behind one interface the capture thread drives.
//
// - next() blocks until the next frame is due and returns it, or returns a typed error:
//   EndOfStream (a recording ran out: the daemon stops), Timeout (no frame in time, or next() was
//   interrupted), NoDevice (the device is gone or cannot be opened), BadFrame (a frame arrived
//   but cannot be used). The daemon retries every cause but EndOfStream with backoff and logs
//   each once per change of state, so a source reports a lost camera and keeps trying to reopen
//   it on later calls.
// - Frames carry the conventions of captured_frame.h: seq strictly increasing, captureTsNs on the
//   source's clock (SourceDescription::liveClock says whether that is CLOCK_MONOTONIC), arrivalNs
//   on CLOCK_MONOTONIC when the source handed the frame over.
// - recycle() gives back a frame the daemon is done with (or dropped) so its buffers serve a
//   later frame: a steady stream then allocates nothing. It is called on the capture thread,
//   like next().
// - interrupt() may be called from any thread: it wakes a next() that waits (pacing, a device),
//   which then returns Timeout. Later calls to next() wait normally again.
// - setExposure() asks a source with exposure control (cameras, the synthetic camera) to take the
//   frames it captures from now on with this exposure (microseconds) and gain (linear, 1 = unity).
//   Cameras apply it a few frames late; every frame carries in RawFrame::exposureUs and ::gain
//   what it was really taken with, so consumers (bracketing) go by the frame, not the request.
//   Sources without exposure control (replay) refuse with a sentence. Capture thread only.
#pragma once

#include <cstdint>
#include <expected>
#include <string>

#include "frames/captured_frame.h"
#include "frames/raw_frame.h"

namespace vem {

enum class SourceErrorCause { EndOfStream, Timeout, NoDevice, BadFrame };

[[nodiscard]] const char* sourceErrorName(SourceErrorCause cause);  // "end of stream", ...

struct SourceError {
  SourceErrorCause cause = SourceErrorCause::EndOfStream;
  std::string message;  // one sentence naming the source and the cause
};

// What a source delivers: the camera, its calibration, its pace.
struct SourceDescription {
  std::string spec;  // as given: "replay:FILE", "synthetic:SCENE"
  std::string cameraModel;
  std::string cameraSerial;
  int sensorWidthPx = 0;
  int sensorHeightPx = 0;
  PixelFormat pixelFormat;
  std::string calibrationToml;  // the camera file in force (calib/io/camera_file.h); may be empty
  double nominalRateHz = 0.0;   // 0 = unknown
  bool liveClock = false;       // captureTsNs is CLOCK_MONOTONIC (the latency from capture)
  bool paced = true;            // frames come at a pace of their own (false: as fast as asked)
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  [[nodiscard]] virtual SourceDescription describe() const = 0;
  [[nodiscard]] virtual std::expected<CapturedFrame, SourceError> next() = 0;
  virtual void recycle(CapturedFrame&& spent) = 0;
  virtual void interrupt() = 0;
  [[nodiscard]] virtual std::expected<void, std::string> setExposure(double exposureUs,
                                                                     double gain);
};

// CLOCK_MONOTONIC now, in nanoseconds (the clock of arrivalNs and of live captureTsNs).
[[nodiscard]] std::int64_t monotonicNowNs();

}  // namespace vem
