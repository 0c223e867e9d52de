// V4l2Source against the fake camera: formats end to end, metadata, controls, buffers, refusals.
#include <gtest/gtest.h>

#include "cameras/v4l2/v4l2_source_fixtures.h"

namespace vem::testing {
namespace {

using cameras::V4l2Source;

struct SourceFormat {
  std::uint32_t fourcc;
  const char* asked;
  vem::PixelFormat output;
  int bits;  // of the codes written
};

class V4l2SourceFormats : public ::testing::TestWithParam<SourceFormat> {};

// Each format through QUERYCAP .. STREAMON, DQBUF and the unpacker, with rows padded to 64 bytes.
TEST_P(V4l2SourceFormats, PixelsArriveExactlyThroughTheDriverAtPaddedStride) {
  const SourceFormat p = GetParam();
  FakeV4l2Camera camera(fakeConfig(p.fourcc, 24, 6, 64));
  auto source = openSource(camera, settingsFor(p.asked, 24, 6));
  ASSERT_TRUE(source);
  ASSERT_GT(camera.format().bytesperline, cameras::packedRowBytes(p.fourcc, 24));
  const auto codes = randomCodes(std::size_t(24 * 6 * p.output.channels), p.bits, p.fourcc);
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, codes)));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(frame->frame.format, p.output);
  EXPECT_EQ(frame->frame.width, 24);
  EXPECT_EQ(frame->frame.height, 6);
  EXPECT_EQ(frame->frame.codes, codes);
  EXPECT_EQ(source->describe().pixelFormat, p.output);
}

INSTANTIATE_TEST_SUITE_P(Formats, V4l2SourceFormats,
                         ::testing::Values(SourceFormat{V4L2_PIX_FMT_Y16, "Mono16", {1, 16}, 16},
                                           SourceFormat{V4L2_PIX_FMT_Y16_BE, "Mono16", {1, 16}, 16},
                                           SourceFormat{V4L2_PIX_FMT_Y12, "Mono12", {1, 12}, 12},
                                           SourceFormat{
                                               cameras::kV4l2PixFmtY12P, "Mono12", {1, 12}, 12},
                                           SourceFormat{V4L2_PIX_FMT_Y10, "Mono10", {1, 10}, 10},
                                           SourceFormat{V4L2_PIX_FMT_Y10P, "Mono10", {1, 10}, 10},
                                           SourceFormat{V4L2_PIX_FMT_Y10BPACK, "", {1, 10}, 10},
                                           SourceFormat{V4L2_PIX_FMT_GREY, "Mono8", {1, 8}, 8},
                                           SourceFormat{V4L2_PIX_FMT_RGB24, "RGB8", {3, 8}, 8}),
                         [](const auto& param) {
                           std::string name = cameras::fourccName(param.param.fourcc);
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(V4l2Source, YuyvGivesRgb8OrMono8AsTheSettingsAsk) {
  for (const char* asked : {"RGB8", "Mono8"}) {
    FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_YUYV, 2, 1));
    auto source = openSource(camera, settingsFor(asked, 2, 1));
    ASSERT_TRUE(source);
    ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, {235, 128, 16, 128})));
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    const std::vector<std::uint16_t> expected =
        std::string(asked) == "RGB8" ? std::vector<std::uint16_t>{255, 255, 255, 0, 0, 0}
                                     : std::vector<std::uint16_t>{235, 16};
    EXPECT_EQ(frame->frame.codes, expected) << asked;
  }
}

TEST(V4l2Source, NoPixelFormatPicksTheDeepestTheCameraOffers) {
  FakeV4l2Config config = fakeConfig(V4L2_PIX_FMT_YUYV, 8, 4);
  config.formats.push_back({V4L2_PIX_FMT_Y12, {{8, 4}}});
  config.formats.push_back({V4L2_PIX_FMT_GREY, {{8, 4}}});
  FakeV4l2Camera camera(config);
  auto source = openSource(camera, settingsFor("", 0, 0));
  ASSERT_TRUE(source);
  EXPECT_EQ(camera.format().pixelformat, V4L2_PIX_FMT_Y12);
  EXPECT_EQ(source->describe().pixelFormat, (vem::PixelFormat{1, 12}));
}

