// LibcameraSource (libcamera_source.h) against FakeLibcameraPort: pixels, metadata, timestamps,
// controls, refusals, unplug and replug, bad frames, interrupt.
#include "cameras/libcamera/libcamera_source.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "fake_frame_generators.h"
#include "fake_libcamera_port.h"

namespace vem::cameras {
namespace {

using testing::FakeLibcameraCamera;
using testing::FakeLibcameraPort;
using vem::SourceErrorCause;

constexpr int kWidth = 36;  // rows of 72 bytes in R16: padded to 128 by the fake's stride
constexpr int kHeight = 20;

FakeLibcameraCamera cameraOffering(LibcameraPixelFormat format, LibcameraRole role) {
  FakeLibcameraCamera c;
  c.formats = {{role, format, {{kWidth, kHeight}}}};
  return c;
}

struct Rig {
  FakeLibcameraPort* fake = nullptr;  // owned by the source
  std::unique_ptr<LibcameraSource> source;
};

Rig openRig(FakeLibcameraCamera camera, CameraSettings settings = {},
            testing::FakeFrameGenerator generator = testing::patternFrames()) {
  auto port = std::make_unique<FakeLibcameraPort>(std::move(camera), std::move(generator));
  Rig rig;
  rig.fake = port.get();
  auto opened =
      LibcameraSource::open(std::move(port), rig.fake->listCameras()->front().id, settings);
  if (!opened)
    ADD_FAILURE() << opened.error().message;
  else
    rig.source = std::move(*opened);
  return rig;
}

vem::CapturedFrame nextFrame(LibcameraSource& source) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    auto frame = source.next();
    if (frame) return std::move(*frame);
    if (frame.error().cause != SourceErrorCause::BadFrame) {
      ADD_FAILURE() << frame.error().message;
      break;
    }
  }
  return {};
}

struct FormatCase {
  LibcameraPixelFormat format;
  LibcameraRole role;
  vem::PixelFormat pixel;
};

class LibcameraSourcePixels : public ::testing::TestWithParam<FormatCase> {};

TEST_P(LibcameraSourcePixels, EveryCodeAndTheFramesMetadataArriveExactly) {
  const FormatCase fc = GetParam();
  Rig rig = openRig(cameraOffering(fc.format, fc.role));
  ASSERT_TRUE(rig.source);
  EXPECT_EQ(rig.source->describe().pixelFormat, fc.pixel);
  for (std::uint64_t k = 0; k < 3; ++k) {
    const vem::CapturedFrame got = nextFrame(*rig.source);
    ASSERT_EQ(got.seq, k);
    const auto record = rig.fake->delivered().at(k);
    ASSERT_EQ(got.frame.width, kWidth);
    ASSERT_EQ(got.frame.height, kHeight);
    ASSERT_EQ(got.frame.format, fc.pixel);
    EXPECT_EQ(got.frame.exposureUs, record.exposureUs);
    EXPECT_EQ(got.frame.gain, record.gain);
    const testing::FakeFrameParams params{record.sequence, record.exposureUs, record.gain};
    int wrong = 0;
    for (int v = 0; v < kHeight; ++v) {
      for (int u = 0; u < kWidth; ++u) {
        for (int c = 0; c < fc.pixel.channels; ++c) {
          wrong += got.frame.at(u, v, c) != testing::patternCode(params, fc.pixel, u, v, c);
        }
      }
    }
    EXPECT_EQ(wrong, 0) << "frame " << k;
    EXPECT_EQ(got.captureTsNs, record.monotonicCaptureNs);
    EXPECT_LE(got.captureTsNs, got.arrivalNs);
  }
  EXPECT_EQ(rig.source->counters().completed, 3u);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, LibcameraSourcePixels,
    ::testing::Values(FormatCase{kLibcameraR8, LibcameraRole::Raw, {1, 8}},
                      FormatCase{kLibcameraR10, LibcameraRole::Raw, {1, 10}},
                      FormatCase{kLibcameraR12, LibcameraRole::Raw, {1, 12}},
                      FormatCase{kLibcameraR16, LibcameraRole::Raw, {1, 16}},
                      FormatCase{kLibcameraRGB888, LibcameraRole::VideoRecording, {3, 8}},
                      FormatCase{kLibcameraBGR888, LibcameraRole::Viewfinder, {3, 8}}));

