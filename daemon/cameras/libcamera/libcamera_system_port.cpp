#include "cameras/libcamera/libcamera_system_port.h"

#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <map>
#include <mutex>

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>
#include <libcamera/control_ids.h>
#include <libcamera/framebuffer_allocator.h>
#include <libcamera/logging.h>
#include <libcamera/property_ids.h>
#include <libcamera/request.h>
#include <libcamera/stream.h>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

// libcamera logs on stderr by itself, each line coloured with ANSI escapes by default, also into a
// pipe or the journal, and says INFO banners ("libcamera v0.0.3") to anyone listing devices. Once,
// before the first CameraManager (libcamera 0.0.3 reads LIBCAMERA_LOG_LEVELS when its logger is
// first used, which this is): its warnings and errors only, and colour only on a terminal; a
// user's own LIBCAMERA_LOG_LEVELS or LIBCAMERA_LOG_NO_COLOR stands.
void setUpLibcameraLogging() {
  static std::once_flag once;
  std::call_once(once, [] {
    ::setenv("LIBCAMERA_LOG_LEVELS", "*:WARN", /*overwrite=*/0);
    const bool colour =
        ::isatty(STDERR_FILENO) == 1 && std::getenv("LIBCAMERA_LOG_NO_COLOR") == nullptr;
    libcamera::logSetStream(&std::cerr, colour);
  });
}

// The process's one CameraManager (libcamera aborts on a second), started while any port lives.
std::expected<std::shared_ptr<libcamera::CameraManager>, std::string> sharedCameraManager() {
  static std::mutex mutex;
  static std::weak_ptr<libcamera::CameraManager> shared;
  std::lock_guard lock(mutex);
  if (auto manager = shared.lock()) return manager;
  setUpLibcameraLogging();
  // ~CameraManager() stops it.
  auto manager = std::make_shared<libcamera::CameraManager>();
  if (const int rc = manager->start(); rc != 0) {
    return std::unexpected(
        fmt::format("libcamera's camera manager did not start ({})", libcameraErrorName(rc)));
  }
  shared = manager;
  return manager;
}

libcamera::StreamRole roleOf(LibcameraRole role) {
  switch (role) {
    case LibcameraRole::Raw: return libcamera::StreamRole::Raw;
    case LibcameraRole::VideoRecording: return libcamera::StreamRole::VideoRecording;
    case LibcameraRole::Viewfinder: return libcamera::StreamRole::Viewfinder;
  }
  return libcamera::StreamRole::Raw;
}

// Sets the controls the camera supports (`supported`); the others are left out, as libcamera
// would refuse them.
void setControls(libcamera::ControlList& list, const libcamera::ControlInfoMap& supported,
                 const LibcameraControls& c) {
  namespace lc = libcamera::controls;
  auto has = [&](const libcamera::ControlId& id) { return supported.count(id.id()) > 0; };
  if (c.aeEnable && has(lc::AeEnable)) list.set(lc::AeEnable, *c.aeEnable);
  if (c.exposureTimeUs && has(lc::ExposureTime)) list.set(lc::ExposureTime, *c.exposureTimeUs);
  if (c.analogueGain && has(lc::AnalogueGain)) list.set(lc::AnalogueGain, *c.analogueGain);
  if (c.frameDurationLimitsUs && has(lc::FrameDurationLimits)) {
    const std::int64_t limits[2] = {c.frameDurationLimitsUs->first,
                                    c.frameDurationLimitsUs->second};
    list.set(lc::FrameDurationLimits, libcamera::Span<const std::int64_t, 2>(limits));
  }
}

// One dmabuf mapped read-only, unmapped on destruction.
class MappedDmabuf {
 public:
  MappedDmabuf(void* address, std::size_t length) : address_(address), length_(length) {}
  ~MappedDmabuf() { munmap(address_, length_); }
  MappedDmabuf(const MappedDmabuf&) = delete;
  MappedDmabuf& operator=(const MappedDmabuf&) = delete;
  [[nodiscard]] const std::uint8_t* bytes() const {
    return static_cast<const std::uint8_t*>(address_);
  }
  [[nodiscard]] std::size_t length() const { return length_; }

 private:
  void* address_;
  std::size_t length_;
};

class SystemPort final : public LibcameraCameraPort {
 public:
  explicit SystemPort(std::shared_ptr<libcamera::CameraManager> manager)
      : manager_(std::move(manager)) {}
  ~SystemPort() override { release(); }

  std::expected<std::vector<LibcameraCameraInfo>, std::string> listCameras() override {
    std::vector<LibcameraCameraInfo> out;
    for (const std::shared_ptr<libcamera::Camera>& camera : manager_->cameras()) {
      out.push_back(describe(*camera));
    }
    return out;
  }

