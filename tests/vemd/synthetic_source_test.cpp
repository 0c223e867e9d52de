// SyntheticSource: a scene through a camera file as a live source: frames of the camera's size,
// seq from 0, CLOCK_MONOTONIC timestamps, the camera file as calibration, clear refusals.
#include "vemd/synthetic_source.h"
#include "vemd/pipeline_setup.h"

#include <gtest/gtest.h>

#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

using SyntheticSourceFiles = VemdFiles;
using vemd::SourceRate;

TEST_F(SyntheticSourceFiles, SkySceneGivesLiveFramesOfTheCamerasSizeAndItsCalibration) {
  const fs::path camera = dir_ / "cam.toml";
  ASSERT_TRUE(calib::io::saveCameraFile(smallCamera(), camera));
  vemd::SyntheticOptions options;
  options.rate = {SourceRate::Mode::Max, 0.0};
  options.cameraFile = camera.string();
  auto source = vemd::SyntheticSource::create("sky", options);
  ASSERT_TRUE(source) << source.error().message;
  const vem::SourceDescription d = (*source)->describe();
  EXPECT_EQ(d.spec, "synthetic:sky");
  EXPECT_EQ(d.sensorWidthPx, kSensorWidth);
  EXPECT_EQ(d.sensorHeightPx, kSensorHeight);
  EXPECT_TRUE(d.liveClock);
  EXPECT_FALSE(d.paced);
  EXPECT_EQ(d.nominalRateHz, 30.0);
  auto pipeline = vemd::pipelineFromCameraFile(d.calibrationToml, d.spec, smallProcessing());
  ASSERT_TRUE(pipeline) << pipeline.error();
  std::int64_t lastTs = 0;
  for (std::uint64_t i = 0; i < 3; ++i) {
    auto frame = (*source)->next();
    ASSERT_TRUE(frame) << frame.error().message;
    EXPECT_EQ(frame->seq, i);
    EXPECT_GT(frame->captureTsNs, lastTs);
    EXPECT_LE(frame->captureTsNs, vem::monotonicNowNs());
    lastTs = frame->captureTsNs;
    EXPECT_EQ(pipeline->frameProblem(frame->frame), std::nullopt);
    EXPECT_GT(pipeline->process(*frame).lights.luminanceSr, 0.0);
    (*source)->recycle(std::move(*frame));
  }
}

TEST(SyntheticSource, UnknownSceneIsRefusedNamingTheScenes) {
  auto source = vemd::SyntheticSource::create("forest", {});
  ASSERT_FALSE(source);
  EXPECT_EQ(source.error().cause, vem::SourceErrorCause::NoDevice);
  EXPECT_EQ(source.error().message.rfind("synthetic:forest: ", 0), 0u) << source.error().message;
}

TEST_F(SyntheticSourceFiles, MissingCameraFileIsRefusedWithTheLoadersSentence) {
  vemd::SyntheticOptions options;
  options.cameraFile = (dir_ / "none.toml").string();
  auto source = vemd::SyntheticSource::create("sky", options);
  ASSERT_FALSE(source);
  EXPECT_NE(source.error().message.find("none.toml"), std::string::npos) << source.error().message;
}

TEST_F(SyntheticSourceFiles, PacedSourceIsInterruptible) {
  const fs::path camera = dir_ / "cam.toml";
  ASSERT_TRUE(calib::io::saveCameraFile(smallCamera(), camera));
  vemd::SyntheticOptions options;
  options.rate = {SourceRate::Mode::Fixed, 0.01};  // 100 s between frames
  options.cameraFile = camera.string();
  auto source = vemd::SyntheticSource::create("sky", options);
  ASSERT_TRUE(source);
  ASSERT_TRUE((*source)->next());  // due at once
  (*source)->interrupt();
  auto frame = (*source)->next();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, vem::SourceErrorCause::Timeout);
}

}  // namespace
}  // namespace vem::testing
