#include "fake_libcamera_port.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>

#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "frames/frame_source.h"

namespace vem::cameras::testing {

namespace {

std::int64_t areaOf(const LibcameraSize& s) { return std::int64_t(s.widthPx) * s.heightPx; }

}  // namespace

void packLibcameraFrame(const LibcameraPixelFormat& format, int strideBytes,
                        const vem::RawFrame& frame, std::span<std::uint8_t> bytes) {
  const int w = frame.width;
  for (int v = 0; v < frame.height; ++v) {
    std::uint8_t* row = bytes.data() + std::size_t(v) * std::size_t(strideBytes);
    for (int u = 0; u < w; ++u) {
      if (format == kLibcameraR8) {
        row[u] = std::uint8_t(frame.at(u, v));
      } else if (format == kLibcameraRGB888) {  // in memory B, G, R
        for (int c = 0; c < 3; ++c) row[3 * u + c] = std::uint8_t(frame.at(u, v, 2 - c));
      } else if (format == kLibcameraBGR888) {  // in memory R, G, B
        for (int c = 0; c < 3; ++c) row[3 * u + c] = std::uint8_t(frame.at(u, v, c));
      } else {  // R10, R12, R16: little-endian 16-bit words
        const std::uint16_t code = frame.at(u, v);
        row[2 * u] = std::uint8_t(code & 0xffu);
        row[2 * u + 1] = std::uint8_t(code >> 8);
      }
    }
  }
}

FakeLibcameraPort::FakeLibcameraPort(FakeLibcameraCamera camera, FakeFrameGenerator generator)
    : camera_(std::move(camera)), generator_(std::move(generator)) {
  thread_ = std::thread([this] { run(); });  // after every member is initialised
}

FakeLibcameraPort::~FakeLibcameraPort() {
  release();
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::expected<std::vector<LibcameraCameraInfo>, std::string> FakeLibcameraPort::listCameras() {
  std::lock_guard lock(mutex_);
  if (!plugged_) return std::vector<LibcameraCameraInfo>{};
  return std::vector<LibcameraCameraInfo>{{camera_.id, camera_.model, camera_.formats}};
}

int FakeLibcameraPort::acquire(const std::string& id, LibcameraEvents& events) {
  std::lock_guard lock(mutex_);
  if (!plugged_ || id != camera_.id) return -ENODEV;
  if (acquired_ || heldElsewhere_) return -EBUSY;
  acquired_ = true;
  events_ = &events;
  ++acquisitions_;
  return 0;
}

int FakeLibcameraPort::bytesPerPixelOf(const LibcameraPixelFormat& format) const {
  const int bytes = libcameraBytesPerPixel(format);
  return bytes > 0 ? bytes : 2;  // YUYV and the like
}

LibcameraConfigStatus FakeLibcameraPort::validate(LibcameraStreamConfig& config) {
  std::lock_guard lock(mutex_);
  if (gone()) return LibcameraConfigStatus::Invalid;
  const LibcameraStreamFormats* entry = nullptr;
  const LibcameraStreamFormats* first = nullptr;
  for (const LibcameraStreamFormats& f : camera_.formats) {
    if (f.role != config.role) continue;
    if (!first) first = &f;
    if (f.format == config.format) entry = &f;
  }
  if (!first) return LibcameraConfigStatus::Invalid;
  bool adjusted = false;
  if (!entry) {
    entry = first;
    config.format = first->format;
    adjusted = true;
  }
  if (std::find(entry->sizes.begin(), entry->sizes.end(), config.size) == entry->sizes.end()) {
    const LibcameraSize wanted = config.size;
    config.size = *std::min_element(entry->sizes.begin(), entry->sizes.end(),
                                    [&](const LibcameraSize& a, const LibcameraSize& b) {
                                      return std::llabs(areaOf(a) - areaOf(wanted)) <
                                             std::llabs(areaOf(b) - areaOf(wanted));
                                    });
    adjusted = true;
  }
  const int count = std::clamp(config.bufferCount, 1, 16);
  adjusted = adjusted || count != config.bufferCount;
  config.bufferCount = count;
  const int align = camera_.strideAlignBytes;
  const int row = config.size.widthPx * bytesPerPixelOf(config.format);
  config.strideBytes = (row + align - 1) / align * align;
  config.frameSizeBytes = config.strideBytes * config.size.heightPx;
  return adjusted ? LibcameraConfigStatus::Adjusted : LibcameraConfigStatus::Valid;
}

int FakeLibcameraPort::configure(LibcameraStreamConfig& config) {
  LibcameraStreamConfig checked = config;
  if (validate(checked) != LibcameraConfigStatus::Valid) {
    std::lock_guard lock(mutex_);
    return gone() ? -ENODEV : -EINVAL;
  }
  std::lock_guard lock(mutex_);
  if (gone()) return -ENODEV;
  if (!acquired_ || running_) return -EACCES;
  configured_ = checked;
  config = checked;
  buffers_.clear();
  queued_.clear();
  return 0;
}

std::expected<std::vector<LibcameraMappedBuffer>, int> FakeLibcameraPort::allocateBuffers() {
  std::lock_guard lock(mutex_);
  if (gone()) return std::unexpected(-ENODEV);
  if (!acquired_ || !configured_ || running_) return std::unexpected(-EACCES);
  buffers_.assign(std::size_t(configured_->bufferCount),
                  std::vector<std::uint8_t>(std::size_t(configured_->frameSizeBytes), 0));
  queued_.assign(buffers_.size(), false);
  std::vector<LibcameraMappedBuffer> out;
  for (const auto& b : buffers_) out.push_back({{std::span<const std::uint8_t>(b)}});
  return out;
}

int FakeLibcameraPort::start(const LibcameraControls& controls) {
  std::lock_guard lock(mutex_);
  if (gone()) return -ENODEV;
  if (!acquired_ || !configured_ || buffers_.empty() || running_) return -EACCES;
  running_ = true;
  framesStarted_ = 0;
  sequence_ = 0;
  lastFrameNs_ = 0;
  changes_.clear();
  exposureUs_ = camera_.defaultExposureUs;
  gain_ = camera_.defaultGain;
  applyControls(controls, 0);
  return 0;
}

int FakeLibcameraPort::queueRequest(std::uint64_t bufferIndex, const LibcameraControls& controls) {
  {
    std::lock_guard lock(mutex_);
    if (gone()) return -ENODEV;
    if (!running_) return -EACCES;
    if (bufferIndex >= queued_.size() || queued_[bufferIndex]) return -EINVAL;
    queued_[bufferIndex] = true;
    pending_.push_back({bufferIndex, controls});
    requestControls_.push_back(controls);
  }
  wake_.notify_all();
  return 0;
}

void FakeLibcameraPort::cancelPending() {
  while (!pending_.empty()) {
    const Pending p = pending_.front();
    pending_.pop_front();
    queued_[p.bufferIndex] = false;
    LibcameraCompletion c;
    c.bufferIndex = p.bufferIndex;
    c.requestCancelled = true;
    c.frameStatus = LibcameraFrameStatus::Cancelled;
    if (events_) events_->requestCompleted(c);
  }
}

int FakeLibcameraPort::stop() {
  std::unique_lock lock(mutex_);
  if (gone()) return -ENODEV;
  if (!running_) return 0;
  running_ = false;
  wake_.notify_all();
  settled_.wait(lock, [this] { return !inFlight_; });
  cancelPending();
  return 0;
}

void FakeLibcameraPort::release() {
  std::unique_lock lock(mutex_);
  if (!acquired_) return;
  running_ = false;
  wake_.notify_all();
  settled_.wait(lock, [this] { return !inFlight_; });
  if (!gone()) cancelPending();
  pending_.clear();
  stale_ = false;
  buffers_.clear();
  queued_.clear();
  configured_.reset();
  acquired_ = false;
  events_ = nullptr;
  disconnectPending_ = false;  // the released camera's signal is no longer connected
}

LibcameraClock FakeLibcameraPort::timestampClock() const { return camera_.clock; }

std::int64_t FakeLibcameraPort::clockNowNs(LibcameraClock clock) const {
  const std::int64_t now = vem::monotonicNowNs();
  return clock == LibcameraClock::Boottime ? now + camera_.boottimeAheadNs : now;
}

void FakeLibcameraPort::applyControls(const LibcameraControls& controls,
                                      std::uint64_t effectiveFrame) {
  if (!controls.exposureTimeUs && !controls.analogueGain) return;
  ControlChange change{effectiveFrame, std::nullopt, std::nullopt};
  if (controls.exposureTimeUs) {
    change.exposureUs =
        std::clamp(*controls.exposureTimeUs, camera_.minExposureUs, camera_.maxExposureUs);
  }
  if (controls.analogueGain) {
    change.gain = std::clamp(*controls.analogueGain, camera_.minGain, camera_.maxGain);
  }
  changes_.push_back(change);
}

void FakeLibcameraPort::settleControls(std::uint64_t frame) {
  auto due = [frame](const ControlChange& c) { return c.effectiveFrame <= frame; };
  for (const ControlChange& c : changes_) {
    if (!due(c)) continue;
    if (c.exposureUs) exposureUs_ = *c.exposureUs;
    if (c.gain) gain_ = *c.gain;
  }
  changes_.erase(std::remove_if(changes_.begin(), changes_.end(), due), changes_.end());
}

void FakeLibcameraPort::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] {
      return quit_ || disconnectPending_ || (running_ && plugged_ && !pending_.empty());
    });
    if (quit_) return;
    if (disconnectPending_) {
      disconnectPending_ = false;
      if (events_) events_->disconnected();
      continue;
    }
    deliverOne(lock);
  }
}