TEST(LibcameraSource, BoottimeStampsAreConvertedToMonotonic) {
  FakeLibcameraCamera camera = cameraOffering(kLibcameraR16, LibcameraRole::Raw);
  camera.clock = LibcameraClock::Boottime;
  camera.boottimeAheadNs = 5'000'000'000;  // 5 s spent suspended
  Rig rig = openRig(camera);
  ASSERT_TRUE(rig.source);
  const vem::CapturedFrame got = nextFrame(*rig.source);
  const auto record = rig.fake->delivered().at(0);
  EXPECT_EQ(record.timestampNs, std::uint64_t(record.monotonicCaptureNs + 5'000'000'000));
  // Clocks read a moment apart: within a millisecond of the true instant, never after arrival.
  EXPECT_NEAR(double(got.captureTsNs), double(record.monotonicCaptureNs), 1e6);
  EXPECT_LE(got.captureTsNs, got.arrivalNs);
}

TEST(LibcameraSource, SettingsControlsGoWithStartAndSetExposureReachesLaterFrames) {
  CameraSettings settings;
  settings.exposureUs = 3000.0;
  settings.gain = 2.0;
  settings.frameRateHz = 25.0;
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw), settings);
  ASSERT_TRUE(rig.source);
  vem::CapturedFrame first = nextFrame(*rig.source);
  EXPECT_EQ(first.frame.exposureUs, 3000.0);
  EXPECT_EQ(first.frame.gain, 2.0);
  EXPECT_EQ(rig.source->describe().nominalRateHz, 25.0);
  ASSERT_TRUE(rig.source->setExposure(800.0, 4.0));
  std::vector<vem::CapturedFrame> later;
  for (int k = 0; k < 10; ++k) later.push_back(nextFrame(*rig.source));
  EXPECT_EQ(later.back().frame.exposureUs, 800.0);
  EXPECT_EQ(later.back().frame.gain, 4.0);
  // Every frame reports what the camera really used (the fake applies controls two frames late).
  const auto records = rig.fake->delivered();
  for (const auto& f : later) EXPECT_EQ(f.frame.exposureUs, records.at(f.seq).exposureUs);
  const auto asked = rig.fake->requestControls();
  EXPECT_EQ(asked.front().aeEnable, std::optional<bool>(false));
  EXPECT_EQ(asked.back().exposureTimeUs, std::optional<std::int32_t>(800));
}