TEST(V4l2Source, NoSizeTakesTheLargestTheDriverLists) {
  FakeV4l2Config config;
  config.formats = {{V4L2_PIX_FMT_Y16, {{320, 240}, {1280, 1024}, {640, 480}}}};
  FakeV4l2Camera camera(config);
  auto source = openSource(camera, settingsFor("Mono16", 0, 0));
  ASSERT_TRUE(source);
  EXPECT_EQ(source->describe().sensorWidthPx, 1280);
  EXPECT_EQ(source->describe().sensorHeightPx, 1024);
}

TEST(V4l2Source, AtLeastFourBuffersAreRequestedAndAllQueued) {
  {
    FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
    cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
    settings.buffers = 2;
    auto source = openSource(camera, settings);
    ASSERT_TRUE(source);
    ASSERT_EQ(camera.requestedBufferCounts().size(), 1u);
    EXPECT_EQ(camera.requestedBufferCounts().front(), 4u);
    EXPECT_EQ(camera.queuedBuffers(), 4u);
    EXPECT_EQ(camera.mappedBuffers(), 4);
    EXPECT_TRUE(camera.streaming());
  }
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.buffers = 6;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  EXPECT_EQ(camera.requestedBufferCounts().front(), 6u);
  EXPECT_EQ(source->bufferCount(), 6u);
}

// The buffer goes back to the driver before next() returns: the driver never runs dry.
TEST(V4l2Source, EachBufferIsQueuedAgainAsSoonAsItIsCopied) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  for (int i = 0; i < 10; ++i) {
    ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, i))));
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    EXPECT_EQ(camera.queuedBuffers(), 4u);
  }
  EXPECT_EQ(source->counters().completed, 10u);
}

TEST(V4l2Source, BuffersAreUnmappedAndFreedWhenTheSourceGoes) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  source.reset();
  EXPECT_EQ(camera.mappedBuffers(), 0);
  EXPECT_EQ(camera.allocatedBuffers(), 0u);
  EXPECT_FALSE(camera.streaming());
}

TEST(V4l2Source, DriverSequenceGapsShowAsSeqGapsAndCountAsLost) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  std::vector<std::uint64_t> seqs;
  for (std::uint32_t skip : {0u, 0u, 3u, 0u}) {
    FakeFrame f = fakeFrame(camera, randomCodes(32, 16, skip));
    f.sequenceSkip = skip;
    ASSERT_TRUE(camera.pushFrame(f));
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    seqs.push_back(frame->seq);
  }
  EXPECT_EQ(seqs, (std::vector<std::uint64_t>{0, 1, 5, 6}));
  EXPECT_EQ(source->counters().lost, 3u);
}

TEST(V4l2Source, MonotonicDriverTimestampIsTheCaptureTime) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  FakeFrame f = fakeFrame(camera, randomCodes(32, 16, 1));
  f.timestampNs = 123'456'789'000;
  ASSERT_TRUE(camera.pushFrame(f));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(frame->captureTsNs, 123'456'789'000);
  EXPECT_GE(frame->arrivalNs, frame->captureTsNs);
  EXPECT_EQ(source->counters().arrivalStamped, 0u);
  EXPECT_TRUE(source->describe().liveClock);
}

TEST(V4l2Source, TimestampOnAnotherClockIsReplacedByArrivalTime) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  FakeFrame f = fakeFrame(camera, randomCodes(32, 16, 1));
  f.timestampNs = 5'000;  // some other clock's idea of time
  f.timestampClock = V4L2_BUF_FLAG_TIMESTAMP_COPY;
  ASSERT_TRUE(camera.pushFrame(f));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_EQ(frame->captureTsNs, frame->arrivalNs);
  EXPECT_EQ(source->counters().arrivalStamped, 1u);
}

