// AravisSource against Aravis's fake GigE Vision camera on 127.0.0.1 (in the test's own network
// namespace): pixels, metadata, settings, refusals, interrupt, device listing.
#include "cameras/aravis/aravis_source.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "aravis_test_rig.h"
#include "cameras/aravis/aravis_devices.h"
#include "fake_gv_camera.h"
#include "sky_frames.h"

namespace vem::testing {
namespace {

using cameras::AravisSource;
using vem::SourceErrorCause;

struct FormatCase {
  const char* pipelineFormat;  // what vemd asks for
  const char* nativeFormat;    // the only variant the camera offers
};

class AravisFormats : public ::testing::TestWithParam<FormatCase> {};

TEST_P(AravisFormats, FramesCarryTheDrawnPixelsInOrderWithTheirMetadata) {
  const FormatCase c = GetParam();
  const vem::PixelFormat format = *vem::parsePixelFormat(c.pipelineFormat);
  const SkyFrames sky = renderSkyFrames(320, 256, format, 3);
  auto fake = FakeGvCamera::start("VEM01", writeFakeGenicam({"BayerRG8", c.nativeFormat}));
  ASSERT_TRUE(fake);
  fake->serve(sky.frames);
  cameras::CameraSettings settings = fakeSettings(c.pipelineFormat, 320, 256, 100.0);
  settings.exposureUs = 2000.0;
  settings.gain = 2.0;
  auto source = AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;

  int previousIndex = -1;
  vem::CapturedFrame previous;
  for (int i = 0; i < 10; ++i) {
    auto got = nextFrame(**source);
    ASSERT_TRUE(got) << got.error().message;
    const vem::RawFrame& frame = got->frame;
    ASSERT_EQ(frame.format, format);
    ASSERT_EQ(frame.width, 320);
    ASSERT_EQ(frame.height, 256);
    const int index = drawnIndex(frame, sky.frames);
    ASSERT_GE(index, 0) << "frame " << i << " is none of the frames the camera drew";
    EXPECT_LE(got->captureTsNs, got->arrivalNs);
    EXPECT_LT(got->arrivalNs - got->captureTsNs, 500'000'000)
        << "captureTsNs is not CLOCK_MONOTONIC";
    EXPECT_EQ(frame.exposureUs, 2000.0);
    EXPECT_NEAR(frame.gain, 2.0, 2e-3);
    if (previousIndex >= 0) {
      ASSERT_GT(got->seq, previous.seq);
      EXPECT_GT(got->captureTsNs, previous.captureTsNs);
      EXPECT_GE(got->arrivalNs, previous.arrivalNs);
      EXPECT_EQ(std::uint64_t(index - previousIndex + 3) % 3, (got->seq - previous.seq) % 3)
          << "seq does not follow the camera's frame order";
    }
    previousIndex = index;
    previous = *got;
  }
  EXPECT_GE((*source)->counters().completed, 10u);
  EXPECT_EQ((*source)->counters().incomplete, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Wire, AravisFormats,
    ::testing::Values(FormatCase{"Mono8", "Mono8"}, FormatCase{"Mono16", "Mono16"},
                      FormatCase{"Mono12", "Mono12"}, FormatCase{"Mono12", "Mono12Packed"},
                      FormatCase{"Mono12", "Mono12p"}, FormatCase{"Mono10", "Mono10"},
                      FormatCase{"Mono10", "Mono10Packed"}, FormatCase{"Mono10", "Mono10p"},
                      FormatCase{"RGB8", "RGB8"}),
    [](const auto& test) { return std::string(test.param.nativeFormat); });

TEST(AravisSource, DescribeNamesTheCameraItsModeAndRate) {
  auto fake = FakeGvCamera::start("VEM02", writeFakeGenicam({"Mono8", "Mono16"}));
  ASSERT_TRUE(fake);
  cameras::CameraSettings settings = fakeSettings("", 320, 256, 50.0);
  settings.calibrationToml = "# the camera file";
  auto source = AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;
  const vem::SourceDescription d = (*source)->describe();
  EXPECT_EQ(d.spec, "aravis:127.0.0.1");
  EXPECT_EQ(d.cameraModel, "Aravis Fake");
  EXPECT_EQ(d.cameraSerial, "VEM02");
  EXPECT_EQ(d.sensorWidthPx, 320);
  EXPECT_EQ(d.sensorHeightPx, 256);
  EXPECT_EQ(d.pixelFormat, (vem::PixelFormat{1, 16}));  // "" picks the deepest offered
  EXPECT_EQ(d.calibrationToml, "# the camera file");
  EXPECT_NEAR(d.nominalRateHz, 50.0, 1e-9);
  EXPECT_TRUE(d.liveClock);
  EXPECT_TRUE(d.paced);
}

TEST(AravisSource, SeqKeepsIncreasingAcrossTheSixteenBitFrameIdWrap) {
  // Aravis's fake camera starts its ids at 65401, so 200 frames cross 65535 -> 1.
  const SkyFrames sky = renderSkyFrames(64, 64, {1, 8}, 3);
  auto fake = FakeGvCamera::start("VEM03", writeFakeGenicam({"Mono8"}));
  ASSERT_TRUE(fake);
  fake->serve(sky.frames);
  auto source = AravisSource::open(kFakeAddress, fakeSettings("Mono8", 64, 64, 500.0));
  ASSERT_TRUE(source) << source.error().message;
  std::uint64_t first = 0, last = 0;
  for (int i = 0; i < 200; ++i) {
    auto got = nextFrame(**source);
    ASSERT_TRUE(got) << got.error().message;
    if (i > 0) {
      ASSERT_GT(got->seq, last) << "at frame " << i;
    }
    if (i == 0) first = got->seq;
    last = got->seq;
    ASSERT_GE(drawnIndex(got->frame, sky.frames), 0);
    (*source)->recycle(std::move(*got));
  }
  const cameras::AravisCounters counters = (*source)->counters();
  EXPECT_EQ(counters.completed, 200u);
  EXPECT_LE(last - first + 1, counters.completed + counters.lost + counters.incomplete)
      << "seq gaps must be frames counted lost or incomplete";
}

TEST(AravisSource, RecycledFrameStorageIsReusedSoASteadyStreamAllocatesNothing) {
  auto fake = FakeGvCamera::start("VEM04", writeFakeGenicam({"Mono16"}));
  ASSERT_TRUE(fake);
  fake->serve(renderSkyFrames(320, 256, {1, 16}, 1).frames);
  auto source = AravisSource::open(kFakeAddress, fakeSettings("Mono16", 320, 256, 100.0));
  ASSERT_TRUE(source) << source.error().message;
  auto first = nextFrame(**source);
  ASSERT_TRUE(first) << first.error().message;
  const std::uint16_t* storage = first->frame.codes.data();
  (*source)->recycle(std::move(*first));
  auto second = nextFrame(**source);
  ASSERT_TRUE(second) << second.error().message;
  EXPECT_EQ(second->frame.codes.data(), storage);
}

TEST(AravisSource, SetExposureReachesTheCameraAndFramesCarryTheReadBack) {
  auto fake = FakeGvCamera::start("VEM05", writeFakeGenicam({"Mono16"}));
  ASSERT_TRUE(fake);
  fake->serve(renderSkyFrames(320, 256, {1, 16}, 1).frames);
  auto source = AravisSource::open(kFakeAddress, fakeSettings("Mono16", 320, 256, 100.0));
  ASSERT_TRUE(source) << source.error().message;
  ASSERT_TRUE(nextFrame(**source));
  ASSERT_TRUE((*source)->setExposure(2500.0, 4.0));
  int framesUntilApplied = -1;
  for (int i = 0; i < 30 && framesUntilApplied < 0; ++i) {
    auto got = nextFrame(**source);
    ASSERT_TRUE(got) << got.error().message;
    if (got->frame.exposureUs == 2500.0) framesUntilApplied = i;
  }
  ASSERT_GE(framesUntilApplied, 0) << "no frame carried the new exposure";
  auto after = nextFrame(**source);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->frame.exposureUs, 2500.0);
  EXPECT_NEAR(after->frame.gain, 4.0, 4e-3);  // 12.04 dB, to 0.01 dB
  // What the camera itself holds (its registers, as its last frame saw them): us and 1/100 dB.
  EXPECT_EQ(fake->lastExposureRegister(), 2500u);
  EXPECT_EQ(fake->lastGainRegister(), 1204u);
}

TEST(AravisSource, GainOutsideTheCamerasRangeIsRefusedWithASentence) {
  auto fake = FakeGvCamera::start("VEM06", writeFakeGenicam({"Mono16"}));
  ASSERT_TRUE(fake);
  auto source = AravisSource::open(kFakeAddress, fakeSettings("Mono16", 320, 256, 100.0));
  ASSERT_TRUE(source) << source.error().message;
  auto refused = (*source)->setExposure(1000.0, 0.5);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(),
            "aravis:127.0.0.1: gain 0.5 (-6.021 dB) is outside the camera's 0 to 24 dB");
}

TEST(AravisSource, CameraWithOnlyRawGainRefusesAGainButStreamsWithoutOne) {
  // Aravis's built-in description: GainRaw (unitless) and no Gain feature.
  auto fake = FakeGvCamera::start("VEM07", "");
  ASSERT_TRUE(fake);
  fake->serve(renderSkyFrames(320, 256, {1, 16}, 1).frames);
  cameras::CameraSettings settings = fakeSettings("Mono16", 320, 256, 100.0);
  settings.gain = 2.0;
  auto refused = AravisSource::open(kFakeAddress, settings);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().cause, SourceErrorCause::NoDevice);
  EXPECT_EQ(refused.error().message,
            "aravis:127.0.0.1: the camera has no Gain feature in dB or as a factor, so gain 2 "
            "cannot be set");
  settings.gain.reset();
  auto source = AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;
  auto got = nextFrame(**source);
  ASSERT_TRUE(got) << got.error().message;
  EXPECT_EQ(got->frame.gain, 1.0);
}

