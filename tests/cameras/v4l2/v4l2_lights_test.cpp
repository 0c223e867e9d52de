// End to end: frames of a simulated calibrated camera, written as Y12 by the fake driver, read by
// V4l2Source and turned into lights, give bit for bit the lights of the same frames fed to the
// pipeline directly. Catches any pixel, order, seq or exposure the backend gets wrong.
#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "calib/io/camera_file.h"
#include "cameras/v4l2/v4l2_source_fixtures.h"
#include "support/test_cameras.h"
#include "support/test_maps.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::testing {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 128;
constexpr int kFrames = 12;

std::vector<vem::RawFrame> skyFrames(const calib::CameraCalibration& camera) {
  const EnvMap sky = proceduralSky(MapLayout::Sphere, 128, 64);
  std::vector<vem::RawFrame> frames;
  for (int i = 0; i < kFrames; ++i) {
    calib::SimulationOptions options;
    options.supersamples = 1;
    options.exposureUs = 1000.0;
    options.noise = {2.0, 0.0, std::uint64_t(i) + 1};
    frames.push_back(
        calib::simulateFrame(calib::radianceFromMap(rotatedColumns(sky, 3 * i)), camera, options));
  }
  return frames;
}

vem::ProcessingOptions smallProcessing() {
  vem::ProcessingOptions o;
  o.mapWidth = 256;
  o.mapHeight = 64;
  o.lightCount = 64;
  o.clusterBudget = 16;
  return o;
}

void expectSameLights(const LightSet& a, const LightSet& b, int frame) {
  ASSERT_EQ(a.lights.size(), b.lights.size()) << "frame " << frame;
  EXPECT_EQ(a.luminanceSr, b.luminanceSr) << "frame " << frame;
  EXPECT_EQ(a.black, b.black);
  for (std::size_t k = 0; k < a.lights.size(); ++k) {
    EXPECT_EQ(a.lights[k].id, b.lights[k].id);
    EXPECT_EQ(a.lights[k].dir, b.lights[k].dir) << "frame " << frame << " light " << k;
    EXPECT_EQ(a.lights[k].rgb, b.lights[k].rgb) << "frame " << frame << " light " << k;
  }
}

TEST(V4l2Lights, LightsThroughTheFakeDriverEqualLightsFromTheFramesDirectly) {
  const calib::CameraCalibration camera = cameraTruth(kWidth, kHeight, 1);
  ASSERT_EQ(camera.camera.pixelFormat, (vem::PixelFormat{1, 12}));
  const std::string toml = calib::io::formatCameraFile(camera);
  const std::vector<vem::RawFrame> frames = skyFrames(camera);

  FakeV4l2Camera fake(fakeConfig(V4L2_PIX_FMT_Y12, kWidth, kHeight, 256));
  cameras::CameraSettings settings = settingsFor("Mono12", kWidth, kHeight);
  settings.exposureUs = 1000.0;
  settings.gain = 1.0;
  settings.calibrationToml = toml;
  auto source = openSource(fake, settings);
  ASSERT_TRUE(source);

  auto throughDriver =
      vemd::pipelineFromCameraFile(source->describe().calibrationToml, "v4l2", smallProcessing());
  auto direct = vemd::pipelineFromCameraFile(toml, "direct", smallProcessing());
  ASSERT_TRUE(throughDriver) << throughDriver.error();
  ASSERT_TRUE(direct) << direct.error();

  for (int i = 0; i < kFrames; ++i) {
    ASSERT_TRUE(fake.pushFrame(fakeFrame(fake, frames[std::size_t(i)].codes)));
    auto captured = source->next();
    ASSERT_TRUE(captured) << captured.error().message;
    ASSERT_EQ(throughDriver->frameProblem(captured->frame), std::nullopt);
    const vem::CapturedFrame fed{frames[std::size_t(i)], std::uint64_t(i), captured->captureTsNs,
                                 captured->arrivalNs};
    EXPECT_EQ(captured->seq, fed.seq);
    EXPECT_EQ(captured->frame.exposureUs, fed.frame.exposureUs);
    EXPECT_EQ(captured->frame.gain, fed.frame.gain);
    const vem::ProcessedFrame& a = throughDriver->process(*captured);
    const vem::ProcessedFrame& b = direct->process(fed);
    expectSameLights(a.lights, b.lights, i);
    ASSERT_EQ(a.filtered.has_value(), b.filtered.has_value());
    if (a.filtered) expectSameLights(*a.filtered, *b.filtered, i);
    source->recycle(std::move(*captured));
  }
}

}  // namespace
}  // namespace vem::testing