TEST(V4l2Source, ManualExposureAndGainReachTheControlsAndTheFrames) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.exposureUs = 5000.0;
  settings.gain = 2.0;
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  EXPECT_EQ(camera.control(V4L2_CID_EXPOSURE_AUTO), V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(camera.control(V4L2_CID_EXPOSURE_ABSOLUTE), 50);  // 100 us units
  EXPECT_EQ(camera.control(V4L2_CID_GAIN), 64);               // default 32 is unity
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 1))));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_DOUBLE_EQ(frame->frame.exposureUs, 5000.0);
  EXPECT_DOUBLE_EQ(frame->frame.gain, 2.0);
}

TEST(V4l2Source, FramesCarryTheExposureTheCameraKeptNotTheOneAsked) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  ASSERT_TRUE(source->setExposure(5e6, 100.0));  // beyond both ranges: clamped
  EXPECT_EQ(camera.control(V4L2_CID_EXPOSURE_ABSOLUTE), 10000);
  EXPECT_EQ(camera.control(V4L2_CID_GAIN), 255);
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 1))));
  auto frame = source->next();
  ASSERT_TRUE(frame) << frame.error().message;
  EXPECT_DOUBLE_EQ(frame->frame.exposureUs, 1e6);
  EXPECT_DOUBLE_EQ(frame->frame.gain, 255.0 / 32.0);
}

TEST(V4l2Source, ACameraWithoutExposureControlRefusesSetExposureWithASentence) {
  FakeV4l2Config config = fakeConfig(V4L2_PIX_FMT_Y16, 8, 4);
  config.controls.clear();
  FakeV4l2Camera camera(config);
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  auto refused = source->setExposure(1000.0, 1.0);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(),
            "v4l2:/dev/video0: the camera has no exposure control (V4L2_CID_EXPOSURE_ABSOLUTE)");
}

TEST(V4l2Source, FrameRateIsSetThroughSParmAndDescribed) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  cameras::CameraSettings settings = settingsFor("Mono16", 8, 4);
  settings.frameRateHz = 55.0;  // the driver offers 15, 30 and 60
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  EXPECT_DOUBLE_EQ(camera.frameRateHz(), 60.0);
  EXPECT_DOUBLE_EQ(source->describe().nominalRateHz, 60.0);
}

TEST(V4l2Source, DescribeNamesTheCardBusSizeAndCalibration) {
  FakeV4l2Config config = fakeConfig(V4L2_PIX_FMT_Y12, 16, 8);
  config.card = "Insta360 X3";
  config.busInfo = "usb-0000:00:14.0-2";
  FakeV4l2Camera camera(config);
  cameras::CameraSettings settings = settingsFor("Mono12", 16, 8);
  settings.calibrationToml = "format = \"vemcast-camera\"\n";
  auto source = openSource(camera, settings);
  ASSERT_TRUE(source);
  const vem::SourceDescription d = source->describe();
  EXPECT_EQ(d.spec, "v4l2:/dev/video0");
  EXPECT_EQ(d.cameraModel, "Insta360 X3");
  EXPECT_EQ(d.cameraSerial, "usb-0000:00:14.0-2");
  EXPECT_EQ(d.sensorWidthPx, 16);
  EXPECT_EQ(d.sensorHeightPx, 8);
  EXPECT_EQ(d.calibrationToml, settings.calibrationToml);
  EXPECT_DOUBLE_EQ(d.nominalRateHz, 30.0);
  EXPECT_TRUE(d.liveClock);
  EXPECT_TRUE(d.paced);
}

