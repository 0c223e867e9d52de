// V4l2Source: a Video4Linux2 camera (a UVC webcam or a 360 camera in UVC mode, a sensor behind a
// V4L2 capture driver) as vemd's frame source (frames/frame_source.h), `--source v4l2:/dev/videoN`
// or `--source v4l2:NAME` (the card name VIDIOC_QUERYCAP gives).
//
// - Capture: memory-mapped streaming with max(settings.buffers, 4) buffers; next() polls the
//   device together with an eventfd (interrupt()), dequeues the oldest finished buffer, copies or
//   converts it into the frame (v4l2_unpack.h, honouring bytesperline) and queues the buffer back
//   at once, so the driver never runs dry while vemd computes.
// - Format: the native format that gives settings.pixelFormat (v4l2_formats.h), at the size asked
//   for; a driver that adjusts either is refused with a sentence (v4l2_format_choice.h).
// - Exposure, gain, frame rate: v4l2_controls.h (exposure in 100 us units, gain mapped linearly
//   with the control's default as unity). Frames carry the exposure and gain last read back from
//   the camera: V4L2 does not say per frame which setting a frame was taken with, so the few
//   frames after a change may carry the new values early.
// - Time: captureTsNs is the driver's buffer timestamp when it is CLOCK_MONOTONIC
//   (V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC; start or end of exposure as the driver chooses); any other
//   clock is replaced by the arrival time and counted (counters().arrivalStamped). seq follows the
//   driver's sequence, strictly increasing, its gaps kept and counted as lost (frame_sequence.h).
// - Faults: EINTR and EAGAIN are retried within the timeout; no frame within settings.timeoutMs,
//   or interrupt(), is Timeout; ENODEV, EIO or any other device failure closes the device and is
//   NoDevice, and every later next() tries the opener once and, when the camera is back, streams
//   again with the same settings (counted in counters().reopened). A short buffer (bytesused
//   below what the layout needs) or one flagged V4L2_BUF_FLAG_ERROR is BadFrame, counted and
//   skipped (its seq is not reused).
// - Threads: everything on the capture thread except interrupt(), which may come from any thread.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "cameras/v4l2/frame_sequence.h"
#include "cameras/v4l2/v4l2_buffers.h"
#include "cameras/v4l2/v4l2_device.h"
#include "cameras/v4l2/v4l2_formats.h"
#include "cameras/v4l2/v4l2_queries.h"
#include "cameras/v4l2/wake_event.h"
#include "frames/frame_source.h"

namespace vem::cameras {

inline constexpr int kMinimumV4l2Buffers = 4;

struct V4l2Counters {
  std::uint64_t completed = 0;       // frames delivered
  std::uint64_t shortFrames = 0;     // bytesused below the layout's need
  std::uint64_t corruptFrames = 0;   // V4L2_BUF_FLAG_ERROR
  std::uint64_t lost = 0;            // gaps in the driver's sequence
  std::uint64_t reopened = 0;        // times the camera came back after being lost
  std::uint64_t arrivalStamped = 0;  // frames whose driver timestamp was not CLOCK_MONOTONIC
};

class V4l2Source final : public FrameSource {
 public:
  // Opens `target` (a path or card name, as the opener understands it) through `opener`, sets the
  // format, controls and rate of `settings`, and starts streaming. NoDevice with one sentence
  // naming "v4l2:TARGET" when any step fails.
  [[nodiscard]] static std::expected<std::unique_ptr<V4l2Source>, SourceError> open(
      const std::string& target, V4l2Opener opener, const CameraSettings& settings);
  // `pathOrName` as --source gives it, with or without "v4l2:": "/dev/video0" or a card name.
  [[nodiscard]] static std::expected<std::unique_ptr<V4l2Source>, SourceError> open(
      const std::string& pathOrName, const CameraSettings& settings);

  ~V4l2Source() override;

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;
  [[nodiscard]] std::expected<void, std::string> setExposure(double exposureUs,
                                                             double gain) override;

  [[nodiscard]] const V4l2Counters& counters() const;
  // Buffers the driver granted (0 while the camera is lost).
  [[nodiscard]] std::size_t bufferCount() const { return buffers_ ? buffers_->count() : 0; }

 private:
  V4l2Source(std::string target, V4l2Opener opener, const CameraSettings& settings);

  [[nodiscard]] std::expected<void, std::string> connect();
  void disconnect();
  [[nodiscard]] SourceError lostDevice(const std::string& what, int error);
  [[nodiscard]] std::expected<CapturedFrame, SourceError> take(const V4l2Dequeued& buffer);
  [[nodiscard]] SourceError error(SourceErrorCause cause, const std::string& what) const;

  std::string target_;
  std::string spec_;
  V4l2Opener opener_;
  CameraSettings settings_;
  WakeEvent wake_;
  std::unique_ptr<V4l2Device> device_;
  std::optional<V4l2Buffers> buffers_;  // after device_: released before it closes
  V4l2Identity identity_;
  V4l2Layout layout_;
  double nominalRateHz_ = 0.0;
  double exposureUs_ = 1000.0;
  double gain_ = 1.0;
  FrameSequence sequence_;
  V4l2Counters counters_;
  std::vector<std::vector<std::uint16_t>> spareCodes_;
};

}  // namespace vem::cameras
