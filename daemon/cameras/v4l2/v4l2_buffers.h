// V4l2Buffers: the memory-mapped capture buffers of one streaming device (V4L2 "Streaming I/O
// (Memory Mapping)"): VIDIOC_REQBUFS, VIDIOC_QUERYBUF + mmap for each, VIDIOC_QBUF of all, then
// VIDIOC_STREAMON. dequeue() takes the oldest finished buffer (VIDIOC_DQBUF, non-blocking), and
// requeue() gives it back to the driver; the caller copies the pixels out in between.
//
// RAII: destruction stops streaming (VIDIOC_STREAMOFF), unmaps every buffer and frees them
// (VIDIOC_REQBUFS with count 0), ignoring errors (a device that is gone fails them all). The
// device is borrowed and must outlive this object.
#pragma once

#include <linux/videodev2.h>

#include <cstdint>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include "cameras/v4l2/v4l2_device.h"

namespace vem::cameras {

struct V4l2Dequeued {
  std::uint32_t index = 0;
  std::uint32_t bytesUsed = 0;
  std::uint32_t flags = 0;  // V4L2_BUF_FLAG_*
  std::uint32_t sequence = 0;
  timeval timestamp{};
};

class V4l2Buffers {
 public:
  // Asks for `count` buffers (the driver may grant another number, at least 2 is required),
  // maps and queues them all and starts streaming. A sentence fragment with the errno text on
  // failure ("VIDIOC_REQBUFS failed: Device or resource busy").
  [[nodiscard]] static std::expected<V4l2Buffers, std::string> start(V4l2Device& device, int count);

  V4l2Buffers(V4l2Buffers&& other) noexcept;
  V4l2Buffers& operator=(V4l2Buffers&&) = delete;
  V4l2Buffers(const V4l2Buffers&) = delete;
  V4l2Buffers& operator=(const V4l2Buffers&) = delete;
  ~V4l2Buffers();

  // The oldest finished buffer, or the errno value (EAGAIN: none yet; ENODEV: the device is gone).
  [[nodiscard]] std::expected<V4l2Dequeued, int> dequeue();
  // Gives buffer `index` back to the driver: 0 or the errno value.
  [[nodiscard]] int requeue(std::uint32_t index);
  [[nodiscard]] std::span<const std::byte> data(std::uint32_t index) const {
    return mappings_[index];
  }
  [[nodiscard]] std::size_t count() const { return mappings_.size(); }

 private:
  explicit V4l2Buffers(V4l2Device& device) : device_(&device) {}
  void release();

  V4l2Device* device_;
  std::vector<std::span<const std::byte>> mappings_;
  bool requested_ = false;
  bool streaming_ = false;
};

}  // namespace vem::cameras