TEST(V4l2Source, AFormatTheDriverReplacesIsRefusedWithOneSentence) {
  FakeV4l2Config config;
  config.formats = {{V4L2_PIX_FMT_YUYV, {{640, 480}}}, {V4L2_PIX_FMT_Y16, {{1280, 1024}}}};
  config.refusedFourccs = {V4L2_PIX_FMT_Y16};
  FakeV4l2Camera camera(config);
  auto source = V4l2Source::open(kFakePath, camera.opener(), settingsFor("Mono16", 1280, 1024));
  ASSERT_FALSE(source);
  EXPECT_EQ(source.error().cause, vem::SourceErrorCause::NoDevice);
  EXPECT_EQ(source.error().message,
            "v4l2:/dev/video0: the camera offers YUYV 640x480, not Y16 1280x1024");
}

TEST(V4l2Source, ASizeTheDriverAdjustsIsRefusedWithOneSentence) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 1280, 1024));
  auto source = V4l2Source::open(kFakePath, camera.opener(), settingsFor("Mono16", 1000, 1000));
  ASSERT_FALSE(source);
  EXPECT_EQ(source.error().message,
            "v4l2:/dev/video0: the camera offers Y16 1280x1024, not Y16 1000x1000");
}

TEST(V4l2Source, AFormatTheCameraLacksIsNamedWithWhatItOffers) {
  FakeV4l2Config config = fakeConfig(V4L2_PIX_FMT_YUYV, 8, 4);
  config.formats.push_back({V4L2_PIX_FMT_MJPEG, {{8, 4}}});
  FakeV4l2Camera camera(config);
  auto source = V4l2Source::open(kFakePath, camera.opener(), settingsFor("Mono16", 8, 4));
  ASSERT_FALSE(source);
  EXPECT_EQ(source.error().message,
            "v4l2:/dev/video0: the camera offers YUYV, MJPG, not Mono16 (Y16, Y16-BE)");
}

TEST(V4l2Source, AMissingDeviceIsNoDeviceNamingTheSpec) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source =
      V4l2Source::open("/dev/video7", camera.opener(kFakePath), settingsFor("Mono16", 8, 4));
  ASSERT_FALSE(source);
  EXPECT_EQ(source.error().cause, vem::SourceErrorCause::NoDevice);
  EXPECT_EQ(source.error().message,
            "v4l2:/dev/video7: cannot open the camera (No such file or directory)");
}

TEST(V4l2Source, RecycledFramesLendTheirStorageToLaterFrames) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 1))));
  auto first = source->next();
  ASSERT_TRUE(first);
  const std::uint16_t* storage = first->frame.codes.data();
  source->recycle(std::move(*first));
  ASSERT_TRUE(camera.pushFrame(fakeFrame(camera, randomCodes(32, 16, 2))));
  auto second = source->next();
  ASSERT_TRUE(second);
  EXPECT_EQ(second->frame.codes.data(), storage);
  EXPECT_EQ(second->frame.codes, randomCodes(32, 16, 2));
}

TEST(V4l2Source, APacedCameraDeliversEveryFrameInOrderAtItsPace) {
  FakeV4l2Camera camera(fakeConfig(V4L2_PIX_FMT_Y16, 8, 4));
  camera.setGenerator(
      [](std::uint64_t index, const v4l2_pix_format& format) {
        FakeFrame f;
        f.bytes = encodeFakeFrame(std::vector<std::uint16_t>(32, std::uint16_t(index)), format);
        return f;
      },
      5'000'000);
  auto source = openSource(camera, settingsFor("Mono16", 8, 4));
  ASSERT_TRUE(source);
  std::int64_t lastTs = 0;
  for (std::uint64_t i = 0; i < 8; ++i) {
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    EXPECT_EQ(frame->seq, i);
    EXPECT_EQ(frame->frame.codes.front(), frame->seq);
    EXPECT_GT(frame->captureTsNs, lastTs);
    if (lastTs > 0) {
      EXPECT_NEAR(double(frame->captureTsNs - lastTs), 5e6, 1e3);
    }
    lastTs = frame->captureTsNs;
  }
}

}  // namespace
}  // namespace vem::testing
