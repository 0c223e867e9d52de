// A camera that vanishes mid-stream and comes back: NoDevice, reopen attempts, resumed stream.
#include <chrono>

#include <gtest/gtest.h>

#include "aravis_test_rig.h"
#include "cameras/aravis/aravis_source.h"
#include "fake_gv_camera.h"
#include "sky_frames.h"

namespace vem::testing {
namespace {

using cameras::AravisSource;
using vem::SourceErrorCause;

TEST(AravisFaults, KilledCameraGivesNoDeviceAndANewCameraOnTheAddressResumesTheStream) {
  const SkyFrames sky = renderSkyFrames(64, 64, {1, 16}, 3);
  const std::string genicam = writeFakeGenicam({"Mono16"});
  auto fake = FakeGvCamera::start("VEM20", genicam);
  ASSERT_TRUE(fake);
  fake->serve(sky.frames);
  cameras::CameraSettings settings = fakeSettings("Mono16", 64, 64, 100.0);
  settings.timeoutMs = 200;
  auto source = AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;
  std::uint64_t lastSeq = 0;
  for (int i = 0; i < 5; ++i) {
    auto got = nextFrame(**source);
    ASSERT_TRUE(got) << got.error().message;
    lastSeq = got->seq;
  }

  fake.reset();  // the camera is gone: no frames, no answers on 127.0.0.1:3956
  std::optional<vem::SourceError> lost;
  for (int i = 0; i < 10 && !lost; ++i) {
    auto got = (*source)->next();
    if (got) {
      lastSeq = got->seq;  // frames already in flight
      continue;
    }
    ASSERT_NE(got.error().cause, SourceErrorCause::BadFrame) << got.error().message;
    if (got.error().cause == SourceErrorCause::NoDevice) lost = got.error();
  }
  ASSERT_TRUE(lost) << "the vanished camera never gave NoDevice";
  EXPECT_TRUE(lost->message.starts_with("aravis:127.0.0.1: ")) << lost->message;

  // While it is away, each next() makes one bounded reopen attempt.
  const auto start = std::chrono::steady_clock::now();
  auto stillGone = (*source)->next();
  ASSERT_FALSE(stillGone);
  EXPECT_EQ(stillGone.error().cause, SourceErrorCause::NoDevice);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(1000));

  fake = FakeGvCamera::start("VEM20", genicam);
  ASSERT_TRUE(fake);
  fake->serve(sky.frames);
  std::optional<vem::CapturedFrame> resumed;
  for (int i = 0; i < 10 && !resumed; ++i) {
    if (auto got = (*source)->next()) resumed = std::move(*got);
  }
  ASSERT_TRUE(resumed) << "no frame after the camera came back";
  EXPECT_GT(resumed->seq, lastSeq);
  EXPECT_GE(drawnIndex(resumed->frame, sky.frames), 0);
  auto following = nextFrame(**source);
  ASSERT_TRUE(following) << following.error().message;
  EXPECT_GT(following->seq, resumed->seq);
  EXPECT_EQ((*source)->counters().reopened, 1u);
}

}  // namespace
}  // namespace vem::testing
