#include "cameras/v4l2/v4l2_buffers.h"

#include <utility>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

constexpr int kMinimumGranted = 2;

std::string failed(const char* what, int error) {
  return fmt::format("{} failed: {}", what, errnoText(error));
}

v4l2_buffer mmapBuffer(std::uint32_t index) {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buffer.memory = V4L2_MEMORY_MMAP;
  buffer.index = index;
  return buffer;
}

}  // namespace

std::expected<V4l2Buffers, std::string> V4l2Buffers::start(V4l2Device& device, int count) {
  V4l2Buffers buffers(device);
  v4l2_requestbuffers request{};
  request.count = std::uint32_t(count);
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  if (const int error = v4l2Ioctl(device, VIDIOC_REQBUFS, &request)) {
    return std::unexpected(failed("VIDIOC_REQBUFS", error));
  }
  buffers.requested_ = true;
  if (int(request.count) < kMinimumGranted) {
    return std::unexpected(
        fmt::format("the driver granted {} capture buffers, at least {} are needed", request.count,
                    kMinimumGranted));
  }
  for (std::uint32_t i = 0; i < request.count; ++i) {
    v4l2_buffer buffer = mmapBuffer(i);
    if (const int error = v4l2Ioctl(device, VIDIOC_QUERYBUF, &buffer)) {
      return std::unexpected(failed("VIDIOC_QUERYBUF", error));
    }
    auto mapped = device.mmap(buffer.length, buffer.m.offset);
    if (!mapped) return std::unexpected(failed("mmap", mapped.error()));
    buffers.mappings_.push_back(*mapped);
  }
  for (std::uint32_t i = 0; i < request.count; ++i) {
    if (const int error = buffers.requeue(i)) return std::unexpected(failed("VIDIOC_QBUF", error));
  }
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (const int error = v4l2Ioctl(device, VIDIOC_STREAMON, &type)) {
    return std::unexpected(failed("VIDIOC_STREAMON", error));
  }
  buffers.streaming_ = true;
  return buffers;
}

V4l2Buffers::V4l2Buffers(V4l2Buffers&& other) noexcept
    : device_(other.device_),
      mappings_(std::move(other.mappings_)),
      requested_(std::exchange(other.requested_, false)),
      streaming_(std::exchange(other.streaming_, false)) {
  other.mappings_.clear();
}

V4l2Buffers::~V4l2Buffers() { release(); }

void V4l2Buffers::release() {
  if (streaming_) {
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    (void)v4l2Ioctl(*device_, VIDIOC_STREAMOFF, &type);
    streaming_ = false;
  }
  for (auto mapping : mappings_) device_->munmap(mapping);
  mappings_.clear();
  if (requested_) {
    v4l2_requestbuffers request{};
    request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    request.memory = V4L2_MEMORY_MMAP;
    (void)v4l2Ioctl(*device_, VIDIOC_REQBUFS, &request);
    requested_ = false;
  }
}

std::expected<V4l2Dequeued, int> V4l2Buffers::dequeue() {
  v4l2_buffer buffer = mmapBuffer(0);
  if (const int error = v4l2Ioctl(*device_, VIDIOC_DQBUF, &buffer)) return std::unexpected(error);
  return V4l2Dequeued{buffer.index, buffer.bytesused, buffer.flags, buffer.sequence,
                      buffer.timestamp};
}

int V4l2Buffers::requeue(std::uint32_t index) {
  v4l2_buffer buffer = mmapBuffer(index);
  return v4l2Ioctl(*device_, VIDIOC_QBUF, &buffer);
}

}  // namespace vem::cameras
