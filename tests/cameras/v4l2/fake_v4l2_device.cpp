#include "cameras/v4l2/fake_v4l2_device.h"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "frames/frame_source.h"

namespace vem::testing {

namespace {

constexpr std::uint32_t kOffsetStride = 64u << 20;  // buffer i maps at i x 64 MiB

bool readable(int fd) {
  if (fd < 0) return false;
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & POLLIN);
}

bool captureType(std::uint32_t type) { return type == V4L2_BUF_TYPE_VIDEO_CAPTURE; }

void copyText(std::uint8_t* out, std::size_t size, const std::string& text) {
  std::memset(out, 0, size);
  std::memcpy(out, text.data(), std::min(size - 1, text.size()));
}

}  // namespace

FakeV4l2Device::FakeV4l2Device(std::shared_ptr<FakeV4l2State> state)
    : state_(std::move(state)), generation_(state_->generation), fileId_(state_->nextFileId++) {}

FakeV4l2Device::~FakeV4l2Device() {
  std::lock_guard lock(state_->mutex);
  if (dead() || state_->owner != fileId_) return;
  state_->releaseQueue();
  state_->owner = 0;
  const bool mapped =
      std::ranges::any_of(state_->buffers, [](const FakeBuffer& b) { return b.mappings > 0; });
  if (!mapped) state_->buffers.clear();
}

int FakeV4l2Device::ioctl(unsigned long request, void* arg) {
  std::lock_guard lock(state_->mutex);
  if (dead()) return ENODEV;
  if (auto fault = state_->takeFault(request)) return *fault;
  state_->advance(vem::monotonicNowNs());
  return dispatch(request, arg);
}

int FakeV4l2Device::dispatch(unsigned long request, void* arg) {
  FakeV4l2State& s = *state_;
  switch (request) {
    case VIDIOC_QUERYCAP: {
      auto& cap = *static_cast<v4l2_capability*>(arg);
      cap = v4l2_capability{};
      copyText(cap.driver, sizeof cap.driver, s.driver);
      copyText(cap.card, sizeof cap.card, s.card);
      copyText(cap.bus_info, sizeof cap.bus_info, s.busInfo);
      cap.version = (6u << 16) | (1u << 8);
      cap.device_caps = s.deviceCaps;
      cap.capabilities = s.deviceCaps | V4L2_CAP_DEVICE_CAPS;
      return 0;
    }
    case VIDIOC_ENUM_FMT: {
      auto& desc = *static_cast<v4l2_fmtdesc*>(arg);
      if (!captureType(desc.type) || desc.index >= s.formats.size()) return EINVAL;
      const std::uint32_t index = desc.index;
      desc = v4l2_fmtdesc{};
      desc.index = index;
      desc.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
      desc.pixelformat = s.formats[index].fourcc;
      return 0;
    }
    case VIDIOC_ENUM_FRAMESIZES: {
      auto& size = *static_cast<v4l2_frmsizeenum*>(arg);
      auto format = std::ranges::find(s.formats, size.pixel_format, &FakeFormat::fourcc);
      if (format == s.formats.end() || size.index >= format->sizes.size()) return EINVAL;
      size.type = V4L2_FRMSIZE_TYPE_DISCRETE;
      size.discrete.width = std::uint32_t(format->sizes[size.index].widthPx);
      size.discrete.height = std::uint32_t(format->sizes[size.index].heightPx);
      return 0;
    }
    case VIDIOC_G_FMT:
    case VIDIOC_S_FMT:
    case VIDIOC_TRY_FMT: {
      auto& format = *static_cast<v4l2_format*>(arg);
      if (!captureType(format.type)) return EINVAL;
      if (request == VIDIOC_G_FMT) {
        format.fmt.pix = s.format;
        return 0;
      }
      if (request == VIDIOC_S_FMT && (!ownsOrFree() || !s.buffers.empty())) return EBUSY;
      const v4l2_pix_format kept = s.format;
      s.applyFormat(format.fmt.pix.pixelformat, int(format.fmt.pix.width),
                    int(format.fmt.pix.height));
      format.fmt.pix = s.format;
      if (request == VIDIOC_TRY_FMT) s.format = kept;
      return 0;
    }
    case VIDIOC_REQBUFS: return reqbufs(*static_cast<v4l2_requestbuffers*>(arg));
    case VIDIOC_QUERYBUF: return querybuf(*static_cast<v4l2_buffer*>(arg));
    case VIDIOC_QBUF: return qbuf(*static_cast<v4l2_buffer*>(arg));
    case VIDIOC_DQBUF: return dqbuf(*static_cast<v4l2_buffer*>(arg));
    case VIDIOC_STREAMON:
    case VIDIOC_STREAMOFF:
      if (!captureType(std::uint32_t(*static_cast<int*>(arg)))) return EINVAL;
      return streamon(request == VIDIOC_STREAMON);
    case VIDIOC_QUERYCTRL: {
      auto& query = *static_cast<v4l2_queryctrl*>(arg);
      auto control = s.controls.find(query.id);
      if (control == s.controls.end()) return EINVAL;
      query = control->second.query;
      return 0;
    }
    case VIDIOC_G_CTRL: {
      auto& control = *static_cast<v4l2_control*>(arg);
      auto found = s.controls.find(control.id);
      if (found == s.controls.end()) return EINVAL;
      control.value = found->second.value;
      return 0;
    }
    case VIDIOC_S_CTRL: return setControl(*static_cast<v4l2_control*>(arg));
    case VIDIOC_G_PARM:
    case VIDIOC_S_PARM: return parm(*static_cast<v4l2_streamparm*>(arg), request == VIDIOC_S_PARM);
    default: return ENOTTY;
  }
}

