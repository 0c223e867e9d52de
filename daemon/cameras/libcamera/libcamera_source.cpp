#include "cameras/libcamera/libcamera_source.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "cameras/libcamera/libcamera_stream_choice.h"
#include "cameras/libcamera/libcamera_system_port.h"

namespace vem::cameras {

namespace {

constexpr std::size_t kMaxSpareBuffers = 8;

bool allDigits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The camera `id` names: its libcamera id, or its index in libcamera's list.
const LibcameraCameraInfo* findCamera(const std::vector<LibcameraCameraInfo>& cameras,
                                      const std::string& id) {
  for (const LibcameraCameraInfo& c : cameras) {
    if (c.id == id) return &c;
  }
  if (allDigits(id) && id.size() < 6) {
    const std::size_t index = std::stoul(id);
    if (index < cameras.size()) return &cameras[index];
  }
  return nullptr;
}

std::string cameraList(const std::vector<LibcameraCameraInfo>& cameras) {
  if (cameras.empty()) return "libcamera lists no camera";
  std::string out = "libcamera lists ";
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    out += fmt::format("{}{} \"{}\"", i == 0 ? "" : ", ", i, cameras[i].id);
  }
  return out;
}

std::string streamText(const LibcameraStreamConfig& c) {
  return fmt::format("{} {}x{} ({})", libcameraFormatName(c.format), c.size.widthPx,
                     c.size.heightPx, libcameraRoleName(c.role));
}

}  // namespace

std::expected<std::unique_ptr<LibcameraSource>, SourceError> LibcameraSource::open(
    std::unique_ptr<LibcameraCameraPort> port, const std::string& id,
    const CameraSettings& settings) {
  const std::string spec = "libcamera:" + id;
  auto cameras = port->listCameras();
  if (!cameras) {
    return std::unexpected(
        SourceError{SourceErrorCause::NoDevice, fmt::format("{}: {}", spec, cameras.error())});
  }
  const LibcameraCameraInfo* camera = findCamera(*cameras, id);
  if (!camera) {
    return std::unexpected(
        SourceError{SourceErrorCause::NoDevice,
                    fmt::format("{}: no libcamera camera has the id or index \"{}\"; {}", spec, id,
                                cameraList(*cameras))});
  }
  auto wanted = chooseLibcameraStream(*camera, settings, spec);
  if (!wanted) return std::unexpected(SourceError{SourceErrorCause::NoDevice, wanted.error()});
  std::unique_ptr<LibcameraSource> source(
      new LibcameraSource(std::move(port), spec, *camera, *wanted, settings));
  if (auto started = source->startCamera(true); !started) {
    return std::unexpected(started.error());
  }
  return source;
}

std::expected<std::unique_ptr<LibcameraSource>, SourceError> LibcameraSource::open(
    const std::string& id, const CameraSettings& settings) {
  auto port = makeLibcameraSystemPort();
  if (!port) {
    return std::unexpected(
        SourceError{SourceErrorCause::NoDevice, fmt::format("libcamera:{}: {}", id, port.error())});
  }
  return open(std::move(*port), id, settings);
}

LibcameraSource::LibcameraSource(std::unique_ptr<LibcameraCameraPort> port, std::string spec,
                                 LibcameraCameraInfo camera, LibcameraStreamConfig wanted,
                                 const CameraSettings& settings)
    : port_(std::move(port)),
      spec_(std::move(spec)),
      camera_(std::move(camera)),
      wanted_(wanted),
      config_(wanted),
      settings_(settings) {
  if (settings.exposureUs || settings.gain) manual_.aeEnable = false;
  if (settings.exposureUs) manual_.exposureTimeUs = std::int32_t(std::lround(*settings.exposureUs));
  if (settings.gain) manual_.analogueGain = float(*settings.gain);
}

LibcameraSource::~LibcameraSource() { closeCamera(); }

SourceError LibcameraSource::failure(SourceErrorCause cause, std::string what) const {
  return SourceError{cause, fmt::format("{}: {}", spec_, what)};
}

LibcameraControls LibcameraSource::startControls() const {
  LibcameraControls controls = manual_;
  if (settings_.frameRateHz && *settings_.frameRateHz > 0.0) {
    const auto periodUs = std::int64_t(std::llround(1e6 / *settings_.frameRateHz));
    controls.frameDurationLimitsUs = std::pair{periodUs, periodUs};
  }
  return controls;
}