  int acquire(const std::string& id, LibcameraEvents& events) override {
    if (camera_) return -EBUSY;
    std::shared_ptr<libcamera::Camera> camera = manager_->get(id);
    if (!camera) return -ENODEV;
    if (const int rc = camera->acquire(); rc != 0) return rc;
    camera_ = std::move(camera);
    {
      std::lock_guard lock(mutex_);
      events_ = &events;
    }
    camera_->requestCompleted.connect(this, &SystemPort::onRequestCompleted);
    camera_->disconnected.connect(this, &SystemPort::onDisconnected);
    return 0;
  }

  LibcameraConfigStatus validate(LibcameraStreamConfig& config) override {
    if (!camera_) return LibcameraConfigStatus::Invalid;
    configuration_ = camera_->generateConfiguration({roleOf(config.role)});
    if (!configuration_ || configuration_->empty()) return LibcameraConfigStatus::Invalid;
    libcamera::StreamConfiguration& stream = configuration_->at(0);
    stream.pixelFormat = libcamera::PixelFormat(config.format.fourcc, config.format.modifier);
    stream.size = libcamera::Size(unsigned(config.size.widthPx), unsigned(config.size.heightPx));
    stream.bufferCount = unsigned(config.bufferCount);
    const auto status = configuration_->validate();
    config.format = {stream.pixelFormat.fourcc(), stream.pixelFormat.modifier()};
    config.size = {int(stream.size.width), int(stream.size.height)};
    config.bufferCount = int(stream.bufferCount);
    config.strideBytes = int(stream.stride);
    config.frameSizeBytes = int(stream.frameSize);
    switch (status) {
      case libcamera::CameraConfiguration::Valid: return LibcameraConfigStatus::Valid;
      case libcamera::CameraConfiguration::Adjusted: return LibcameraConfigStatus::Adjusted;
      case libcamera::CameraConfiguration::Invalid: break;
    }
    return LibcameraConfigStatus::Invalid;
  }

  int configure(LibcameraStreamConfig& config) override {
    if (!camera_) return -ENODEV;
    if (validate(config) != LibcameraConfigStatus::Valid) return -EINVAL;
    if (const int rc = camera_->configure(configuration_.get()); rc != 0) return rc;
    const libcamera::StreamConfiguration& stream = configuration_->at(0);
    stream_ = stream.stream();
    config.strideBytes = int(stream.stride);
    config.frameSizeBytes = int(stream.frameSize);
    return 0;
  }