int FakeV4l2Device::reqbufs(v4l2_requestbuffers& request) {
  FakeV4l2State& s = *state_;
  if (!captureType(request.type) || request.memory != V4L2_MEMORY_MMAP) return EINVAL;
  if (!ownsOrFree() || s.streaming) return EBUSY;
  s.requestedBufferCounts.push_back(request.count);
  if (std::ranges::any_of(s.buffers, [](const FakeBuffer& b) { return b.mappings > 0; })) {
    return EBUSY;
  }
  s.releaseQueue();
  s.buffers.clear();
  if (request.count == 0) {
    s.owner = 0;
    return 0;
  }
  request.count = std::clamp(request.count, 2u, s.maxBuffers);
  s.buffers.resize(request.count);
  for (FakeBuffer& b : s.buffers) b.memory.assign(s.format.sizeimage, 0);
  s.owner = fileId_;
  return 0;
}

int FakeV4l2Device::querybuf(v4l2_buffer& buffer) {
  FakeV4l2State& s = *state_;
  if (!captureType(buffer.type) || buffer.memory != V4L2_MEMORY_MMAP ||
      buffer.index >= s.buffers.size() || s.owner != fileId_) {
    return EINVAL;
  }
  const FakeBuffer& b = s.buffers[buffer.index];
  buffer.length = std::uint32_t(b.memory.size());
  buffer.m.offset = buffer.index * kOffsetStride;
  buffer.bytesused = b.bytesUsed;
  buffer.flags = (b.state == FakeBuffer::State::Queued ? V4L2_BUF_FLAG_QUEUED : 0u) |
                 (b.state == FakeBuffer::State::Done ? V4L2_BUF_FLAG_DONE : 0u) |
                 (b.mappings > 0 ? V4L2_BUF_FLAG_MAPPED : 0u) | V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
  return 0;
}