std::expected<void, SourceError> LibcameraSource::configureStream(bool first) {
  LibcameraStreamConfig config = wanted_;
  const LibcameraConfigStatus status = port_->validate(config);
  if (status == LibcameraConfigStatus::Invalid) {
    return std::unexpected(failure(SourceErrorCause::NoDevice,
                                   fmt::format("the camera refuses the stream {}; it offers {}",
                                               streamText(wanted_), libcameraOffer(camera_))));
  }
  const bool sizeGiven = settings_.widthPx > 0 && settings_.heightPx > 0;
  const LibcameraStreamConfig& reference = first ? wanted_ : config_;
  if (config.format != wanted_.format || ((sizeGiven || !first) && config.size != reference.size)) {
    return std::unexpected(
        failure(SourceErrorCause::NoDevice,
                fmt::format("the camera cannot deliver {} and offers {} instead; set the [camera] "
                            "pixel format and size to one it offers",
                            streamText(reference), streamText(config))));
  }
  if (const int rc = port_->configure(config); rc != 0) {
    return std::unexpected(failure(
        SourceErrorCause::NoDevice,
        fmt::format("configuring {} failed ({})", streamText(config), libcameraErrorName(rc))));
  }
  config_ = config;
  return {};
}

std::expected<void, SourceError> LibcameraSource::startCamera(bool first) {
  queue_.clear();
  if (const int rc = port_->acquire(camera_.id, queue_); rc != 0) {
    const std::string why =
        rc == -EBUSY    ? "the camera is in use by another program (or another vemd source)"
        : rc == -ENODEV ? "the camera is not connected"
                        : fmt::format("acquiring the camera failed ({})", libcameraErrorName(rc));
    return std::unexpected(failure(SourceErrorCause::NoDevice, why));
  }
  auto fail = [this](SourceError error) {
    port_->release();
    streaming_ = false;
    buffers_.clear();
    return std::unexpected(std::move(error));
  };
  if (auto configured = configureStream(first); !configured) return fail(configured.error());
  auto buffers = port_->allocateBuffers();
  if (!buffers || buffers->empty()) {
    return fail(failure(SourceErrorCause::NoDevice,
                        fmt::format("allocating capture buffers failed ({})",
                                    libcameraErrorName(buffers ? -ENOMEM : buffers.error()))));
  }
  buffers_ = std::move(*buffers);
  asked_.assign(buffers_.size(), LibcameraControls{});
  if (const int rc = port_->start(startControls()); rc != 0) {
    return fail(failure(SourceErrorCause::NoDevice,
                        fmt::format("starting the camera failed ({})", libcameraErrorName(rc))));
  }
  streaming_ = true;
  numbering_.startSession();
  for (std::size_t i = 0; i < buffers_.size(); ++i) {
    if (auto queued = requeue(i); !queued) return fail(queued.error());
  }
  return {};
}

void LibcameraSource::closeCamera() {
  if (!streaming_) return;
  port_->release();
  buffers_.clear();
  streaming_ = false;
}

std::expected<void, SourceError> LibcameraSource::requeue(std::uint64_t bufferIndex) {
  asked_[bufferIndex] = manual_;
  if (const int rc = port_->queueRequest(bufferIndex, manual_); rc != 0) {
    closeCamera();  // a buffer that cannot go back would starve the stream: start afresh
    return std::unexpected(
        failure(SourceErrorCause::NoDevice,
                rc == -ENODEV ? std::string("the camera was removed")
                              : fmt::format("queueing buffer {} failed ({}); restarting the camera",
                                            bufferIndex, libcameraErrorName(rc))));
  }
  return {};
}

SourceError LibcameraSource::badFrame(std::uint64_t bufferIndex, std::string why) {
  bad_.fetch_add(1);
  if (streaming_ && bufferIndex < buffers_.size()) {
    if (auto queued = requeue(bufferIndex); !queued) return queued.error();
  }
  return failure(SourceErrorCause::BadFrame, std::move(why));
}

std::expected<CapturedFrame, SourceError> LibcameraSource::next() {
  if (!streaming_) {
    if (auto started = startCamera(false); !started) return std::unexpected(started.error());
    reopened_.fetch_add(1);
  }
  const auto waited = queue_.waitFor(std::chrono::milliseconds(settings_.timeoutMs));
  switch (waited.wake) {
    case LibcameraCompletionQueue::Wake::Interrupted:
      return std::unexpected(
          failure(SourceErrorCause::Timeout, "interrupted while waiting for the next frame"));
    case LibcameraCompletionQueue::Wake::Timeout:
      return std::unexpected(failure(SourceErrorCause::Timeout,
                                     fmt::format("no frame within {} ms", settings_.timeoutMs)));
    case LibcameraCompletionQueue::Wake::Disconnected:
      closeCamera();
      return std::unexpected(failure(SourceErrorCause::NoDevice, "the camera was removed"));
    case LibcameraCompletionQueue::Wake::Completion: break;
  }
  return take(waited.completion);
}