TEST(LibcameraSource, ExposureTheSensorClampedIsReportedNotTheAskedOne) {
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw));
  ASSERT_TRUE(rig.source);
  ASSERT_TRUE(rig.source->setExposure(900'000.0, 1.0));  // the fake sensor stops at 200 ms
  vem::CapturedFrame got;
  for (int k = 0; k < 8; ++k) got = nextFrame(*rig.source);
  EXPECT_EQ(got.frame.exposureUs, 200'000.0);
  EXPECT_FALSE(rig.source->setExposure(-5.0, 1.0));
  EXPECT_FALSE(rig.source->setExposure(100.0, 0.5));
}

TEST(LibcameraSource, WithoutExposureMetadataTheAskedExposureIsReported) {
  FakeLibcameraCamera camera = cameraOffering(kLibcameraR16, LibcameraRole::Raw);
  camera.reportsExposure = false;
  CameraSettings settings;
  settings.exposureUs = 1500.0;
  Rig rig = openRig(camera, settings);
  ASSERT_TRUE(rig.source);
  ASSERT_TRUE(rig.source->setExposure(1500.0, 3.0));
  vem::CapturedFrame got;
  for (int k = 0; k < 6; ++k) got = nextFrame(*rig.source);
  EXPECT_EQ(got.frame.exposureUs, 1500.0);
  EXPECT_EQ(got.frame.gain, 3.0);
}

TEST(LibcameraSource, CameraOfferingNoTakenFormatIsRefusedNamingItsFormats) {
  FakeLibcameraCamera camera;
  camera.formats = {
      {LibcameraRole::VideoRecording, {drmFourcc('Y', 'U', 'Y', 'V'), 0}, {{640, 480}}}};
  auto port = std::make_unique<FakeLibcameraPort>(camera, testing::patternFrames());
  auto opened = LibcameraSource::open(std::move(port), "0", {});
  ASSERT_FALSE(opened);
  EXPECT_EQ(opened.error().cause, SourceErrorCause::NoDevice);
  EXPECT_NE(opened.error().message.find("offers YUYV 640x480"), std::string::npos)
      << opened.error().message;
}

TEST(LibcameraSource, AskedSizeTheCameraAdjustsIsRefusedNotSilentlyChanged) {
  CameraSettings settings;
  settings.widthPx = 40;
  settings.heightPx = 20;
  auto port = std::make_unique<FakeLibcameraPort>(cameraOffering(kLibcameraR16, LibcameraRole::Raw),
                                                  testing::patternFrames());
  auto opened = LibcameraSource::open(std::move(port), "0", settings);
  ASSERT_FALSE(opened);
  EXPECT_NE(opened.error().message.find("cannot deliver R16 40x20"), std::string::npos)
      << opened.error().message;
}

TEST(LibcameraSource, UnknownIdIsRefusedListingTheCameras) {
  auto port = std::make_unique<FakeLibcameraPort>(cameraOffering(kLibcameraR16, LibcameraRole::Raw),
                                                  testing::patternFrames());
  auto opened = LibcameraSource::open(std::move(port), "3", {});
  ASSERT_FALSE(opened);
  EXPECT_NE(opened.error().message.find("0 \"/base/fake/hdr-sensor@10\""), std::string::npos)
      << opened.error().message;
}

TEST(LibcameraSource, CameraHeldByAnotherProgramIsNoDeviceSayingSo) {
  auto port = std::make_unique<FakeLibcameraPort>(cameraOffering(kLibcameraR16, LibcameraRole::Raw),
                                                  testing::patternFrames());
  port->holdElsewhere(true);
  auto opened = LibcameraSource::open(std::move(port), "0", {});
  ASSERT_FALSE(opened);
  EXPECT_EQ(opened.error().cause, SourceErrorCause::NoDevice);
  EXPECT_NE(opened.error().message.find("in use"), std::string::npos) << opened.error().message;
}

TEST(LibcameraSource, UnplugGivesNoDeviceAndReplugResumesWithIncreasingSeq) {
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw));
  ASSERT_TRUE(rig.source);
  std::uint64_t lastSeq = 0;
  for (int k = 0; k < 3; ++k) lastSeq = nextFrame(*rig.source).seq;
  rig.fake->unplug();
  // Frames already completed may still come; then the removal.
  std::expected<vem::CapturedFrame, vem::SourceError> r;
  for (int k = 0; k < 10; ++k) {
    r = rig.source->next();
    if (!r && r.error().cause == SourceErrorCause::NoDevice) break;
    if (r) lastSeq = r->seq;
  }
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().cause, SourceErrorCause::NoDevice);
  EXPECT_NE(r.error().message.find("the camera was removed"), std::string::npos)
      << r.error().message;
  const auto whileGone = rig.source->next();
  ASSERT_FALSE(whileGone);
  EXPECT_EQ(whileGone.error().cause, SourceErrorCause::NoDevice);
  EXPECT_NE(whileGone.error().message.find("not connected"), std::string::npos);
  rig.fake->replug();
  const vem::CapturedFrame resumed = nextFrame(*rig.source);
  EXPECT_GT(resumed.seq, lastSeq);
  EXPECT_EQ(resumed.frame.width, kWidth);
  EXPECT_EQ(rig.source->counters().reopened, 1u);
  EXPECT_EQ(rig.fake->acquisitions(), 2);
}

TEST(LibcameraSource, ErroredFramesAreBadFramesCountedAndTheStreamGoesOn) {
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw));
  ASSERT_TRUE(rig.source);
  (void)nextFrame(*rig.source);
  rig.fake->failFrames(2);
  int bad = 0;
  int good = 0;
  for (int k = 0; k < 12; ++k) {  // frames completed before the failures, the two, then more
    auto r = rig.source->next();
    if (r)
      ++good;
    else if (r.error().cause == SourceErrorCause::BadFrame)
      ++bad;
    else
      ADD_FAILURE() << r.error().message;
  }
  EXPECT_EQ(bad, 2);
  EXPECT_EQ(good, 10);
  EXPECT_EQ(rig.source->counters().bad, 2u);
  EXPECT_EQ(rig.source->counters().completed, 11u);
}