int FakeV4l2Device::qbuf(v4l2_buffer& buffer) {
  FakeV4l2State& s = *state_;
  if (!captureType(buffer.type) || buffer.memory != V4L2_MEMORY_MMAP ||
      buffer.index >= s.buffers.size() || s.owner != fileId_) {
    return EINVAL;
  }
  FakeBuffer& b = s.buffers[buffer.index];
  if (b.state != FakeBuffer::State::Dequeued) return EINVAL;
  b.state = FakeBuffer::State::Queued;
  s.queued.push_back(buffer.index);
  buffer.flags = V4L2_BUF_FLAG_QUEUED | V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
  s.ready.signal();  // a paced or free-running feed may now fill it
  return 0;
}

int FakeV4l2Device::dqbuf(v4l2_buffer& buffer) {
  FakeV4l2State& s = *state_;
  if (!captureType(buffer.type) || buffer.memory != V4L2_MEMORY_MMAP || s.owner != fileId_ ||
      !s.streaming) {
    return EINVAL;
  }
  if (s.done.empty()) return EAGAIN;
  const std::uint32_t index = s.done.front();
  s.done.pop_front();
  FakeBuffer& b = s.buffers[index];
  b.state = FakeBuffer::State::Dequeued;
  buffer.index = index;
  buffer.bytesused = b.bytesUsed;
  buffer.flags = b.flags | (b.mappings > 0 ? V4L2_BUF_FLAG_MAPPED : 0u);
  buffer.field = V4L2_FIELD_NONE;
  buffer.sequence = b.sequence;
  buffer.timestamp.tv_sec = b.timestampNs / 1'000'000'000;
  buffer.timestamp.tv_usec = (b.timestampNs % 1'000'000'000) / 1'000;
  buffer.length = std::uint32_t(b.memory.size());
  buffer.m.offset = index * kOffsetStride;
  return 0;
}

int FakeV4l2Device::streamon(bool on) {
  FakeV4l2State& s = *state_;
  if (s.owner != fileId_ || s.buffers.empty()) return EINVAL;
  if (on) {
    if (!s.streaming) {
      s.streaming = true;
      s.streamOnNs = vem::monotonicNowNs();
      s.nextDueNs = s.streamOnNs + s.periodNs;
    }
  } else {
    s.releaseQueue();
  }
  s.ready.signal();
  return 0;
}

int FakeV4l2Device::setControl(v4l2_control& control) {
  FakeV4l2State& s = *state_;
  auto found = s.controls.find(control.id);
  if (found == s.controls.end()) return EINVAL;
  const v4l2_queryctrl& q = found->second.query;
  if (q.flags & (V4L2_CTRL_FLAG_READ_ONLY | V4L2_CTRL_FLAG_DISABLED)) return EACCES;
  int value = control.value;
  if (q.type == V4L2_CTRL_TYPE_MENU || q.type == V4L2_CTRL_TYPE_BOOLEAN) {
    if (value < q.minimum || value > q.maximum) return ERANGE;
  } else {
    const int step = std::max(q.step, 1);
    value = q.minimum + int(std::lround(double(value - q.minimum) / step)) * step;
    value = std::clamp(value, q.minimum, q.maximum);
  }
  if (control.id == V4L2_CID_EXPOSURE_ABSOLUTE) {
    auto mode = s.controls.find(V4L2_CID_EXPOSURE_AUTO);
    if (mode != s.controls.end() && mode->second.value != V4L2_EXPOSURE_MANUAL &&
        mode->second.value != V4L2_EXPOSURE_SHUTTER_PRIORITY) {
      return EACCES;
    }
  }
  found->second.value = value;
  control.value = value;
  return 0;
}

int FakeV4l2Device::parm(v4l2_streamparm& parm, bool set) {
  FakeV4l2State& s = *state_;
  if (!captureType(parm.type)) return EINVAL;
  if (s.frameRatesHz.empty()) return set ? ENOTTY : 0;
  if (set) {
    if (s.streaming) return EBUSY;
    const v4l2_fract asked = parm.parm.capture.timeperframe;
    if (asked.numerator != 0 && asked.denominator != 0) {
      const double hz = double(asked.denominator) / double(asked.numerator);
      s.frameRateHz =
          *std::ranges::min_element(s.frameRatesHz, {}, [&](double r) { return std::abs(r - hz); });
    }
  }
  parm.parm.capture = v4l2_captureparm{};
  parm.parm.capture.capability = V4L2_CAP_TIMEPERFRAME;
  parm.parm.capture.timeperframe = {1000, std::uint32_t(std::lround(s.frameRateHz * 1000.0))};
  parm.parm.capture.readbuffers = 0;
  return 0;
}

std::expected<std::span<const std::byte>, int> FakeV4l2Device::mmap(std::size_t length,
                                                                    std::uint32_t offset) {
  std::lock_guard lock(state_->mutex);
  if (dead()) return std::unexpected(ENODEV);
  FakeV4l2State& s = *state_;
  const std::uint32_t index = offset / kOffsetStride;
  if (s.owner != fileId_ || offset % kOffsetStride != 0 || index >= s.buffers.size() ||
      length == 0 || length > s.buffers[index].memory.size()) {
    return std::unexpected(EINVAL);
  }
  ++s.buffers[index].mappings;
  return std::span<const std::byte>(
      reinterpret_cast<const std::byte*>(s.buffers[index].memory.data()), length);
}

void FakeV4l2Device::munmap(std::span<const std::byte> mapping) {
  std::lock_guard lock(state_->mutex);
  for (FakeBuffer& b : state_->buffers) {
    if (reinterpret_cast<const std::byte*>(b.memory.data()) == mapping.data() && b.mappings > 0) {
      --b.mappings;
      return;
    }
  }
}

cameras::V4l2PollResult FakeV4l2Device::pollState() const {
  const FakeV4l2State& s = *state_;
  cameras::V4l2PollResult result;
  if (dead() || !s.streaming || s.owner != fileId_) {
    result.deviceError = true;
  } else if (!s.done.empty()) {
    result.frameReady = true;
  } else if (s.queued.empty()) {
    result.deviceError = true;
  }
  return result;
}

std::expected<cameras::V4l2PollResult, int> FakeV4l2Device::poll(int wakeFd, int timeoutMs) {
  const std::int64_t deadlineNs = vem::monotonicNowNs() + std::int64_t(timeoutMs) * 1'000'000;
  {
    std::lock_guard lock(state_->mutex);
    if (auto fault = state_->takeFault(0)) return std::unexpected(*fault);
  }
  for (;;) {
    std::int64_t waitNs = 0;
    {
      std::lock_guard lock(state_->mutex);
      const std::int64_t nowNs = vem::monotonicNowNs();
      if (!dead()) state_->advance(nowNs);
      cameras::V4l2PollResult result = pollState();
      if (result.frameReady || result.deviceError) {
        result.woken = readable(wakeFd);
        return result;
      }
      waitNs = deadlineNs - nowNs;
      if (state_->generator && state_->periodNs > 0 && state_->streaming) {
        waitNs = std::min(waitNs, state_->nextDueNs - nowNs);
      }
    }
    pollfd fds[2] = {{state_->ready.fd(), POLLIN, 0}, {wakeFd, POLLIN, 0}};
    const int waitMs = int(std::max<std::int64_t>(0, (waitNs + 999'999) / 1'000'000));
    if (::poll(fds, wakeFd >= 0 ? 2 : 1, waitMs) < 0) return std::unexpected(errno);
    if (wakeFd >= 0 && (fds[1].revents & POLLIN)) {
      cameras::V4l2PollResult woken;
      woken.woken = true;
      return woken;
    }
    if (fds[0].revents & POLLIN) {
      state_->ready.consume();
      continue;
    }
    if (vem::monotonicNowNs() >= deadlineNs) return cameras::V4l2PollResult{};
  }
}

}  // namespace vem::testing
