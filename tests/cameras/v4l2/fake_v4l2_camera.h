// FakeV4l2Camera: an in-process V4L2 capture camera for the backend's tests and benchmark. It is
// the hardware (formats, controls, frame rates, a frame feed, the USB plug); open() gives a new
// FakeV4l2Device (an open file of it, fake_v4l2_device.h) as the kernel would, and opener() the
// function V4l2Source takes to reopen it after an unplug.
//
// Frames: pushFrame() (from any thread) fills the oldest queued buffer now; setGenerator() makes
// frames itself, one every periodNs of CLOCK_MONOTONIC from STREAMON (a frame due with no buffer
// queued is lost and the sequence skips, as in a driver) or, with periodNs 0, one whenever the
// last was taken. encodeFakeFrame() (fake_v4l2_frames.h) writes codes in any format's layout.
// Faults: failNext() makes the next calls of one ioctl (or poll, request 0) fail with an errno;
// unplug() kills every open file (ENODEV from then on) and refuses opens (ENOENT) until replug(),
// which brings the camera back with its default settings (format, controls, rate).
// Thread-safe.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cameras/v4l2/fake_v4l2_state.h"
#include "cameras/v4l2/v4l2_device.h"

namespace vem::testing {

struct FakeV4l2Config {
  std::string card = "Fake V4L2 Camera";
  std::string busInfo = "usb-fake-1.2";
  std::string driver = "vem_fake";
  std::uint32_t deviceCaps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
  std::vector<FakeFormat> formats;            // at least one; the first is the default
  std::vector<std::uint32_t> refusedFourccs;  // listed by ENUM_FMT, but S_FMT will not take them
  std::size_t rowAlignBytes = 1;              // bytesperline = packed row rounded up to this
  std::vector<double> frameRatesHz = {30.0, 15.0, 60.0};  // the first is the default
  unsigned maxBuffers = 32;
  std::vector<FakeControl> controls = defaultControls();

  // A UVC-like set: EXPOSURE_AUTO (menu, default aperture priority), EXPOSURE_ABSOLUTE
  // (1..10000 x 100 us, default 156), GAIN (0..255, default 32 = unity).
  [[nodiscard]] static std::vector<FakeControl> defaultControls();
};

class FakeV4l2Camera {
 public:
  explicit FakeV4l2Camera(FakeV4l2Config config);

  [[nodiscard]] std::expected<std::unique_ptr<cameras::V4l2Device>, int> open();
  // Opens this camera for `path` == expectedPath (any path when empty); ENOENT otherwise.
  [[nodiscard]] cameras::V4l2Opener opener(std::string expectedPath = "");

  // Fills the oldest queued buffer; false (the frame lost) when none is queued or not streaming.
  bool pushFrame(const FakeFrame& frame);
  void setGenerator(FakeFrameGenerator generator, std::int64_t periodNs);

  void unplug();
  void replug();
  void failNext(unsigned long request, int error, int count = 1);

  // Observations.
  [[nodiscard]] v4l2_pix_format format() const;
  [[nodiscard]] int control(std::uint32_t id) const;
  [[nodiscard]] double frameRateHz() const;
  [[nodiscard]] std::vector<std::uint32_t> requestedBufferCounts() const;
  [[nodiscard]] std::size_t allocatedBuffers() const;
  [[nodiscard]] int mappedBuffers() const;
  [[nodiscard]] std::size_t queuedBuffers() const;
  [[nodiscard]] bool streaming() const;
  [[nodiscard]] std::uint64_t droppedFrames() const;
  [[nodiscard]] int pendingFaults() const;

 private:
  std::shared_ptr<FakeV4l2State> state_;
};

}  // namespace vem::testing