void FakeLibcameraPort::deliverOne(std::unique_lock<std::mutex>& lock) {
  if (camera_.framePeriodNs > 0 && lastFrameNs_ != 0) {
    const auto due = std::chrono::steady_clock::time_point(
        std::chrono::nanoseconds(lastFrameNs_ + camera_.framePeriodNs));
    wake_.wait_until(lock, due, [this] { return quit_ || disconnectPending_ || !running_; });
    if (quit_ || disconnectPending_ || !running_ || pending_.empty()) return;
  }
  const Pending p = pending_.front();
  pending_.pop_front();
  inFlight_ = true;
  const std::uint64_t frame = framesStarted_++;
  applyControls(p.controls, frame + std::uint64_t(camera_.controlDelayFrames));
  settleControls(frame);
  sequence_ += skip_;
  skip_ = 0;
  FakeFrameRecord record;
  record.sequence = sequence_++;
  record.status = fail_ > 0 ? LibcameraFrameStatus::Error : LibcameraFrameStatus::Success;
  if (fail_ > 0) --fail_;
  record.exposureUs = exposureUs_;
  record.gain = double(gain_);
  record.monotonicCaptureNs = vem::monotonicNowNs();
  record.timestampNs =
      std::uint64_t(record.monotonicCaptureNs +
                    (camera_.clock == LibcameraClock::Boottime ? camera_.boottimeAheadNs : 0));
  const LibcameraStreamConfig config = *configured_;
  std::span<std::uint8_t> bytes(buffers_[p.bufferIndex]);
  lock.unlock();  // render outside the lock: the buffer is the fake's until it completes

  vem::RawFrame raw;
  raw.width = config.size.widthPx;
  raw.height = config.size.heightPx;
  raw.format = calibFormatOf(config.format).value_or(vem::PixelFormat{1, 16});
  raw.codes.assign(
      std::size_t(raw.width) * std::size_t(raw.height) * std::size_t(raw.format.channels), 0);
  generator_({record.sequence, record.exposureUs, record.gain}, raw);
  if (calibFormatOf(config.format))
    packLibcameraFrame(config.format, config.strideBytes, raw, bytes);

  lock.lock();
  if (!gone()) {
    LibcameraCompletion c;
    c.bufferIndex = p.bufferIndex;
    c.requestCancelled = !running_;
    c.frameStatus = running_ ? record.status : LibcameraFrameStatus::Cancelled;
    c.sequence = record.sequence;
    c.timestampNs = record.timestampNs;
    c.bytesUsed = std::uint64_t(config.frameSizeBytes);
    if (camera_.reportsExposure) {
      c.exposureTimeUs = std::int32_t(record.exposureUs);
      c.analogueGain = float(record.gain);
    }
    queued_[p.bufferIndex] = false;
    lastFrameNs_ = record.monotonicCaptureNs;
    if (running_) delivered_.push_back(record);
    if (events_) events_->requestCompleted(c);
  }
  inFlight_ = false;
  settled_.notify_all();
}