TEST(AravisSource, PixelFormatTheCameraDoesNotOfferIsRefusedWithASentence) {
  auto fake = FakeGvCamera::start("VEM08", writeFakeGenicam({"Mono8", "Mono16", "BayerRG8"}));
  ASSERT_TRUE(fake);
  auto refused = AravisSource::open(kFakeAddress, fakeSettings("Mono12", 320, 256, 100.0));
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().cause, SourceErrorCause::NoDevice);
  EXPECT_EQ(refused.error().message,
            "aravis:127.0.0.1: the camera offers no pixel format giving Mono12 (it offers Mono8, "
            "Mono16, BayerRG8)");
}

TEST(AravisSource, SizeOffTheCamerasIncrementIsRefusedWithASentence) {
  auto fake = FakeGvCamera::start("VEM09", writeFakeGenicam({"Mono16"}));
  ASSERT_TRUE(fake);
  auto refused = AravisSource::open(kFakeAddress, fakeSettings("Mono16", 1000, 256, 100.0));
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().message,
            "aravis:127.0.0.1: the camera offers widths 16 to 2048 px in steps of 16, not 1000 px");
}

TEST(AravisSource, InterruptWakesANextThatWaitsForASlowCamera) {
  auto fake = FakeGvCamera::start("VEM10", writeFakeGenicam({"Mono8"}));
  ASSERT_TRUE(fake);
  // One frame every 5 s. Where the fake camera is in its period is not ours to know (the
  // first frame may come at once, or a frame may be queued already), so take frames until one had
  // to be waited for: it came on the camera's own schedule, and the next is a whole period away.
  cameras::CameraSettings settings = fakeSettings("Mono8", 64, 64, 0.2);
  settings.timeoutMs = 12'000;
  auto source = AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;
  bool waitedForAFrame = false;
  for (int frame = 0; frame < 3 && !waitedForAFrame; ++frame) {
    const auto asked = std::chrono::steady_clock::now();
    ASSERT_TRUE((*source)->next());
    waitedForAFrame = std::chrono::steady_clock::now() - asked > std::chrono::milliseconds(500);
  }
  ASSERT_TRUE(waitedForAFrame) << "three frames came at once from a 0.2 Hz camera";
  std::thread interrupter([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    (*source)->interrupt();
  });
  const auto start = std::chrono::steady_clock::now();
  auto got = (*source)->next();
  const auto waited = std::chrono::steady_clock::now() - start;
  interrupter.join();
  ASSERT_FALSE(got);
  EXPECT_EQ(got.error().cause, SourceErrorCause::Timeout);
  EXPECT_LT(waited, std::chrono::milliseconds(1500));
}

