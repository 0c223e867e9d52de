#include "cameras/aravis/aravis_source.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "cameras/aravis/aravis_camera_setup.h"
#include "cameras/aravis/aravis_pixel_formats.h"
#include "cameras/aravis/aravis_session.h"
#include "cameras/aravis/frame_id_unwrapper.h"

namespace vem::cameras {

namespace {

constexpr std::size_t kMaxSpareBuffers = 8;
constexpr std::uint64_t kPopAfterDoneUs = 200'000;  // the buffer follows its BUFFER_DONE at once
constexpr std::int64_t kMaxProbeWaitMs = 1000;

// What woke a wait for the next buffer.
enum class Wake { Buffer, Interrupted, ControlLost, Timeout };

// The events of one session, seen by the capture thread: finished buffers, the control channel
// lost (Aravis's threads), interrupt() (any thread).
class WaitState final : public SessionEvents {
 public:
  void bufferDone() override {
    signal([this] { ++pendingBuffers_; });
  }
  void controlLost() override {
    signal([this] { controlLost_ = true; });
  }
  void interrupt() {
    signal([this] { interrupted_ = true; });
  }

  // For a new session: no buffers pending, the control channel fine; a pending interrupt stays.
  void reset() {
    std::lock_guard lock(mutex_);
    pendingBuffers_ = 0;
    controlLost_ = false;
  }

  [[nodiscard]] Wake wait(std::int64_t deadlineNs) {
    const std::chrono::steady_clock::time_point deadline{std::chrono::nanoseconds(deadlineNs)};
    std::unique_lock lock(mutex_);
    cv_.wait_until(lock, deadline,
                   [this] { return interrupted_ || pendingBuffers_ > 0 || controlLost_; });
    if (std::exchange(interrupted_, false)) return Wake::Interrupted;
    if (pendingBuffers_ > 0) {
      --pendingBuffers_;
      return Wake::Buffer;
    }
    return controlLost_ ? Wake::ControlLost : Wake::Timeout;
  }

 private:
  template <typename F>
  void signal(F change) {
    {
      std::lock_guard lock(mutex_);
      change();
    }
    cv_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable cv_;
  std::uint64_t pendingBuffers_ = 0;
  bool controlLost_ = false;
  bool interrupted_ = false;
};

std::int64_t clockNs(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return std::int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

// CLOCK_REALTIME minus CLOCK_MONOTONIC now (the monotonic reads bracket the realtime one).
std::int64_t realtimeMinusMonotonicNs() {
  const std::int64_t before = clockNs(CLOCK_MONOTONIC);
  const std::int64_t real = clockNs(CLOCK_REALTIME);
  const std::int64_t after = clockNs(CLOCK_MONOTONIC);
  return real - (before + (after - before) / 2);
}

const char* bufferStatusName(ArvBufferStatus status) {
  switch (status) {
    case ARV_BUFFER_STATUS_SUCCESS: return "complete";
    case ARV_BUFFER_STATUS_CLEARED: return "cleared";
    case ARV_BUFFER_STATUS_TIMEOUT: return "timed out before all its packets arrived";
    case ARV_BUFFER_STATUS_MISSING_PACKETS: return "with missing packets";
    case ARV_BUFFER_STATUS_WRONG_PACKET_ID: return "with a wrong packet id";
    case ARV_BUFFER_STATUS_SIZE_MISMATCH: return "larger than its buffer";
    case ARV_BUFFER_STATUS_FILLING: return "still filling";
    case ARV_BUFFER_STATUS_ABORTED: return "aborted";
    default: return "in an unknown state";
  }
}

// The exposure and gain frames were taken with, around a change made at changedNs.
struct ExposureHistory {
  ExposureReadback current;
  ExposureReadback previous;
  std::int64_t changedNs = std::numeric_limits<std::int64_t>::min();

  [[nodiscard]] const ExposureReadback& forFrame(std::int64_t captureTsNs) const {
    const auto exposureNs = std::int64_t(current.exposureUs * 1000.0);
    return captureTsNs - exposureNs >= changedNs ? current : previous;
  }
};

}  // namespace

struct AravisSource::Impl {
  std::string id;
  std::string spec;
  CameraSettings settings;
  SourceDescription description;
  WaitState waitState;
  std::unique_ptr<AravisSession> session;
  FrameIdUnwrapper unwrapper;
  ExposureHistory exposure;
  int timeoutsInARow = 0;
  std::vector<std::vector<std::uint16_t>> spareCodes;
  std::atomic<std::uint64_t> completed{0}, incomplete{0}, lost{0}, reopened{0};
  // Sessions of lost cameras, closing on threads of their own (Aravis's teardown waits out its
  // GVCP timeouts); joined before waitState goes.
  struct Closing {
    std::shared_ptr<std::atomic<bool>> done;
    std::jthread thread;
  };
  std::vector<Closing> closing;

