// FakeLibcameraPort keeps libcamera's semantics (fake_libcamera_port.h): a fake that drifted from
// them would let the backend pass tests it fails on hardware.
#include "fake_libcamera_port.h"

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "fake_frame_generators.h"

namespace vem::cameras::testing {
namespace {

FakeLibcameraCamera smallCamera() {
  FakeLibcameraCamera c;
  c.formats = {{LibcameraRole::Raw, kLibcameraR16, {{32, 24}, {64, 48}}},
               {LibcameraRole::Raw, kLibcameraR8, {{32, 24}}}};
  return c;
}

// Records what the port reports, and on which thread.
// Declared before the port in each test: the port reports to it until the port is gone.
class Recorder final : public LibcameraEvents {
 public:
  void requestCompleted(const LibcameraCompletion& c) override {
    std::lock_guard lock(mutex_);
    completions_.push_back(c);
    threads_.push_back(std::this_thread::get_id());
    wake_.notify_all();
  }
  void disconnected() override {
    std::lock_guard lock(mutex_);
    disconnected_ = true;
    wake_.notify_all();
  }
  bool waitFor(std::size_t completions) {
    std::unique_lock lock(mutex_);
    return wake_.wait_for(lock, std::chrono::seconds(5),
                          [&] { return completions_.size() >= completions; });
  }
  bool waitDisconnected() {
    std::unique_lock lock(mutex_);
    return wake_.wait_for(lock, std::chrono::seconds(5), [&] { return disconnected_; });
  }
  std::vector<LibcameraCompletion> completions() {
    std::lock_guard lock(mutex_);
    return completions_;
  }
  std::vector<std::thread::id> threads() {
    std::lock_guard lock(mutex_);
    return threads_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<LibcameraCompletion> completions_;
  std::vector<std::thread::id> threads_;
  bool disconnected_ = false;
};

LibcameraStreamConfig r16Config() {
  LibcameraStreamConfig c;
  c.format = kLibcameraR16;
  c.size = {32, 24};
  c.bufferCount = 2;
  return c;
}

void startStream(FakeLibcameraPort& port, Recorder& events,
                 const LibcameraControls& controls = {}) {
  ASSERT_EQ(port.acquire(smallCamera().id, events), 0);
  LibcameraStreamConfig config = r16Config();
  ASSERT_EQ(port.configure(config), 0);
  ASSERT_TRUE(port.allocateBuffers());
  ASSERT_EQ(port.start(controls), 0);
}

TEST(FakeLibcameraPort, SecondAcquireIsBusyAndUnknownIdIsNoDevice) {
  Recorder events;
  FakeLibcameraPort port(smallCamera(), patternFrames());
  EXPECT_EQ(port.acquire("nope", events), -ENODEV);
  EXPECT_EQ(port.acquire(smallCamera().id, events), 0);
  EXPECT_EQ(port.acquire(smallCamera().id, events), -EBUSY);
  port.release();
  EXPECT_EQ(port.acquire(smallCamera().id, events), 0);
}

TEST(FakeLibcameraPort, ValidateAdjustsUnofferedFormatAndSizeAndRefusesUnofferedRole) {
  FakeLibcameraPort port(smallCamera(), patternFrames());
  LibcameraStreamConfig config = r16Config();
  config.format = kLibcameraRGB888;
  config.size = {60, 40};
  EXPECT_EQ(port.validate(config), LibcameraConfigStatus::Adjusted);
  EXPECT_EQ(config.format, kLibcameraR16);
  EXPECT_EQ(config.size, (LibcameraSize{64, 48}));
  EXPECT_EQ(config.strideBytes, 128);
  EXPECT_EQ(port.validate(config), LibcameraConfigStatus::Valid);
  config.role = LibcameraRole::Viewfinder;
  EXPECT_EQ(port.validate(config), LibcameraConfigStatus::Invalid);
}

TEST(FakeLibcameraPort, ConfigureRefusesAnAdjustableConfiguration) {
  Recorder events;
  FakeLibcameraPort port(smallCamera(), patternFrames());
  ASSERT_EQ(port.acquire(smallCamera().id, events), 0);
  LibcameraStreamConfig config = r16Config();
  config.size = {33, 24};
  EXPECT_EQ(port.configure(config), -EINVAL);
}

TEST(FakeLibcameraPort, QueueingABufferAlreadyQueuedIsInvalid) {
  FakeLibcameraCamera camera = smallCamera();
  camera.framePeriodNs = 2'000'000'000;  // after the first frame, the next waits 2 s
  Recorder events;
  FakeLibcameraPort port(camera, patternFrames());
  EXPECT_EQ(port.queueRequest(0, {}), -EACCES);  // not started
  startStream(port, events);
  EXPECT_EQ(port.queueRequest(5, {}), -EINVAL);  // no such buffer
  ASSERT_EQ(port.queueRequest(0, {}), 0);
  ASSERT_TRUE(events.waitFor(1));
  ASSERT_EQ(port.queueRequest(1, {}), 0);  // pending for 2 s
  EXPECT_EQ(port.queueRequest(1, {}), -EINVAL);
  EXPECT_EQ(port.queueRequest(0, {}), 0);  // completed: legal again
}

TEST(FakeLibcameraPort, CompletionsArriveOnAnotherThreadInOrder) {
  Recorder events;
  FakeLibcameraPort port(smallCamera(), patternFrames());
  startStream(port, events);
  ASSERT_EQ(port.queueRequest(0, {}), 0);
  ASSERT_EQ(port.queueRequest(1, {}), 0);
  ASSERT_TRUE(events.waitFor(2));
  const auto done = events.completions();
  EXPECT_EQ(done[0].bufferIndex, 0u);
  EXPECT_EQ(done[1].bufferIndex, 1u);
  EXPECT_EQ(done[1].sequence, done[0].sequence + 1);
  for (const auto& id : events.threads()) EXPECT_NE(id, std::this_thread::get_id());
}

TEST(FakeLibcameraPort, StopCancelsPendingRequestsBeforeReturning) {
  FakeLibcameraCamera camera = smallCamera();
  camera.framePeriodNs = 2'000'000'000;  // the second request waits 2 s
  Recorder events;
  FakeLibcameraPort port(camera, patternFrames());
  startStream(port, events);
  ASSERT_EQ(port.queueRequest(0, {}), 0);
  ASSERT_TRUE(events.waitFor(1));
  ASSERT_EQ(port.queueRequest(1, {}), 0);
  ASSERT_EQ(port.stop(), 0);
  const auto done = events.completions();
  ASSERT_EQ(done.size(), 2u);
  EXPECT_TRUE(done[1].requestCancelled);
  EXPECT_EQ(done[1].frameStatus, LibcameraFrameStatus::Cancelled);
}

TEST(FakeLibcameraPort, UnplugNotifiesAndFailsLaterCallsWithNoDevice) {
  Recorder events;
  FakeLibcameraPort port(smallCamera(), patternFrames());
  startStream(port, events);
  port.unplug();
  ASSERT_TRUE(events.waitDisconnected());
  EXPECT_EQ(port.queueRequest(0, {}), -ENODEV);
  EXPECT_EQ(port.stop(), -ENODEV);
  EXPECT_EQ(port.start({}), -ENODEV);
  port.replug();
  EXPECT_EQ(port.start({}), -ENODEV);  // the old camera stays dead until released
  EXPECT_EQ(port.acquire(smallCamera().id, events), -EBUSY);
  port.release();
  EXPECT_EQ(port.acquire(smallCamera().id, events), 0);
}

TEST(FakeLibcameraPort, ControlsAreClampedAndTakeEffectAfterTheSensorDelay) {
  FakeLibcameraCamera camera = smallCamera();
  camera.controlDelayFrames = 2;
  Recorder events;
  FakeLibcameraPort port(camera, patternFrames());
  LibcameraControls first;
  first.exposureTimeUs = 1000;
  startStream(port, events, first);
  LibcameraControls big;
  big.exposureTimeUs = 10'000'000;  // above the sensor's 200 ms
  big.analogueGain = 0.5f;          // below its unity
  for (std::size_t k = 0; k < 5; ++k) {
    ASSERT_EQ(port.queueRequest(k % 2, k == 0 ? big : LibcameraControls{}), 0);
    ASSERT_TRUE(events.waitFor(k + 1));
  }
  const auto done = events.completions();
  EXPECT_EQ(*done[0].exposureTimeUs, 1000);
  EXPECT_EQ(*done[1].exposureTimeUs, 1000);
  EXPECT_EQ(*done[2].exposureTimeUs, camera.maxExposureUs);
  EXPECT_EQ(*done[2].analogueGain, camera.minGain);
  EXPECT_EQ(*done[4].exposureTimeUs, camera.maxExposureUs);
}

}  // namespace
}  // namespace vem::cameras::testing
