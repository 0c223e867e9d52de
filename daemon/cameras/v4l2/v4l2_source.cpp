#include "cameras/v4l2/v4l2_source.h"

#include <algorithm>
#include <cerrno>
#include <utility>

#include <fmt/format.h>

#include "cameras/v4l2/v4l2_controls.h"
#include "cameras/v4l2/v4l2_device_list.h"
#include "cameras/v4l2/v4l2_format_choice.h"
#include "cameras/v4l2/v4l2_unpack.h"

namespace vem::cameras {

namespace {

constexpr std::size_t kMaxSpareBuffers = 8;
constexpr std::string_view kSpecPrefix = "v4l2:";

std::int64_t nsOf(const timeval& t) {
  return std::int64_t(t.tv_sec) * 1'000'000'000LL + std::int64_t(t.tv_usec) * 1'000LL;
}

bool sameLayout(const V4l2Layout& a, const V4l2Layout& b) {
  return a.fourcc == b.fourcc && a.widthPx == b.widthPx && a.heightPx == b.heightPx &&
         a.output == b.output;
}

}  // namespace

std::expected<std::unique_ptr<V4l2Source>, SourceError> V4l2Source::open(
    const std::string& target, V4l2Opener opener, const CameraSettings& settings) {
  std::unique_ptr<V4l2Source> source(new V4l2Source(target, std::move(opener), settings));
  if (auto connected = source->connect(); !connected) {
    return std::unexpected(source->error(SourceErrorCause::NoDevice, connected.error()));
  }
  return source;
}

std::expected<std::unique_ptr<V4l2Source>, SourceError> V4l2Source::open(
    const std::string& pathOrName, const CameraSettings& settings) {
  std::string target = pathOrName;
  if (target.starts_with(kSpecPrefix)) target.erase(0, kSpecPrefix.size());
  return open(target, systemV4l2Opener(), settings);
}

V4l2Source::V4l2Source(std::string target, V4l2Opener opener, const CameraSettings& settings)
    : target_(std::move(target)),
      spec_(std::string(kSpecPrefix) + target_),
      opener_(std::move(opener)),
      settings_(settings) {}

V4l2Source::~V4l2Source() { disconnect(); }

SourceError V4l2Source::error(SourceErrorCause cause, const std::string& what) const {
  return {cause, fmt::format("{}: {}", spec_, what)};
}

std::expected<void, std::string> V4l2Source::connect() {
  auto device = opener_(target_);
  if (!device) {
    return std::unexpected(fmt::format("cannot open the camera ({})", errnoText(device.error())));
  }
  auto identity = queryCaptureIdentity(**device, target_);
  if (!identity) return std::unexpected(identity.error());
  auto layout = setCaptureFormat(**device, settings_);
  if (!layout) return std::unexpected(layout.error());
  if (layout_.widthPx > 0 && !sameLayout(*layout, layout_)) {
    return std::unexpected(fmt::format("the camera came back as {} {}x{}, not {} {}x{}",
                                       fourccName(layout->fourcc), layout->widthPx,
                                       layout->heightPx, fourccName(layout_.fourcc),
                                       layout_.widthPx, layout_.heightPx));
  }
  if (settings_.frameRateHz) {
    auto rate = applyFrameRate(**device, *settings_.frameRateHz);
    if (!rate) return std::unexpected(rate.error());
  }
  nominalRateHz_ = currentFrameRate(**device).value_or(0.0);
  if (settings_.exposureUs) {
    auto applied = applyExposureUs(**device, *settings_.exposureUs);
    if (!applied) return std::unexpected(applied.error());
  }
  if (settings_.gain && (*settings_.gain != 1.0 || queryControl(**device, V4L2_CID_GAIN) ||
                         queryControl(**device, V4L2_CID_ANALOGUE_GAIN))) {
    auto applied = applyGain(**device, *settings_.gain);
    if (!applied) return std::unexpected(applied.error());
  }
  exposureUs_ = currentExposureUs(**device).value_or(settings_.exposureUs.value_or(exposureUs_));
  gain_ = currentGain(**device).value_or(1.0);
  auto buffers = V4l2Buffers::start(**device, std::max(settings_.buffers, kMinimumV4l2Buffers));
  if (!buffers) return std::unexpected(buffers.error());
  device_ = std::move(*device);
  buffers_.emplace(std::move(*buffers));
  identity_ = std::move(*identity);
  layout_ = *layout;
  return {};
}

void V4l2Source::disconnect() {
  buffers_.reset();
  device_.reset();
}

SourceError V4l2Source::lostDevice(const std::string& what, int errorCode) {
  disconnect();
  const bool gone = errorCode == ENODEV || errorCode == ENXIO;
  return error(SourceErrorCause::NoDevice,
               fmt::format("{} ({}: {})", gone ? "the camera is gone" : "the camera failed", what,
                           errnoText(errorCode)));
}

std::expected<CapturedFrame, SourceError> V4l2Source::next() {
  if (!buffers_) {
    if (auto connected = connect(); !connected) {
      return std::unexpected(error(SourceErrorCause::NoDevice, connected.error()));
    }
    ++counters_.reopened;
    sequence_.restart();
  }
  const std::int64_t deadlineNs = monotonicNowNs() + settings_.timeoutMs * 1'000'000LL;
  for (;;) {
    const std::int64_t remainingNs = deadlineNs - monotonicNowNs();
    if (remainingNs <= 0) {
      return std::unexpected(error(SourceErrorCause::Timeout,
                                   fmt::format("no frame within {} ms", settings_.timeoutMs)));
    }
    auto polled = device_->poll(wake_.fd(), int((remainingNs + 999'999) / 1'000'000));
    if (!polled) {
      if (polled.error() == EINTR) continue;
      return std::unexpected(lostDevice("poll", polled.error()));
    }
    if (polled->woken) {
      wake_.consume();
      return std::unexpected(
          error(SourceErrorCause::Timeout, "interrupted while waiting for the next frame"));
    }
    if (!polled->frameReady && !polled->deviceError) continue;
    auto buffer = buffers_->dequeue();
    if (!buffer) {
      const bool retry =
          buffer.error() == EINTR || (buffer.error() == EAGAIN && !polled->deviceError);
      if (retry) continue;
      return std::unexpected(lostDevice("VIDIOC_DQBUF", buffer.error()));
    }
    return take(*buffer);
  }
}

std::expected<CapturedFrame, SourceError> V4l2Source::take(const V4l2Dequeued& buffer) {
  if (buffer.index >= buffers_->count()) return std::unexpected(lostDevice("VIDIOC_DQBUF", EINVAL));
  const std::uint64_t seq = sequence_.next(buffer.sequence);
  counters_.lost = sequence_.lost();
  const std::span<const std::byte> data = buffers_->data(buffer.index);
  const std::size_t used = std::min<std::size_t>(buffer.bytesUsed, data.size());
  const bool corrupt = (buffer.flags & V4L2_BUF_FLAG_ERROR) != 0;
  const bool shortFrame = used < layout_.minimumBytes();
  CapturedFrame out;
  if (!corrupt && !shortFrame) {
    if (!spareCodes_.empty()) {
      out.frame.codes = std::move(spareCodes_.back());
      spareCodes_.pop_back();
    }
    unpackV4l2Frame(data.first(used), layout_, out.frame);
  }
  if (const int requeueError = buffers_->requeue(buffer.index)) {
    // The pixels are already copied: deliver them; the next call reopens the camera.
    if (corrupt || shortFrame) return std::unexpected(lostDevice("VIDIOC_QBUF", requeueError));
    disconnect();
  }
  if (corrupt) {
    ++counters_.corruptFrames;
    return std::unexpected(error(SourceErrorCause::BadFrame,
                                 fmt::format("the driver flagged frame {} as corrupt", seq)));
  }
  if (shortFrame) {
    ++counters_.shortFrames;
    return std::unexpected(
        error(SourceErrorCause::BadFrame,
              fmt::format("frame {} is short: {} of {} bytes", seq, used, layout_.minimumBytes())));
  }
  out.frame.exposureUs = exposureUs_;
  out.frame.gain = gain_;
  out.seq = seq;
  out.arrivalNs = monotonicNowNs();
  const bool monotonic =
      (buffer.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
  out.captureTsNs = monotonic ? nsOf(buffer.timestamp) : out.arrivalNs;
  if (!monotonic) ++counters_.arrivalStamped;
  ++counters_.completed;
  return out;
}

void V4l2Source::recycle(CapturedFrame&& spent) {
  if (spareCodes_.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    spareCodes_.push_back(std::move(spent.frame.codes));
  }
}

void V4l2Source::interrupt() { wake_.signal(); }

std::expected<void, std::string> V4l2Source::setExposure(double exposureUs, double gain) {
  if (!device_) return std::unexpected(spec_ + ": the camera is not connected");
  auto exposure = applyExposureUs(*device_, exposureUs);
  if (!exposure) return std::unexpected(fmt::format("{}: {}", spec_, exposure.error()));
  exposureUs_ = *exposure;
  settings_.exposureUs = exposureUs;
  if (gain != 1.0 || queryControl(*device_, V4L2_CID_GAIN) ||
      queryControl(*device_, V4L2_CID_ANALOGUE_GAIN)) {
    auto applied = applyGain(*device_, gain);
    if (!applied) return std::unexpected(fmt::format("{}: {}", spec_, applied.error()));
    gain_ = *applied;
  }
  settings_.gain = gain;
  return {};
}

const V4l2Counters& V4l2Source::counters() const { return counters_; }

SourceDescription V4l2Source::describe() const {
  SourceDescription d;
  d.spec = spec_;
  d.cameraModel = identity_.card;
  d.cameraSerial = identity_.busInfo;
  d.sensorWidthPx = layout_.widthPx;
  d.sensorHeightPx = layout_.heightPx;
  d.pixelFormat = layout_.output;
  d.calibrationToml = settings_.calibrationToml;
  d.nominalRateHz = nominalRateHz_;
  d.liveClock = true;
  d.paced = true;
  return d;
}

}  // namespace vem::cameras