void FakeLibcameraPort::skipFrames(std::uint32_t count) {
  std::lock_guard lock(mutex_);
  skip_ += count;
}

void FakeLibcameraPort::failFrames(int count) {
  std::lock_guard lock(mutex_);
  fail_ += count;
}

void FakeLibcameraPort::unplug() {
  {
    std::lock_guard lock(mutex_);
    if (!plugged_) return;
    plugged_ = false;
    stale_ = acquired_;
    running_ = false;
    pending_.clear();  // never complete: the device is gone
    disconnectPending_ = true;
  }
  wake_.notify_all();
}

void FakeLibcameraPort::replug() {
  std::lock_guard lock(mutex_);
  plugged_ = true;  // a new camera; one still acquired from before stays dead (stale_)
}

void FakeLibcameraPort::holdElsewhere(bool held) {
  std::lock_guard lock(mutex_);
  heldElsewhere_ = held;
}

std::vector<FakeFrameRecord> FakeLibcameraPort::delivered() const {
  std::lock_guard lock(mutex_);
  return delivered_;
}

std::vector<LibcameraControls> FakeLibcameraPort::requestControls() const {
  std::lock_guard lock(mutex_);
  return requestControls_;
}

bool FakeLibcameraPort::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

int FakeLibcameraPort::acquisitions() const {
  std::lock_guard lock(mutex_);
  return acquisitions_;
}

}  // namespace vem::cameras::testing
