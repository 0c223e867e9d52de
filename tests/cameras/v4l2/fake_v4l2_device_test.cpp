// The fake follows the kernel: the semantics the backend relies on, checked on the fake itself so
// a test of the backend cannot pass on a fake that is kinder than a driver.
#include <gtest/gtest.h>

#include <cerrno>

#include "cameras/v4l2/fake_v4l2_camera.h"
#include "cameras/v4l2/fake_v4l2_frames.h"

namespace vem::testing {
namespace {

FakeV4l2Config y16Camera() {
  FakeV4l2Config c;
  c.formats = {{V4L2_PIX_FMT_Y16, {{8, 4}, {16, 8}}}, {V4L2_PIX_FMT_YUYV, {{8, 4}}}};
  return c;
}

v4l2_buffer mmapBuffer(std::uint32_t index = 0) {
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = index;
  return b;
}

// Allocates `count` buffers, maps none, queues all, streams.
void stream(cameras::V4l2Device& device, std::uint32_t count) {
  v4l2_requestbuffers request{};
  request.count = count;
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  ASSERT_EQ(device.ioctl(VIDIOC_REQBUFS, &request), 0);
  for (std::uint32_t i = 0; i < request.count; ++i) {
    v4l2_buffer b = mmapBuffer(i);
    ASSERT_EQ(device.ioctl(VIDIOC_QBUF, &b), 0);
  }
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  ASSERT_EQ(device.ioctl(VIDIOC_STREAMON, &type), 0);
}

FakeFrame frameOf(const v4l2_pix_format& format, std::uint16_t value) {
  FakeFrame f;
  f.bytes =
      encodeFakeFrame(std::vector<std::uint16_t>(format.width * format.height, value), format);
  return f;
}

TEST(FakeV4l2Device, DriverAdjustsAnUnknownFormatAndSize) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f.fmt.pix.pixelformat = V4L2_PIX_FMT_MJPEG;
  f.fmt.pix.width = 15;
  f.fmt.pix.height = 9;
  ASSERT_EQ((*device)->ioctl(VIDIOC_S_FMT, &f), 0);
  EXPECT_EQ(f.fmt.pix.pixelformat, V4L2_PIX_FMT_Y16);
  EXPECT_EQ(f.fmt.pix.width, 16u);
  EXPECT_EQ(f.fmt.pix.height, 8u);
}

TEST(FakeV4l2Device, DequeueWithNothingDoneIsEagainAndBuffersComeBackInOrder) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  stream(**device, 4);
  v4l2_buffer b = mmapBuffer();
  EXPECT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), EAGAIN);
  for (std::uint16_t i = 0; i < 3; ++i) ASSERT_TRUE(camera.pushFrame(frameOf(camera.format(), i)));
  for (std::uint32_t i = 0; i < 3; ++i) {
    b = mmapBuffer();
    ASSERT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), 0);
    EXPECT_EQ(b.index, i);
    EXPECT_EQ(b.sequence, i);
    EXPECT_EQ(b.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK, V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC);
  }
}

TEST(FakeV4l2Device, QueueingABufferTheDriverHoldsIsEinval) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  stream(**device, 4);
  v4l2_buffer b = mmapBuffer(1);
  EXPECT_EQ((*device)->ioctl(VIDIOC_QBUF, &b), EINVAL);
  b = mmapBuffer(9);
  EXPECT_EQ((*device)->ioctl(VIDIOC_QBUF, &b), EINVAL);
}

TEST(FakeV4l2Device, AFrameWithNoQueuedBufferIsLostAndTheSequenceSkips) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  stream(**device, 2);
  EXPECT_TRUE(camera.pushFrame(frameOf(camera.format(), 1)));
  EXPECT_TRUE(camera.pushFrame(frameOf(camera.format(), 2)));
  EXPECT_FALSE(camera.pushFrame(frameOf(camera.format(), 3)));
  v4l2_buffer b = mmapBuffer();
  ASSERT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), 0);
  ASSERT_EQ((*device)->ioctl(VIDIOC_QBUF, &b), 0);
  EXPECT_TRUE(camera.pushFrame(frameOf(camera.format(), 4)));
  ASSERT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), 0);
  ASSERT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), 0);
  EXPECT_EQ(b.sequence, 3u);
  EXPECT_EQ(camera.droppedFrames(), 1u);
}

TEST(FakeV4l2Device, AfterAnUnplugEveryCallIsEnodevAndOpensFail) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  stream(**device, 4);
  camera.unplug();
  v4l2_capability cap{};
  EXPECT_EQ((*device)->ioctl(VIDIOC_QUERYCAP, &cap), ENODEV);
  v4l2_buffer b = mmapBuffer();
  EXPECT_EQ((*device)->ioctl(VIDIOC_DQBUF, &b), ENODEV);
  const auto mapped = (*device)->mmap(16, 0);
  ASSERT_FALSE(mapped);
  EXPECT_EQ(mapped.error(), ENODEV);
  auto polled = (*device)->poll(-1, 0);
  ASSERT_TRUE(polled);
  EXPECT_TRUE(polled->deviceError);
  const auto refused = camera.open();
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), ENOENT);
  camera.replug();
  EXPECT_TRUE(camera.open());
}

TEST(FakeV4l2Device, FormatCannotChangeWhileBuffersAreAllocated) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  stream(**device, 4);
  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f.fmt.pix = camera.format();
  EXPECT_EQ((*device)->ioctl(VIDIOC_S_FMT, &f), EBUSY);
  v4l2_requestbuffers request{};
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  EXPECT_EQ((*device)->ioctl(VIDIOC_REQBUFS, &request), EBUSY);  // streaming
}

TEST(FakeV4l2Device, ExposureTimeIsRefusedWhileExposureIsAutomatic) {
  FakeV4l2Camera camera(y16Camera());
  auto device = camera.open();
  ASSERT_TRUE(device);
  v4l2_control c{V4L2_CID_EXPOSURE_ABSOLUTE, 50};
  EXPECT_EQ((*device)->ioctl(VIDIOC_S_CTRL, &c), EACCES);
  v4l2_control mode{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL};
  ASSERT_EQ((*device)->ioctl(VIDIOC_S_CTRL, &mode), 0);
  c.value = 50000;  // clamped, as the V4L2 control framework does for integers
  ASSERT_EQ((*device)->ioctl(VIDIOC_S_CTRL, &c), 0);
  EXPECT_EQ(c.value, 10000);
}

}  // namespace
}  // namespace vem::testing
