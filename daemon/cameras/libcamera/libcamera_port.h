// LibcameraCameraPort: the thin interface between vemd's libcamera backend (libcamera_source.h) and
// libcamera's C++ API (0.0.3, Debian 12), so the backend is tested against an in-process fake
// (tests/cameras/libcamera/fake_libcamera_port.h) and runs on hardware through
// LibcameraSystemPort (libcamera_system_port.h). The calls keep libcamera's meaning:
//
// - One camera per port at a time: acquire(id) takes it for this process (-ENODEV when no camera
//   has that id, -EBUSY when it is acquired already, here or by another process) and subscribes
//   `events`; release() stops it if it runs, frees its buffers and gives it back. release() is
//   always allowed, even after the camera was unplugged.
// - validate() adjusts a stream configuration the way CameraConfiguration::validate() does: Valid,
//   Adjusted (fields changed to what the camera can do: read them back) or Invalid. configure()
//   accepts only a configuration that validates as Valid, and fills in the stride and frame size.
// - allocateBuffers() allocates config.bufferCount buffers (FrameBufferAllocator) and maps their
//   dmabuf planes read-only; buffer i's bytes stay valid until release(). Buffer i is queued with
//   queueRequest(i, controls); a buffer already queued is refused with -EINVAL.
// - start()/stop(): stop() completes every pending request as cancelled before it returns.
// - Completions and the disconnect notification arrive on the port's own thread (libcamera's),
//   through LibcameraEvents; the receiver hands them over to its own threads.
// - Errors are negative errno values (0 = success), as libcamera returns them; every call on an
//   unplugged camera but release() fails with -ENODEV.
//
// Units: exposure in microseconds (controls::ExposureTime), gain linear (controls::AnalogueGain),
// frame durations in microseconds (controls::FrameDurationLimits), timestamps in nanoseconds on
// the clock timestampClock() names (FrameMetadata::timestamp: the V4L2 buffer timestamp, which the
// kernel takes on CLOCK_MONOTONIC).
#pragma once

#include <cstdint>
#include <expected>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace vem::cameras {

enum class LibcameraRole { Raw, VideoRecording, Viewfinder };

// libcamera::PixelFormat: a DRM fourcc and a modifier (0 = linear; packed CSI-2 formats have one).
struct LibcameraPixelFormat {
  std::uint32_t fourcc = 0;
  std::uint64_t modifier = 0;
  friend bool operator==(const LibcameraPixelFormat&, const LibcameraPixelFormat&) = default;
};

struct LibcameraSize {
  int widthPx = 0;
  int heightPx = 0;
  friend bool operator==(const LibcameraSize&, const LibcameraSize&) = default;
};

// What a camera offers for one role and pixel format (StreamFormats): discrete sizes, or when
// the format takes a continuous range, the largest size of that range.
struct LibcameraStreamFormats {
  LibcameraRole role = LibcameraRole::Raw;
  LibcameraPixelFormat format;
  std::vector<LibcameraSize> sizes;
};

struct LibcameraCameraInfo {
  std::string id;     // Camera::id(), what acquire() takes
  std::string model;  // properties::Model, "" when the camera has none
  std::vector<LibcameraStreamFormats> formats;
};

enum class LibcameraConfigStatus { Valid, Adjusted, Invalid };

// One stream (StreamConfiguration). stride and frame size are outputs of validate()/configure().
struct LibcameraStreamConfig {
  LibcameraRole role = LibcameraRole::Raw;
  LibcameraPixelFormat format;
  LibcameraSize size;
  int bufferCount = 4;
  int strideBytes = 0;
  int frameSizeBytes = 0;
  friend bool operator==(const LibcameraStreamConfig&, const LibcameraStreamConfig&) = default;
};

// Controls set on start() or on one request; nullopt leaves a control out of the list.
struct LibcameraControls {
  std::optional<bool> aeEnable;
  std::optional<std::int32_t> exposureTimeUs;
  std::optional<float> analogueGain;
  std::optional<std::pair<std::int64_t, std::int64_t>> frameDurationLimitsUs;  // min, max
  [[nodiscard]] bool empty() const {
    return !aeEnable && !exposureTimeUs && !analogueGain && !frameDurationLimitsUs;
  }
  friend bool operator==(const LibcameraControls&, const LibcameraControls&) = default;
};

enum class LibcameraClock { Monotonic, Boottime };

enum class LibcameraFrameStatus { Success, Error, Cancelled };  // FrameMetadata::Status

// One completed request, copied out of libcamera's objects on its thread.
struct LibcameraCompletion {
  std::uint64_t bufferIndex = 0;  // the request's cookie: which buffer it carried
  bool requestCancelled = false;  // Request::RequestCancelled
  LibcameraFrameStatus frameStatus = LibcameraFrameStatus::Success;
  std::uint32_t sequence = 0;                  // FrameMetadata::sequence (wraps at 2^32)
  std::uint64_t timestampNs = 0;               // FrameMetadata::timestamp, on timestampClock()
  std::uint64_t bytesUsed = 0;                 // over all planes
  std::optional<std::int32_t> exposureTimeUs;  // request metadata: what the frame was taken with
  std::optional<float> analogueGain;
};

// Where a port delivers what happens on its thread. Implementations must be thread-safe.
class LibcameraEvents {
 public:
  virtual ~LibcameraEvents() = default;
  virtual void requestCompleted(const LibcameraCompletion& completion) = 0;
  virtual void disconnected() = 0;
};

// One mapped buffer: its planes' bytes, read-only.
struct LibcameraMappedBuffer {
  std::vector<std::span<const std::uint8_t>> planes;
};

class LibcameraCameraPort {
 public:
  virtual ~LibcameraCameraPort() = default;

  [[nodiscard]] virtual std::expected<std::vector<LibcameraCameraInfo>, std::string>
  listCameras() = 0;

  // `events` must outlive the acquisition (until release() returns).
  [[nodiscard]] virtual int acquire(const std::string& id, LibcameraEvents& events) = 0;
  [[nodiscard]] virtual LibcameraConfigStatus validate(LibcameraStreamConfig& config) = 0;
  [[nodiscard]] virtual int configure(LibcameraStreamConfig& config) = 0;
  [[nodiscard]] virtual std::expected<std::vector<LibcameraMappedBuffer>, int>
  allocateBuffers() = 0;
  [[nodiscard]] virtual int start(const LibcameraControls& controls) = 0;
  [[nodiscard]] virtual int queueRequest(std::uint64_t bufferIndex,
                                         const LibcameraControls& controls) = 0;
  virtual int stop() = 0;
  virtual void release() = 0;

  [[nodiscard]] virtual LibcameraClock timestampClock() const = 0;
  [[nodiscard]] virtual std::int64_t clockNowNs(LibcameraClock clock) const = 0;
};

[[nodiscard]] const char* libcameraRoleName(LibcameraRole role);  // "Raw", "VideoRecording", ...
// "R16", "RGB888", "R10_CSI2P", or the fourcc's four characters for one vemd does not name.
[[nodiscard]] std::string libcameraFormatName(const LibcameraPixelFormat& format);
// "No such device" for -ENODEV (strerror of the positive value).
[[nodiscard]] std::string libcameraErrorName(int negativeErrno);

}  // namespace vem::cameras
