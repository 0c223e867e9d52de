// FakeLibcameraPort: an in-process camera behind LibcameraCameraPort
// (daemon/cameras/libcamera/libcamera_port.h) that keeps libcamera 0.0.3's semantics, for the
// backend's tests and the camera-path benchmark:
//
// - One camera (FakeLibcameraCamera). acquire() twice, or while "another process" holds it
//   (holdElsewhere), fails with -EBUSY; an unknown id with -ENODEV.
// - validate() adjusts a format the role does not offer to the role's first format, and a size the
//   format does not list to the listed size nearest in area (Adjusted), clamps the buffer count to
//   1..16, fills stride (rows padded to strideAlignBytes) and frame size; a role the camera does
//   not offer is Invalid. configure() takes only a Valid configuration (-EINVAL), on an acquired
//   camera that does not run (-EACCES).
// - start() / queueRequest() / stop(): requests complete in order on the fake's own thread (as on
//   libcamera's), each framePeriodNs after the previous one at the earliest. A buffer already
//   queued is refused with -EINVAL. stop() completes every pending request as cancelled before it
//   returns.
// - Controls: ExposureTime and AnalogueGain are clamped to the sensor's range and take effect
//   controlDelayFrames frames after the request that carried them (the sensor's pipeline delay);
//   each completion's metadata carries what its frame was really taken with.
// - Timestamps: the capture instant on CLOCK_MONOTONIC, or on a simulated CLOCK_BOOTTIME that runs
//   boottimeAheadNs ahead (the time a system spent suspended) when `clock` says Boottime.
// - Faults: skipFrames(n) loses n frames (a gap in the sequence), failFrames(n) completes the next
//   n with FrameError, unplug() fires the disconnect notification on the fake's thread and fails
//   every later call but release() with -ENODEV (pending requests never complete), replug() brings
//   the camera back, unacquired.
//
// Frames come from a generator (fake_frame_generators.h) called on the fake's thread with the
// frame's sequence number, exposure and gain, and are packed into the buffers in libcamera's
// memory layout (libcamera_pixel_layout.h): R8 bytes; R10/R12/R16 little-endian 16-bit words;
// RGB888 as B, G, R bytes; BGR888 as R, G, B.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cameras/libcamera/libcamera_port.h"
#include "frames/raw_frame.h"

namespace vem::cameras::testing {

struct FakeFrameParams {
  std::uint32_t sequence = 0;
  double exposureUs = 1000.0;
  double gain = 1.0;
};

// Fills `frame` (width, height, format and codes sized as configured) for `params`.
using FakeFrameGenerator = std::function<void(const FakeFrameParams& params, vem::RawFrame& frame)>;

struct FakeLibcameraCamera {
  std::string id = "/base/fake/hdr-sensor@10";
  std::string model = "fake-hdr-sensor";
  std::vector<LibcameraStreamFormats> formats;
  std::int32_t minExposureUs = 10;
  std::int32_t maxExposureUs = 200'000;
  float minGain = 1.0f;
  float maxGain = 16.0f;
  std::int32_t defaultExposureUs = 5000;
  float defaultGain = 1.0f;
  int controlDelayFrames = 2;
  bool reportsExposure = true;  // ExposureTime and AnalogueGain in the request metadata
  int strideAlignBytes = 64;
  std::int64_t framePeriodNs = 0;  // 0: as fast as requests come
  LibcameraClock clock = LibcameraClock::Monotonic;
  std::int64_t boottimeAheadNs = 0;
};

// What the fake delivered, frame by frame, for the tests to compare with.
struct FakeFrameRecord {
  std::uint32_t sequence = 0;
  LibcameraFrameStatus status = LibcameraFrameStatus::Success;
  double exposureUs = 0.0;
  double gain = 0.0;
  std::uint64_t timestampNs = 0;        // as reported, on the camera's clock
  std::int64_t monotonicCaptureNs = 0;  // the same instant on CLOCK_MONOTONIC
};

class FakeLibcameraPort final : public LibcameraCameraPort {
 public:
  FakeLibcameraPort(FakeLibcameraCamera camera, FakeFrameGenerator generator);
  ~FakeLibcameraPort() override;
  FakeLibcameraPort(const FakeLibcameraPort&) = delete;
  FakeLibcameraPort& operator=(const FakeLibcameraPort&) = delete;