TEST(LibcameraSource, CancelledRequestsAreCountedAndTheCameraIsRestarted) {
  FakeLibcameraCamera camera = cameraOffering(kLibcameraR16, LibcameraRole::Raw);
  camera.framePeriodNs = 2'000'000'000;  // after the first frame the others stay pending
  Rig rig = openRig(camera);
  ASSERT_TRUE(rig.source);
  const std::uint64_t before = nextFrame(*rig.source).seq;
  ASSERT_EQ(rig.fake->stop(), 0);  // the pipeline stopped underneath: pending requests cancelled
  std::optional<vem::CapturedFrame> resumed;
  for (int k = 0; k < 5 && !resumed; ++k) {
    auto r = rig.source->next();
    if (r) resumed = std::move(*r);
  }
  ASSERT_TRUE(resumed);
  EXPECT_EQ(rig.source->counters().reopened, 1u);
  EXPECT_GE(rig.source->counters().bad, 1u);
  EXPECT_GT(resumed->seq, before);
}

TEST(LibcameraSource, SequenceGapsAreCountedAsLost) {
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw));
  ASSERT_TRUE(rig.source);
  const std::uint64_t before = nextFrame(*rig.source).seq;
  // Frames already queued keep their place; the skip applies to the next frame the fake starts.
  rig.fake->skipFrames(3);
  std::uint64_t last = before;
  for (int k = 0; k < 6; ++k) last = nextFrame(*rig.source).seq;
  EXPECT_EQ(rig.source->counters().lost, 3u);
  EXPECT_EQ(last, before + 6 + 3);
}

TEST(LibcameraSource, InterruptWakesAWaitingNextAndTimeoutBoundsIt) {
  FakeLibcameraCamera camera = cameraOffering(kLibcameraR16, LibcameraRole::Raw);
  camera.framePeriodNs = 30'000'000'000;  // after the first frame, none for 30 s
  CameraSettings settings;
  settings.timeoutMs = 20'000;
  Rig rig = openRig(camera, settings);
  ASSERT_TRUE(rig.source);
  (void)nextFrame(*rig.source);
  const auto t0 = std::chrono::steady_clock::now();
  std::thread waker([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    rig.source->interrupt();
  });
  const auto woken = rig.source->next();
  waker.join();
  ASSERT_FALSE(woken);
  EXPECT_EQ(woken.error().cause, SourceErrorCause::Timeout);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));

  CameraSettings quick;
  quick.timeoutMs = 50;
  Rig slow = openRig(camera, quick);
  ASSERT_TRUE(slow.source);
  (void)nextFrame(*slow.source);
  const auto timedOut = slow.source->next();
  ASSERT_FALSE(timedOut);
  EXPECT_EQ(timedOut.error().cause, SourceErrorCause::Timeout);
  EXPECT_NE(timedOut.error().message.find("50 ms"), std::string::npos);
}

TEST(LibcameraSource, RecycledStorageIsReusedAndDescribeNamesTheCamera) {
  CameraSettings settings;
  settings.calibrationToml = "# the camera file";
  Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw), settings);
  ASSERT_TRUE(rig.source);
  vem::CapturedFrame first = nextFrame(*rig.source);
  const std::uint16_t* storage = first.frame.codes.data();
  rig.source->recycle(std::move(first));
  const vem::CapturedFrame second = nextFrame(*rig.source);
  EXPECT_EQ(second.frame.codes.data(), storage);
  const vem::SourceDescription d = rig.source->describe();
  EXPECT_EQ(d.spec, "libcamera:/base/fake/hdr-sensor@10");
  EXPECT_EQ(d.cameraModel, "fake-hdr-sensor");
  EXPECT_EQ(d.cameraSerial, "/base/fake/hdr-sensor@10");
  EXPECT_EQ(d.sensorWidthPx, kWidth);
  EXPECT_EQ(d.calibrationToml, "# the camera file");
  EXPECT_TRUE(d.liveClock);
}

TEST(LibcameraSource, DestroyingWhileFramesFlowStopsCleanly) {
  for (int round = 0; round < 5; ++round) {
    Rig rig = openRig(cameraOffering(kLibcameraR16, LibcameraRole::Raw));
    ASSERT_TRUE(rig.source);
    (void)nextFrame(*rig.source);
    // The fake keeps completing queued requests on its thread while the source goes away.
  }
}

}  // namespace
}  // namespace vem::cameras