TEST(AravisSource, AbsentCameraIsNoDeviceWithinTheTimeoutWithoutDiscovery) {
  cameras::CameraSettings settings = fakeSettings("Mono8", 64, 64, 10.0);
  settings.timeoutMs = 300;
  const auto start = std::chrono::steady_clock::now();
  auto refused = AravisSource::open(kFakeAddress, settings);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().cause, SourceErrorCause::NoDevice);
  EXPECT_EQ(refused.error().message,
            "aravis:127.0.0.1: no GigE Vision camera answers at 127.0.0.1 (GVCP, UDP port 3956)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(1000));
}

TEST(AravisDevices, ListsTheFakeCameraWithTheModesTheBackendReads) {
  auto fake = FakeGvCamera::start("VEM11", writeFakeGenicam({"Mono8", "Mono12Packed", "BayerRG8"}));
  ASSERT_TRUE(fake);
  auto devices = cameras::listAravisDevices();
  ASSERT_TRUE(devices) << devices.error();
  const auto it = std::ranges::find(*devices, std::string("aravis:Aravis-Fake-VEM11"),
                                    &cameras::DeviceInfo::spec);
  ASSERT_NE(it, devices->end());
  EXPECT_EQ(it->model, "Aravis Fake");
  EXPECT_EQ(it->serial, "VEM11");
  EXPECT_EQ(it->modes,
            (std::vector<std::string>{"Mono8 2048x2048", "Mono12 2048x2048 (as Mono12Packed)"}));
}

}  // namespace
}  // namespace vem::testing