  std::expected<std::vector<LibcameraCameraInfo>, std::string> listCameras() override;
  int acquire(const std::string& id, LibcameraEvents& events) override;
  LibcameraConfigStatus validate(LibcameraStreamConfig& config) override;
  int configure(LibcameraStreamConfig& config) override;
  std::expected<std::vector<LibcameraMappedBuffer>, int> allocateBuffers() override;
  int start(const LibcameraControls& controls) override;
  int queueRequest(std::uint64_t bufferIndex, const LibcameraControls& controls) override;
  int stop() override;
  void release() override;
  LibcameraClock timestampClock() const override;
  std::int64_t clockNowNs(LibcameraClock clock) const override;

  // Faults and observation (any thread).
  void skipFrames(std::uint32_t count);
  void failFrames(int count);
  void unplug();
  void replug();
  void holdElsewhere(bool held);
  [[nodiscard]] std::vector<FakeFrameRecord> delivered() const;
  [[nodiscard]] std::vector<LibcameraControls> requestControls() const;  // as queued, in order
  [[nodiscard]] bool running() const;
  [[nodiscard]] int acquisitions() const;  // successful acquire() calls

 private:
  struct Pending {
    std::uint64_t bufferIndex = 0;
    LibcameraControls controls;
  };
  struct ControlChange {
    std::uint64_t effectiveFrame = 0;
    std::optional<std::int32_t> exposureUs;
    std::optional<float> gain;
  };

  void run();
  void deliverOne(std::unique_lock<std::mutex>& lock);
  void cancelPending();
  void applyControls(const LibcameraControls& controls, std::uint64_t effectiveFrame);
  void settleControls(std::uint64_t frame);
  [[nodiscard]] bool gone() const { return !plugged_ || stale_; }
  [[nodiscard]] int bytesPerPixelOf(const LibcameraPixelFormat& format) const;

  const FakeLibcameraCamera camera_;
  const FakeFrameGenerator generator_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;     // the fake's thread: work to do
  std::condition_variable settled_;  // stop(): the frame in flight is done
  std::thread thread_;
  bool quit_ = false;
  bool plugged_ = true;
  bool stale_ = false;  // acquired before an unplug: every call but release() fails
  bool acquired_ = false;
  bool heldElsewhere_ = false;
  bool running_ = false;
  bool inFlight_ = false;
  bool disconnectPending_ = false;
  int acquisitions_ = 0;
  LibcameraEvents* events_ = nullptr;
  std::optional<LibcameraStreamConfig> configured_;
  std::vector<std::vector<std::uint8_t>> buffers_;
  std::vector<bool> queued_;
  std::deque<Pending> pending_;
  std::vector<ControlChange> changes_;
  std::int32_t exposureUs_ = 0;
  float gain_ = 1.0f;
  std::uint64_t framesStarted_ = 0;  // frames the sensor began in this session
  std::uint32_t sequence_ = 0;
  std::uint32_t skip_ = 0;
  int fail_ = 0;
  std::int64_t lastFrameNs_ = 0;
  std::vector<FakeFrameRecord> delivered_;
  std::vector<LibcameraControls> requestControls_;
};

// Packs `frame` into libcamera's memory layout for `format` (rows strideBytes apart).
void packLibcameraFrame(const LibcameraPixelFormat& format, int strideBytes,
                        const vem::RawFrame& frame, std::span<std::uint8_t> bytes);

}  // namespace vem::cameras::testing