std::expected<CapturedFrame, SourceError> LibcameraSource::take(const LibcameraCompletion& c) {
  if (!streaming_ || c.bufferIndex >= buffers_.size()) {
    return std::unexpected(badFrame(c.bufferIndex, "a request of a stopped stream came back"));
  }
  if (c.requestCancelled || c.frameStatus == LibcameraFrameStatus::Cancelled) {
    return std::unexpected(
        badFrame(c.bufferIndex, fmt::format("frame {} was cancelled", c.sequence)));
  }
  if (c.frameStatus == LibcameraFrameStatus::Error) {
    return std::unexpected(
        badFrame(c.bufferIndex, fmt::format("frame {} came back with an error", c.sequence)));
  }
  const auto numbered = numbering_.accept(c.sequence);
  if (!numbered) {
    return std::unexpected(
        badFrame(c.bufferIndex, fmt::format("frame {} is out of sequence", c.sequence)));
  }
  CapturedFrame out;
  if (!spareCodes_.empty()) {
    out.frame.codes = std::move(spareCodes_.back());
    spareCodes_.pop_back();
  }
  const LibcameraMappedBuffer& buffer = buffers_[c.bufferIndex];
  std::span<const std::uint8_t> bytes =
      buffer.planes.empty() ? std::span<const std::uint8_t>() : buffer.planes.front();
  bytes = bytes.first(std::min<std::size_t>(bytes.size(), c.bytesUsed));
  if (auto problem = unpackLibcameraFrame(config_.format, config_.size, config_.strideBytes, bytes,
                                          out.frame)) {
    recycle(std::move(out));
    return std::unexpected(
        badFrame(c.bufferIndex, fmt::format("frame {}: {}", c.sequence, *problem)));
  }
  const LibcameraControls asked = asked_[c.bufferIndex];
  if (auto queued = requeue(c.bufferIndex); !queued) return std::unexpected(queued.error());
  if (c.exposureTimeUs)
    out.frame.exposureUs = double(*c.exposureTimeUs);
  else if (asked.exposureTimeUs)
    out.frame.exposureUs = double(*asked.exposureTimeUs);
  if (c.analogueGain)
    out.frame.gain = double(*c.analogueGain);
  else if (asked.analogueGain)
    out.frame.gain = double(*asked.analogueGain);
  const LibcameraClock clock = port_->timestampClock();
  const std::int64_t clockNow = port_->clockNowNs(clock);
  out.arrivalNs = monotonicNowNs();
  out.captureTsNs = monotonicCaptureNs(c.timestampNs, clock, clockNow, out.arrivalNs);
  out.seq = numbered->seq;
  lost_.fetch_add(numbered->lost);
  completed_.fetch_add(1);
  return out;
}

void LibcameraSource::recycle(CapturedFrame&& spent) {
  if (spareCodes_.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    spareCodes_.push_back(std::move(spent.frame.codes));
  }
}

void LibcameraSource::interrupt() { queue_.interrupt(); }

std::expected<void, std::string> LibcameraSource::setExposure(double exposureUs, double gain) {
  if (!std::isfinite(exposureUs) || exposureUs < 1.0 || exposureUs > 2.0e9) {
    return std::unexpected(fmt::format(
        "{}: exposure {} us is out of range (expected 1 us to 2000 s)", spec_, exposureUs));
  }
  if (!std::isfinite(gain) || gain < 1.0) {
    return std::unexpected(fmt::format(
        "{}: gain {} is out of range (expected a linear factor of at least 1)", spec_, gain));
  }
  manual_.aeEnable = false;
  manual_.exposureTimeUs = std::int32_t(std::lround(exposureUs));
  manual_.analogueGain = float(gain);
  return {};
}

SourceDescription LibcameraSource::describe() const {
  SourceDescription d;
  d.spec = spec_;
  d.cameraModel = camera_.model.empty() ? "libcamera camera" : camera_.model;
  d.cameraSerial = camera_.id;
  d.sensorWidthPx = config_.size.widthPx;
  d.sensorHeightPx = config_.size.heightPx;
  if (auto pixel = calibFormatOf(config_.format)) d.pixelFormat = *pixel;
  d.calibrationToml = settings_.calibrationToml;
  d.nominalRateHz = settings_.frameRateHz.value_or(0.0);
  d.liveClock = true;
  d.paced = true;
  return d;
}

LibcameraCounters LibcameraSource::counters() const {
  return {completed_.load(), bad_.load(), lost_.load(), reopened_.load()};
}

}  // namespace vem::cameras
