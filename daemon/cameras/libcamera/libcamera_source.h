// LibcameraSource: a camera libcamera drives (Raspberry Pi CSI cameras, UVC webcams, ISP
// pipelines: docs/cameras.md), as vemd's FrameSource (frames/frame_source.h), `--source
// libcamera:ID`. ID is the camera's libcamera id (`vemd --list-devices`, `cam -l`) or its index in
// that list.
//
// - Stream: libcamera_stream_choice.h picks role, format and size; libcamera_pixel_layout.h widens
//   the frames into RawFrame codes. A camera that offers nothing vemd takes is refused with one
//   sentence naming what it offers.
// - Buffers: settings.buffers requests stay queued with the camera. next() copies a completed
//   frame out of its (mapped, dmabuf) buffer and queues the buffer again at once; recycle() only
//   keeps the RawFrame's storage for later frames.
// - Frames: seq and captureTsNs as libcamera_frame_identity.h says (gaps in the camera's sequence
//   are counted as lost; captureTsNs on CLOCK_MONOTONIC); arrivalNs = monotonicNowNs() when
//   next() hands the frame over; exposureUs and gain from the request's metadata (ExposureTime,
//   AnalogueGain), or when the camera reports none, from the controls that request carried, else
//   RawFrame's defaults (1000 us, 1).
// - Controls: settings' exposure and gain (AeEnable false, ExposureTime, AnalogueGain) and
//   frame rate (FrameDurationLimits) go with start(); setExposure() replaces exposure and gain on
//   every request queued from then on (the camera applies them a few frames late).
// - Errors: next() waits at most settings.timeoutMs (Timeout); interrupt() ends the wait (Timeout);
//   a cancelled, failed, out-of-sequence or short frame is BadFrame (counted bad); an unplugged
//   camera is NoDevice, and every later next() tries once to acquire it again and resume with the
//   same stream and controls (counted reopened).
// Threads: next(), recycle(), setExposure() on the capture thread; interrupt() and counters() from
// any thread; the port's completions arrive on libcamera's thread (libcamera_completion_queue.h).
#pragma once

#include <atomic>
#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "cameras/libcamera/libcamera_completion_queue.h"
#include "cameras/libcamera/libcamera_frame_identity.h"
#include "cameras/libcamera/libcamera_port.h"
#include "frames/frame_source.h"

namespace vem::cameras {

struct LibcameraCounters {
  std::uint64_t completed = 0;  // frames delivered
  std::uint64_t bad = 0;        // cancelled, failed, out-of-sequence or unreadable frames
  std::uint64_t lost = 0;       // gaps in the camera's sequence numbers
  std::uint64_t reopened = 0;   // times the camera was acquired again after it was lost
};

class LibcameraSource final : public FrameSource {
 public:
  // Opens camera `id` through `port` and starts streaming. NoDevice with one sentence when the
  // camera is unknown, busy, or offers nothing that fits `settings`.
  [[nodiscard]] static std::expected<std::unique_ptr<LibcameraSource>, SourceError> open(
      std::unique_ptr<LibcameraCameraPort> port, const std::string& id,
      const CameraSettings& settings);
  // The same through libcamera itself (libcamera_system_port.h).
  [[nodiscard]] static std::expected<std::unique_ptr<LibcameraSource>, SourceError> open(
      const std::string& id, const CameraSettings& settings);

  ~LibcameraSource() override;
  LibcameraSource(const LibcameraSource&) = delete;
  LibcameraSource& operator=(const LibcameraSource&) = delete;

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;
  [[nodiscard]] std::expected<void, std::string> setExposure(double exposureUs,
                                                             double gain) override;

  [[nodiscard]] LibcameraCounters counters() const;
  [[nodiscard]] const LibcameraStreamConfig& streamConfig() const { return config_; }

 private:
  LibcameraSource(std::unique_ptr<LibcameraCameraPort> port, std::string spec,
                  LibcameraCameraInfo camera, LibcameraStreamConfig wanted,
                  const CameraSettings& settings);

  [[nodiscard]] std::expected<void, SourceError> startCamera(bool first);
  [[nodiscard]] std::expected<void, SourceError> configureStream(bool first);
  void closeCamera();
  [[nodiscard]] std::expected<CapturedFrame, SourceError> take(
      const LibcameraCompletion& completion);
  [[nodiscard]] SourceError badFrame(std::uint64_t bufferIndex, std::string why);
  [[nodiscard]] std::expected<void, SourceError> requeue(std::uint64_t bufferIndex);
  [[nodiscard]] LibcameraControls startControls() const;
  [[nodiscard]] SourceError failure(SourceErrorCause cause, std::string what) const;

  // queue_ outlives port_ (members are destroyed in reverse order), so no callback finds it gone.
  LibcameraCompletionQueue queue_;
  std::unique_ptr<LibcameraCameraPort> port_;
  std::string spec_;
  LibcameraCameraInfo camera_;
  LibcameraStreamConfig wanted_;
  LibcameraStreamConfig config_;  // as configured the first time; a reopened camera must match
  CameraSettings settings_;
  LibcameraControls manual_;  // exposure and gain every request carries
  std::vector<LibcameraMappedBuffer> buffers_;
  std::vector<LibcameraControls> asked_;  // per buffer: the controls its request carried
  std::vector<std::vector<std::uint16_t>> spareCodes_;
  LibcameraFrameNumbering numbering_;
  bool streaming_ = false;
  std::atomic<std::uint64_t> completed_{0};
  std::atomic<std::uint64_t> bad_{0};
  std::atomic<std::uint64_t> lost_{0};
  std::atomic<std::uint64_t> reopened_{0};
};

}  // namespace vem::cameras