  std::expected<std::vector<LibcameraMappedBuffer>, int> allocateBuffers() override {
    if (!camera_ || !stream_) return std::unexpected(-ENODEV);
    freeBuffers();
    allocator_ = std::make_unique<libcamera::FrameBufferAllocator>(camera_);
    if (const int rc = allocator_->allocate(stream_); rc < 0) return std::unexpected(rc);
    std::vector<LibcameraMappedBuffer> out;
    const auto& buffers = allocator_->buffers(stream_);
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      auto mapped = map(*buffers[i]);
      if (!mapped) return std::unexpected(mapped.error());
      std::unique_ptr<libcamera::Request> request = camera_->createRequest(i);
      if (!request) return std::unexpected(-ENOMEM);
      if (const int rc = request->addBuffer(stream_, buffers[i].get()); rc != 0) {
        return std::unexpected(rc);
      }
      requests_.push_back(std::move(request));
      out.push_back(std::move(*mapped));
    }
    std::lock_guard lock(mutex_);
    queued_.assign(requests_.size(), false);
    return out;
  }

  int start(const LibcameraControls& controls) override {
    if (!camera_) return -ENODEV;
    libcamera::ControlList list(camera_->controls());
    setControls(list, camera_->controls(), controls);
    const int rc = camera_->start(&list);
    running_ = rc == 0;
    return rc;
  }

  int queueRequest(std::uint64_t bufferIndex, const LibcameraControls& controls) override {
    if (!camera_) return -ENODEV;
    {
      std::lock_guard lock(mutex_);
      if (bufferIndex >= queued_.size() || queued_[bufferIndex]) return -EINVAL;
      queued_[bufferIndex] = true;
    }
    libcamera::Request& request = *requests_[bufferIndex];
    request.reuse(libcamera::Request::ReuseBuffers);
    setControls(request.controls(), camera_->controls(), controls);
    const int rc = camera_->queueRequest(&request);
    if (rc != 0) {
      std::lock_guard lock(mutex_);
      queued_[bufferIndex] = false;
    }
    return rc;
  }

  int stop() override {
    if (!camera_) return -ENODEV;
    const int rc = running_ ? camera_->stop() : 0;
    running_ = false;
    return rc;
  }

  void release() override {
    if (!camera_) return;
    (void)stop();  // -ENODEV after an unplug: nothing more will complete
    camera_->requestCompleted.disconnect(this);
    camera_->disconnected.disconnect(this);
    {
      std::lock_guard lock(mutex_);
      events_ = nullptr;
    }
    freeBuffers();
    configuration_.reset();
    stream_ = nullptr;
    camera_->release();
    camera_.reset();
  }

  LibcameraClock timestampClock() const override { return LibcameraClock::Monotonic; }

  std::int64_t clockNowNs(LibcameraClock clock) const override {
    timespec ts{};
    clock_gettime(clock == LibcameraClock::Boottime ? CLOCK_BOOTTIME : CLOCK_MONOTONIC, &ts);
    return std::int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
  }

 private:
  static LibcameraCameraInfo describe(libcamera::Camera& camera) {
    LibcameraCameraInfo info;
    info.id = camera.id();
    info.model = camera.properties().get(libcamera::properties::Model).value_or("");
    for (LibcameraRole role :
         {LibcameraRole::Raw, LibcameraRole::VideoRecording, LibcameraRole::Viewfinder}) {
      std::unique_ptr<libcamera::CameraConfiguration> config =
          camera.generateConfiguration({roleOf(role)});
      if (!config || config->empty()) continue;
      const libcamera::StreamFormats& formats = config->at(0).formats();
      for (const libcamera::PixelFormat& pf : formats.pixelformats()) {
        LibcameraStreamFormats entry{role, {pf.fourcc(), pf.modifier()}, {}};
        for (const libcamera::Size& s : formats.sizes(pf)) {
          entry.sizes.push_back({int(s.width), int(s.height)});
        }
        if (entry.sizes.empty()) {
          const libcamera::SizeRange range = formats.range(pf);
          entry.sizes.push_back({int(range.max.width), int(range.max.height)});
        }
        info.formats.push_back(std::move(entry));
      }
    }
    return info;
  }

  std::expected<LibcameraMappedBuffer, int> map(const libcamera::FrameBuffer& buffer) {
    LibcameraMappedBuffer out;
    for (const libcamera::FrameBuffer::Plane& plane : buffer.planes()) {
      const int fd = plane.fd.get();
      if (!mappings_.contains(fd)) {
        const off_t length = lseek(fd, 0, SEEK_END);
        if (length <= 0) return std::unexpected(-errno);
        void* address = mmap(nullptr, std::size_t(length), PROT_READ, MAP_SHARED, fd, 0);
        if (address == MAP_FAILED) return std::unexpected(-errno);
        mappings_.emplace(fd, std::make_unique<MappedDmabuf>(address, std::size_t(length)));
      }
      const MappedDmabuf& mapped = *mappings_.at(fd);
      if (std::size_t(plane.offset) + plane.length > mapped.length())
        return std::unexpected(-ERANGE);
      out.planes.emplace_back(mapped.bytes() + plane.offset, plane.length);
    }
    return out;
  }

  void freeBuffers() {
    requests_.clear();
    mappings_.clear();
    if (allocator_ && stream_) allocator_->free(stream_);
    allocator_.reset();
    std::lock_guard lock(mutex_);
    queued_.clear();
  }

  // libcamera's thread.
  void onRequestCompleted(libcamera::Request* request) {
    LibcameraCompletion c;
    c.bufferIndex = request->cookie();
    c.requestCancelled = request->status() == libcamera::Request::RequestCancelled;
    if (!request->buffers().empty()) {
      const libcamera::FrameMetadata& meta = request->buffers().begin()->second->metadata();
      c.frameStatus =
          meta.status == libcamera::FrameMetadata::FrameSuccess ? LibcameraFrameStatus::Success
          : meta.status == libcamera::FrameMetadata::FrameError ? LibcameraFrameStatus::Error
                                                                : LibcameraFrameStatus::Cancelled;
      c.sequence = meta.sequence;
      c.timestampNs = meta.timestamp;
      for (const libcamera::FrameMetadata::Plane& p : meta.planes()) c.bytesUsed += p.bytesused;
    }
    c.exposureTimeUs = request->metadata().get(libcamera::controls::ExposureTime);
    c.analogueGain = request->metadata().get(libcamera::controls::AnalogueGain);
    std::lock_guard lock(mutex_);
    if (c.bufferIndex < queued_.size()) queued_[c.bufferIndex] = false;
    if (events_) events_->requestCompleted(c);
  }

  void onDisconnected() {
    std::lock_guard lock(mutex_);
    if (events_) events_->disconnected();
  }

  std::shared_ptr<libcamera::CameraManager> manager_;
  std::shared_ptr<libcamera::Camera> camera_;
  std::unique_ptr<libcamera::CameraConfiguration> configuration_;
  libcamera::Stream* stream_ = nullptr;
  std::unique_ptr<libcamera::FrameBufferAllocator> allocator_;
  std::map<int, std::unique_ptr<MappedDmabuf>> mappings_;
  std::vector<std::unique_ptr<libcamera::Request>> requests_;
  bool running_ = false;
  std::mutex mutex_;  // events_ and queued_, shared with libcamera's thread
  LibcameraEvents* events_ = nullptr;
  std::vector<bool> queued_;
};

}  // namespace

std::expected<std::unique_ptr<LibcameraCameraPort>, std::string> makeLibcameraSystemPort() {
  auto manager = sharedCameraManager();
  if (!manager) return std::unexpected(manager.error());
  return std::make_unique<SystemPort>(std::move(*manager));
}

}  // namespace vem::cameras
