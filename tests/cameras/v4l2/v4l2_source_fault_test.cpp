// V4l2Source when things go wrong: interrupted calls, timeouts, interrupt(), an unplugged camera,
// short and corrupt buffers.
#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <thread>

#include "cameras/v4l2/v4l2_source_fixtures.h"
#include "frames/frame_source.h"

namespace vem::testing {
namespace {

using vem::SourceErrorCause;

FakeFrameGenerator constantFrames() {
  return [](std::uint64_t index, const v4l2_pix_format& format) {
    FakeFrame f;
    f.bytes = encodeFakeFrame(
        std::vector<std::uint16_t>(std::size_t(format.width) * format.height, std::uint16_t(index)),
        format);
    return f;
  };
}

double msSince(std::int64_t startNs) { return double(vem::monotonicNowNs() - startNs) / 1e6; }

TEST(V4l2SourceFaults, EintrFromPollDequeueAndQueueIsRetried) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  camera.failNext(0, EINTR, 2);  // poll
  camera.failNext(VIDIOC_DQBUF, EINTR, 3);
  camera.failNext(VIDIOC_QBUF, EINTR, 1);
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 3))));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(frame->frame.codes, randomCodes(32, 16, 3));
  EXPECT_EQ(camera.pendingFaults(), 0);
  EXPECT_EQ(camera.queuedBuffers(), 4u);
}

// poll said readable, yet DQBUF finds nothing yet: wait again, not an error.
TEST(V4l2SourceFaults, EagainFromDequeueIsRetried) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  camera.failNext(VIDIOC_DQBUF, EAGAIN, 2);
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 4))));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(camera.pendingFaults(), 0);
}

TEST(V4l2SourceFaults, NoFrameWithinTheTimeoutIsTimeout) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.timeoutMs = 40;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  const std::int64_t start = vem::monotonicNowNs();
  auto frame = source->next();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, SourceErrorCause::Timeout);
  EXPECT_EQ(frame.error().message, "v4l2:/dev/video0: no frame within 40 ms");
  EXPECT_GE(msSince(start), 39.0);
  // Still streaming: the next frame comes.
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 5))));
  EXPECT_TRUE(source->next());
}

TEST(V4l2SourceFaults, InterruptFromAnotherThreadWakesAWaitingNext) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.timeoutMs = 20'000;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  const std::int64_t start = vem::monotonicNowNs();
  std::thread other([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    source->interrupt();
  });
  auto frame = source->next();
  other.join();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, SourceErrorCause::Timeout);
  EXPECT_LT(msSince(start), 5000.0);
  // The interrupt is spent: the next call waits for a frame again.
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 6))));
  EXPECT_TRUE(source->next());
}

TEST(V4l2SourceFaults, AnInterruptBeforeNextIsNotLost) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.timeoutMs = 20'000;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  source->interrupt();
  const std::int64_t start = vem::monotonicNowNs();
  auto frame = source->next();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, SourceErrorCause::Timeout);
  EXPECT_LT(msSince(start), 5000.0);
}

TEST(V4l2SourceFaults, UnplugIsNoDeviceAndReplugResumesWithTheSameSettings) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  camera.setGenerator(constantFrames(), 0);
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.exposureUs = 2000.0;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  std::uint64_t lastSeq = 0;
  for (int i = 0; i < 3; ++i) {
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    lastSeq = frame->seq;
  }
  camera.unplug();
  auto lost = source->next();
  ASSERT_FALSE(lost);
  EXPECT_EQ(lost.error().cause, SourceErrorCause::NoDevice);
  EXPECT_EQ(lost.error().message,
            "v4l2:/dev/video0: the camera is gone (VIDIOC_DQBUF: No such device)");
  auto stillGone = source->next();
  ASSERT_FALSE(stillGone);
  EXPECT_EQ(stillGone.error().cause, SourceErrorCause::NoDevice);
  EXPECT_EQ(stillGone.error().message,
            "v4l2:/dev/video0: cannot open the camera (No such file or directory)");
  EXPECT_EQ(camera.mappedBuffers(), 0);

  camera.replug();  // back with its defaults: automatic exposure, 15.6 ms
  auto back = source->next();
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_GT(back->seq, lastSeq);
  EXPECT_EQ(source->counters().reopened, 1u);
  EXPECT_EQ(camera.control(V4L2_CID_EXPOSURE_AUTO), V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(camera.control(V4L2_CID_EXPOSURE_ABSOLUTE), 20);
  EXPECT_EQ(camera.format().pixelformat, V4L2_PIX_FMT_Y16);
  EXPECT_EQ(camera.queuedBuffers() + 1, source->bufferCount());  // the generator filled one
  auto after = source->next();
  ASSERT_TRUE(after) << after.error().message;
  EXPECT_EQ(after->seq, back->seq + 1);
}

TEST(V4l2SourceFaults, UnplugWhileWaitingEndsTheWaitWithNoDevice) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.timeoutMs = 20'000;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  const std::int64_t start = vem::monotonicNowNs();
  std::thread other([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    camera.unplug();
  });
  auto frame = source->next();
  other.join();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, SourceErrorCause::NoDevice);
  EXPECT_LT(msSince(start), 5000.0);
}

TEST(V4l2SourceFaults, ShortAndCorruptBuffersAreCountedAndSkipped) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  FakeFrame shortFrame = fakeFrame(camera, randomCodes(32, 16, 1));
  shortFrame.bytesUsed = 40;
  FakeFrame corrupt = fakeFrame(camera, randomCodes(32, 16, 2));
  corrupt.errorFlag = true;
  ASSERT_TRUE(camera.pushFrame(shortFrame));
  ASSERT_TRUE(camera.pushFrame(corrupt));
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 3))));

  auto first = source->next();
  ASSERT_FALSE(first);
  EXPECT_EQ(first.error().cause, SourceErrorCause::BadFrame);
  EXPECT_EQ(first.error().message, "v4l2:/dev/video0: frame 0 is short: 40 of 64 bytes");
  auto second = source->next();
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().cause, SourceErrorCause::BadFrame);
  EXPECT_EQ(second.error().message, "v4l2:/dev/video0: the driver flagged frame 1 as corrupt");
  auto good = source->next();
  ASSERT_TRUE(good) << good.error().message;
  EXPECT_EQ(good->seq, 2u);
  EXPECT_EQ(good->frame.codes, randomCodes(32, 16, 3));
  EXPECT_EQ(source->counters().shortFrames, 1u);
  EXPECT_EQ(source->counters().corruptFrames, 1u);
  EXPECT_EQ(source->counters().completed, 1u);
  EXPECT_EQ(camera.queuedBuffers(), 4u);  // the bad buffers went back too
}

// A padded last row may be cut: bytesused covers the pixels, not the padding.
TEST(V4l2SourceFaults, ABufferWithoutTheLastRowsPaddingIsNotShort) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4, 64));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  FakeFrame f = fakeFrame(camera, randomCodes(32, 16, 9));
  f.bytesUsed = 64 * 3 + 16;
  ASSERT_TRUE(camera.pushFrame(f));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(frame->frame.codes, randomCodes(32, 16, 9));
}

}  // namespace
}  // namespace vem::testing
