// V4l2Device: the thin seam between the V4L2 backend and the kernel. One object is one open file of
// a video node (/dev/videoN); the backend does everything else (formats, buffers, controls) through
// these few calls, so tests put an in-process fake (tests/cameras/v4l2/) in its place.
//
// Conventions:
// - Every call returns 0 / a value on success and a positive errno value on failure (never -1,
//   never through the global errno): ioctl() gives 0 or EINVAL, EAGAIN, ENODEV... The real device
//   retries EINTR itself; callers retry it too (v4l2Ioctl()), so a fake may inject it.
// - The file is opened non-blocking: VIDIOC_DQBUF with no finished buffer is EAGAIN.
// - poll() waits for a finished buffer (POLLIN), an error (POLLERR / POLLHUP: not streaming, or the
//   device is gone) or a readable `wakeFd` (an eventfd the caller signals from another thread to
//   cut the wait short), for at most timeoutMs milliseconds. Timing out sets no flag.
// - mmap() maps one buffer (offset as VIDIOC_QUERYBUF gives it), read-only and shared; the mapping
//   must be unmapped before the device is destroyed.
// Reference: the Linux Media Infrastructure userspace API, part I (V4L2), "Streaming I/O (Memory
// Mapping)" and "ioctl VIDIOC_QBUF, VIDIOC_DQBUF".
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace vem::cameras {

struct V4l2PollResult {
  bool frameReady = false;   // POLLIN: a buffer can be dequeued
  bool deviceError = false;  // POLLERR / POLLHUP: dequeue to learn why (ENODEV after an unplug)
  bool woken = false;        // wakeFd became readable
};

class V4l2Device {
 public:
  virtual ~V4l2Device() = default;
  V4l2Device() = default;
  V4l2Device(const V4l2Device&) = delete;
  V4l2Device& operator=(const V4l2Device&) = delete;

  // ioctl(2) on the device: 0, or the errno value.
  [[nodiscard]] virtual int ioctl(unsigned long request, void* arg) = 0;
  // mmap(2) of `length` bytes at `offset` (v4l2_buffer::m.offset), or the errno value.
  [[nodiscard]] virtual std::expected<std::span<const std::byte>, int> mmap(
      std::size_t length, std::uint32_t offset) = 0;
  virtual void munmap(std::span<const std::byte> mapping) = 0;
  // poll(2) on the device and wakeFd (-1: none); the errno value on failure (EINTR included).
  [[nodiscard]] virtual std::expected<V4l2PollResult, int> poll(int wakeFd, int timeoutMs) = 0;
};

// Opens the video node at `path` (a new V4l2Device each call), or gives the errno value
// (ENOENT while the camera is unplugged, EACCES without permission).
using V4l2Opener =
    std::function<std::expected<std::unique_ptr<V4l2Device>, int>(const std::string& path)>;

// The real thing: open(path, O_RDWR | O_NONBLOCK | O_CLOEXEC) over <linux/videodev2.h> and libc.
[[nodiscard]] std::expected<std::unique_ptr<V4l2Device>, int> openSystemV4l2Device(
    const std::string& path);

// ioctl with EINTR retried (a bounded number of times); 0 or the errno value.
[[nodiscard]] int v4l2Ioctl(V4l2Device& device, unsigned long request, void* arg);

// strerror text of an errno value ("No such device").
[[nodiscard]] std::string errnoText(int error);

}  // namespace vem::cameras
