// The per-frame pipeline: determinism (record then replay gives the same lights bit for bit), the
// code table's rebuilds, the stages it reports, and frames it must refuse.
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

#include <cmath>

#include <gtest/gtest.h>

#include "recording/recording_fixtures.h"
#include "recording/recording_reader.h"
#include "vemd/replay_source.h"
#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

vemd::Pipeline smallPipeline(vem::ProcessingOptions options = smallProcessing()) {
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "test camera", options);
  EXPECT_TRUE(pipeline) << (pipeline ? "" : pipeline.error());
  return std::move(*pipeline);
}

struct ReplayedLights {
  std::vector<LightSet> lights, filtered;
  std::vector<std::optional<Clustering>> clusterings;
};

ReplayedLights replayThroughPipeline(const fs::path& path) {
  ReplayedLights out;
  auto source = vemd::ReplaySource::open(path, {{vemd::SourceRate::Mode::Max, 0.0}, false});
  EXPECT_TRUE(source);
  if (!source) return out;
  auto pipeline = vemd::pipelineFromCameraFile((*source)->describe().calibrationToml, path.string(),
                                               smallProcessing());
  EXPECT_TRUE(pipeline);
  if (!pipeline) return out;
  for (;;) {
    auto frame = (*source)->next();
    if (!frame) {
      EXPECT_EQ(frame.error().cause, vem::SourceErrorCause::EndOfStream) << frame.error().message;
      break;
    }
    const vem::ProcessedFrame& p = pipeline->process(*frame);
    out.lights.push_back(p.lights);
    out.filtered.push_back(*p.filtered);
    out.clusterings.push_back(p.clustering);
  }
  return out;
}

using PipelineFiles = VemdFiles;

TEST_F(PipelineFiles, ReplayGivesTheLightsStoredAtRecordingBitForBit) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 12, true);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  const ReadBack stored = readAll(*reader);
  const ReplayedLights replayed = replayThroughPipeline(path);
  ASSERT_EQ(replayed.lights.size(), 12u);
  ASSERT_EQ(stored.frames.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) {
    ASSERT_TRUE(stored.frames[i].lights.has_value());
    EXPECT_TRUE(sameLights(replayed.lights[i], *stored.frames[i].lights)) << "frame " << i;
  }
}

TEST_F(PipelineFiles, ReplayingTwiceGivesIdenticalFilteredAndClusteredLights) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 12, false);
  const ReplayedLights first = replayThroughPipeline(path);
  const ReplayedLights second = replayThroughPipeline(path);
  ASSERT_EQ(first.filtered.size(), 12u);
  ASSERT_EQ(second.filtered.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_TRUE(sameLights(first.lights[i], second.lights[i])) << "frame " << i;
    EXPECT_TRUE(sameLights(first.filtered[i], second.filtered[i])) << "frame " << i;
    ASSERT_TRUE(first.clusterings[i] && second.clusterings[i]);
    EXPECT_TRUE(sameLights(first.clusterings[i]->clusters, second.clusterings[i]->clusters));
    EXPECT_EQ(first.clusterings[i]->clusterOfLight, second.clusterings[i]->clusterOfLight);
  }
}

// A fresh pipeline and one that already saw other frames give the same lights for a frame: the
// only state over time is the temporal filter's.
TEST(Pipeline, FrameLightsDoNotDependOnEarlierFrames) {
  vemd::Pipeline fresh = smallPipeline();
  vemd::Pipeline used = smallPipeline();
  for (int i = 0; i < 5; ++i) (void)used.process(captured(cachedSkyFrame(i), std::uint64_t(i)));
  const vem::CapturedFrame frame = captured(cachedSkyFrame(7), 5);
  const LightSet a = fresh.process(frame).lights;
  const LightSet b = used.process(frame).lights;
  EXPECT_TRUE(sameLights(a, b));
}

TEST(Pipeline, CodeTableIsRebuiltOnlyWhenExposureOrGainChange) {
  vemd::Pipeline pipeline = smallPipeline();
  vem::RawFrame frame = cachedSkyFrame(0);
  (void)pipeline.process(captured(frame, 0));
  (void)pipeline.process(captured(frame, 1));
  EXPECT_EQ(pipeline.lutRebuilds(), 1u);
  frame.exposureUs *= 2.0;
  (void)pipeline.process(captured(frame, 2));
  EXPECT_EQ(pipeline.lutRebuilds(), 2u);
  frame.gain = 2.0;
  (void)pipeline.process(captured(frame, 3));
  (void)pipeline.process(captured(frame, 4));
  EXPECT_EQ(pipeline.lutRebuilds(), 3u);
}