  [[nodiscard]] SourceError error(SourceErrorCause cause, const std::string& what) const {
    return SourceError{cause, fmt::format("{}: {}", spec, what)};
  }

  [[nodiscard]] std::expected<void, std::string> openSession() {
    waitState.reset();
    const int probeWaitMs = int(std::min<std::int64_t>(settings.timeoutMs, kMaxProbeWaitMs));
    auto opened = AravisSession::open(id, settings, std::max(1, probeWaitMs), waitState);
    if (!opened) return std::unexpected(opened.error());
    session = std::move(*opened);
    unwrapper.restart();
    timeoutsInARow = 0;
    exposure = ExposureHistory{};
    exposure.current = readExposureGain(session->camera());
    exposure.previous = exposure.current;
    return {};
  }

  SourceError loseCamera(const std::string& why) {
    std::erase_if(closing, [](const Closing& c) { return c.done->load(); });
    session->abandon();
    auto done = std::make_shared<std::atomic<bool>>(false);
    closing.push_back(Closing{done, std::jthread([dead = std::move(session), done]() mutable {
                                dead.reset();
                                done->store(true);
                              })});
    return error(SourceErrorCause::NoDevice, why);
  }

  std::expected<CapturedFrame, SourceError> waitForFrame();
  std::expected<CapturedFrame, SourceError> take(ArvBuffer* buffer);
  SourceError refuse(ArvBuffer* buffer, const std::string& why);
};

std::expected<std::unique_ptr<AravisSource>, SourceError> AravisSource::open(
    const std::string& id, const CameraSettings& settings) {
  auto impl = std::make_unique<Impl>();
  impl->id = id;
  impl->spec = "aravis:" + id;
  impl->settings = settings;
  if (auto opened = impl->openSession(); !opened) {
    return std::unexpected(impl->error(SourceErrorCause::NoDevice, opened.error()));
  }
  const AravisSession& session = *impl->session;
  SourceDescription& d = impl->description;
  d.spec = impl->spec;
  d.cameraModel = session.identity().model;
  d.cameraSerial = session.identity().serial;
  d.sensorWidthPx = session.geometry().widthPx;
  d.sensorHeightPx = session.geometry().heightPx;
  d.pixelFormat = session.geometry().native->format;
  d.calibrationToml = settings.calibrationToml;
  d.nominalRateHz = readFrameRateHz(session.camera());
  d.liveClock = true;
  d.paced = true;
  return std::unique_ptr<AravisSource>(new AravisSource(std::move(impl)));
}

AravisSource::AravisSource(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

AravisSource::~AravisSource() = default;

SourceDescription AravisSource::describe() const { return impl_->description; }

std::expected<CapturedFrame, SourceError> AravisSource::next() {
  Impl& s = *impl_;
  if (!s.session) {
    if (auto opened = s.openSession(); !opened) {
      return std::unexpected(
          s.error(SourceErrorCause::NoDevice, "the camera is still gone (" + opened.error() + ")"));
    }
    s.reopened.fetch_add(1);
  }
  return s.waitForFrame();
}

std::expected<CapturedFrame, SourceError> AravisSource::Impl::waitForFrame() {
  const std::int64_t deadline = monotonicNowNs() + settings.timeoutMs * 1'000'000;
  for (;;) {
    switch (waitState.wait(deadline)) {
      case Wake::Interrupted:
        return std::unexpected(
            error(SourceErrorCause::Timeout, "interrupted while waiting for the next frame"));
      case Wake::ControlLost:
        return std::unexpected(loseCamera("the camera's control channel was lost"));
      case Wake::Timeout:
        if (++timeoutsInARow >= kTimeoutsBeforeLost) {
          return std::unexpected(loseCamera(
              fmt::format("no frame for {} waits of {} ms in a row: the camera is taken as lost",
                          timeoutsInARow, settings.timeoutMs)));
        }
        return std::unexpected(
            error(SourceErrorCause::Timeout, fmt::format("no frame in {} ms", settings.timeoutMs)));
      case Wake::Buffer:
        if (ArvBuffer* buffer = session->pop(kPopAfterDoneUs)) {
          timeoutsInARow = 0;
          return take(buffer);
        }
        break;
    }
  }
}

SourceError AravisSource::Impl::refuse(ArvBuffer* buffer, const std::string& why) {
  const std::uint64_t frameId = arv_buffer_get_frame_id(buffer);
  if (frameId != 0) lost.fetch_add(unwrapper.next(frameId).skipped);
  session->push(buffer);
  incomplete.fetch_add(1);
  return error(SourceErrorCause::BadFrame, fmt::format("frame {} {}", frameId, why));
}

std::expected<CapturedFrame, SourceError> AravisSource::Impl::take(ArvBuffer* buffer) {
  const ArvBufferStatus status = arv_buffer_get_status(buffer);
  if (status != ARV_BUFFER_STATUS_SUCCESS) {
    return std::unexpected(refuse(buffer, fmt::format("came back {}", bufferStatusName(status))));
  }
  const CameraGeometry& geometry = session->geometry();
  const NativePixelFormat* native = nativeFormatByCode(arv_buffer_get_image_pixel_format(buffer));
  const int width = arv_buffer_get_image_width(buffer);
  const int height = arv_buffer_get_image_height(buffer);
  if (native == nullptr || native->format != geometry.native->format || width != geometry.widthPx ||
      height != geometry.heightPx) {
    return std::unexpected(refuse(
        buffer, fmt::format("came as {}x{} pixel format 0x{:08x}, not {}x{} {}", width, height,
                            arv_buffer_get_image_pixel_format(buffer), geometry.widthPx,
                            geometry.heightPx, geometry.native->genicamName)));
  }
  CapturedFrame out;
  if (!spareCodes.empty()) {
    out.frame.codes = std::move(spareCodes.back());
    spareCodes.pop_back();
  }
  std::size_t size = 0;
  const auto* data = static_cast<const std::uint8_t*>(arv_buffer_get_image_data(buffer, &size));
  if (data == nullptr || !decodePixels(*native, {data, size}, width, height, out.frame.codes)) {
    return std::unexpected(refuse(buffer, fmt::format("holds {} bytes, too few for {}x{} {}", size,
                                                      width, height, native->genicamName)));
  }
  const std::uint64_t frameId = arv_buffer_get_frame_id(buffer);
  const auto systemTsNs = std::int64_t(arv_buffer_get_system_timestamp(buffer));
  session->push(buffer);

  const FrameIdUnwrapper::Step step = unwrapper.next(frameId);
  lost.fetch_add(step.skipped);
  completed.fetch_add(1);
  out.arrivalNs = monotonicNowNs();
  out.captureTsNs = systemTsNs - realtimeMinusMonotonicNs();
  out.seq = step.seq;
  out.frame.width = width;
  out.frame.height = height;
  out.frame.format = native->format;
  if (exposure.current.automatic) exposure.current = readExposureGain(session->camera());
  const ExposureReadback& inForce = exposure.forFrame(out.captureTsNs);
  out.frame.exposureUs = inForce.exposureUs;
  out.frame.gain = inForce.gain;
  return out;
}

void AravisSource::recycle(CapturedFrame&& spent) {
  if (impl_->spareCodes.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    impl_->spareCodes.push_back(std::move(spent.frame.codes));
  }
}

void AravisSource::interrupt() { impl_->waitState.interrupt(); }

std::expected<void, std::string> AravisSource::setExposure(double exposureUs, double gain) {
  Impl& s = *impl_;
  if (!s.session) return std::unexpected(s.spec + ": the camera is not open (it was lost)");
  if (auto applied = applyExposureGain(s.session->camera(), exposureUs, gain); !applied) {
    return std::unexpected(fmt::format("{}: {}", s.spec, applied.error()));
  }
  s.settings.exposureUs = exposureUs;  // a reopen keeps them
  s.settings.gain = gain;
  s.exposure.previous = s.exposure.current;
  s.exposure.current = readExposureGain(s.session->camera());
  s.exposure.changedNs = monotonicNowNs();
  return {};
}

AravisCounters AravisSource::counters() const {
  return AravisCounters{impl_->completed.load(), impl_->incomplete.load(), impl_->lost.load(),
                        impl_->reopened.load()};
}

}  // namespace vem::cameras
