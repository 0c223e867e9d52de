// FakeV4l2Device: one open file of a FakeV4l2Camera, implementing cameras::V4l2Device the way the
// kernel's V4L2 core and videobuf2 behave for a non-blocking single-planar mmap capture device:
//
// - VIDIOC_QUERYCAP, ENUM_FMT, ENUM_FRAMESIZES (discrete), G_FMT / S_FMT / TRY_FMT with the
//   driver's adjustment (an unknown format becomes the first, a size the nearest listed one;
//   bytesperline may be padded), S_FMT / REQBUFS EBUSY while buffers are allocated or streaming.
// - REQBUFS (MMAP only; count clamped to [2, maxBuffers]; count 0 frees, EBUSY while mapped),
//   QUERYBUF, mmap / munmap by offset, QBUF (EINVAL unless the buffer is the caller's),
//   DQBUF (EAGAIN when none is done, oldest first, EINVAL when not streaming), STREAMON / STREAMOFF
//   (which returns every buffer to the caller).
// - QUERYCTRL / G_CTRL / S_CTRL: integers rounded to step and clamped, menus ERANGE out of range;
//   EXPOSURE_ABSOLUTE EACCES while EXPOSURE_AUTO is automatic (as uvcvideo does for an inactive
//   control). G_PARM / S_PARM: the nearest listed frame rate.
// - poll: POLLIN when a buffer is done, POLLERR when not streaming or nothing is queued, waits on
//   an eventfd the camera signals (and on the caller's wake fd) otherwise.
// - After the camera is unplugged every call fails with ENODEV and poll reports POLLERR, as for a
//   disconnected USB device. Closing the owning file frees the queue.
// Unknown requests are ENOTTY.
#pragma once

#include <memory>

#include "cameras/v4l2/fake_v4l2_state.h"
#include "cameras/v4l2/v4l2_device.h"

namespace vem::testing {

class FakeV4l2Device final : public cameras::V4l2Device {
 public:
  explicit FakeV4l2Device(std::shared_ptr<FakeV4l2State> state);
  ~FakeV4l2Device() override;

  int ioctl(unsigned long request, void* arg) override;
  std::expected<std::span<const std::byte>, int> mmap(std::size_t length,
                                                      std::uint32_t offset) override;
  void munmap(std::span<const std::byte> mapping) override;
  std::expected<cameras::V4l2PollResult, int> poll(int wakeFd, int timeoutMs) override;

 private:
  [[nodiscard]] bool dead() const { return state_->generation != generation_; }
  int dispatch(unsigned long request, void* arg);
  int reqbufs(v4l2_requestbuffers& request);
  int querybuf(v4l2_buffer& buffer);
  int qbuf(v4l2_buffer& buffer);
  int dqbuf(v4l2_buffer& buffer);
  int streamon(bool on);
  int setControl(v4l2_control& control);
  int parm(v4l2_streamparm& parm, bool set);
  [[nodiscard]] bool ownsOrFree() const { return state_->owner == 0 || state_->owner == fileId_; }
  [[nodiscard]] cameras::V4l2PollResult pollState() const;

  std::shared_ptr<FakeV4l2State> state_;
  std::uint64_t generation_;
  std::uint64_t fileId_;
};

}  // namespace vem::testing