// A linear camera reads twice the luminance from the same codes at half the exposure: a table
// kept from the earlier exposure would give the old map.
TEST(Pipeline, HalvingTheExposureDoublesTheMapOfALinearCamera) {
  calib::CameraCalibration camera = smallCamera();
  calib::PhotometricCalibration linear;
  linear.blackLevelCode = 0.0;
  linear.saturationCode = 4095.0;
  linear.response = calib::LinearResponse{{0.01, 0.01, 0.01}};
  camera.photometric = linear;
  vem::ProcessingOptions options = smallProcessing();
  options.filter = FilterPreset::None;
  auto pipeline =
      vemd::pipelineFromCameraFile(calib::io::formatCameraFile(camera), "linear", options);
  ASSERT_TRUE(pipeline) << pipeline.error();
  vem::RawFrame frame = vem::RawFrame::blank(kSensorWidth, kSensorHeight, {1, 12});
  std::fill(frame.codes.begin(), frame.codes.end(), std::uint16_t(1000));
  const double before = pipeline->process(captured(frame, 0)).lights.luminanceSr;
  frame.exposureUs /= 2.0;
  const double after = pipeline->process(captured(frame, 1)).lights.luminanceSr;
  EXPECT_NEAR(after / before, 2.0, 1e-6);
}

TEST(Pipeline, TimingsNameEveryStageInOrder) {
  vemd::Pipeline pipeline = smallPipeline();
  const vem::ProcessedFrame& p = pipeline.process(captured(cachedSkyFrame(0), 0));
  ASSERT_EQ(p.timings.size(), 5u);
  const char* names[] = {"calibrate", "tables", "lights", "filter", "cluster"};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(p.timings[i].stage, names[i]);
    EXPECT_GE(p.timings[i].micros, 0.0);
  }
}

TEST(Pipeline, ResultCarriesTheMapLightsFilteredSetAndClustering) {
  vemd::Pipeline pipeline = smallPipeline();
  for (int i = 0; i < 6; ++i) {
    // ProcessedFrame borrows the captured frame: keep it alive while p is read.
    const vem::CapturedFrame frame = captured(cachedSkyFrame(i), std::uint64_t(10 + i));
    const vem::ProcessedFrame& p = pipeline.process(frame);
    ASSERT_NE(p.polar, nullptr);
    EXPECT_EQ(p.polar->width, 256);
    EXPECT_EQ(p.polar->height, 64);
    EXPECT_EQ(p.polar->layout, MapLayout::Hemisphere);
    EXPECT_EQ(p.lights.lights.size(), 64u);
    EXPECT_GT(p.lights.luminanceSr, 0.0);
    ASSERT_TRUE(p.filtered.has_value());
    EXPECT_EQ(p.filtered->lights.size(), 64u);
    EXPECT_EQ(p.filteredSeq, std::uint64_t(10 + i >= 4 ? 10 + i - 4 : 0));  // paper9: 4 frames
    ASSERT_TRUE(p.clustering.has_value());
    EXPECT_EQ(p.clustering->clusterOfLight.size(), 64u);
    EXPECT_LT(p.clustering->clusters.lights.size(), 64u);
    EXPECT_EQ(p.captured->seq, std::uint64_t(10 + i));
  }
}

TEST(Pipeline, ClusteringOffGivesNoClustering) {
  vem::ProcessingOptions options = smallProcessing();
  options.clustering = false;
  vemd::Pipeline pipeline = smallPipeline(options);
  EXPECT_FALSE(pipeline.process(captured(cachedSkyFrame(0), 0)).clustering.has_value());
}

TEST(Pipeline, FrameOfAnotherSizeOrFormatIsReportedBeforeProcessing) {
  vemd::Pipeline pipeline = smallPipeline();
  EXPECT_EQ(pipeline.frameProblem(cachedSkyFrame(0)), std::nullopt);
  const vem::RawFrame small = vem::RawFrame::blank(64, 48, {1, 12});
  const auto problem = pipeline.frameProblem(small);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "the frame is 64 x 48 Mono12 but the camera is 320 x 256 Mono12");
  const vem::RawFrame rgb = vem::RawFrame::blank(kSensorWidth, kSensorHeight, {3, 12});
  EXPECT_TRUE(pipeline.frameProblem(rgb));
}

// A code above 4095 in a Mono12 frame would read past the end of the code table.
TEST(Pipeline, CodeAboveTheFormatsLargestIsRefused) {
  vemd::Pipeline pipeline = smallPipeline();
  vem::RawFrame frame = cachedSkyFrame(0);
  frame.codes[1234] = 5000;
  const auto problem = pipeline.frameProblem(frame);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "the frame holds code 5000, above Mono12's largest code 4095");
}

TEST(Pipeline, CalibrationWithoutALensIsRefusedInOneSentence) {
  calib::CameraCalibration camera = smallCamera();
  camera.lens.reset();
  auto pipeline = vemd::pipelineFromCameraFile(calib::io::formatCameraFile(camera), "cam.toml",
                                               smallProcessing());
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error(),
            "cam.toml: the camera file has no geometric section (run vemcalib fisheye)");
}

TEST(Pipeline, MissingCalibrationIsRefused) {
  auto pipeline = vemd::pipelineFromCameraFile("", "replay:x.vem", smallProcessing());
  ASSERT_FALSE(pipeline);
  EXPECT_NE(pipeline.error().find("replay:x.vem: no calibration comes with the frames"),
            std::string::npos);
}

TEST(Pipeline, LightCountOutOfRangeIsRefused) {
  vem::ProcessingOptions options = smallProcessing();
  options.lightCount = 0;
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "cam", options);
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error(), "the light count must be 1 to 65536, not 0");
}

}  // namespace
}  // namespace vem::testing
