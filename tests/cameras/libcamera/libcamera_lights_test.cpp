// End to end: a synthetic sky through the fake camera, LibcameraSource and vemd's pipeline gives
// bit for bit the lights the same frames give when fed to the pipeline directly, so the backend
// changes nothing in codes, exposure, gain or seq.
#include <gtest/gtest.h>

#include "calib/io/camera_file.h"
#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "cameras/libcamera/libcamera_source.h"
#include "fake_frame_generators.h"
#include "fake_libcamera_port.h"
#include "support/test_cameras.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::cameras {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 128;
constexpr double kRateHz = 30.0;

vem::ProcessingOptions smallOptions() {
  vem::ProcessingOptions o;
  o.mapWidth = 128;
  o.mapHeight = 32;
  o.lightCount = 64;
  o.clustering = false;
  return o;
}

TEST(LibcameraLights, LightsThroughTheFakeCameraEqualLightsFromTheSameFramesDirectly) {
  const calib::CameraCalibration camera = vem::testing::cameraTruth(kWidth, kHeight, 1);  // Mono12
  const std::string toml = calib::io::formatCameraFile(camera);
  testing::FakeLibcameraCamera fakeCamera;
  fakeCamera.formats = {{LibcameraRole::Raw, kLibcameraR12, {{kWidth, kHeight}}}};
  auto port = std::make_unique<testing::FakeLibcameraPort>(
      fakeCamera, testing::syntheticFrames(camera, "sky", kRateHz));
  testing::FakeLibcameraPort* fake = port.get();
  CameraSettings settings;
  settings.calibrationToml = toml;
  auto source = LibcameraSource::open(std::move(port), "0", settings);
  ASSERT_TRUE(source) << source.error().message;

  auto viaCamera =
      vemd::pipelineFromCameraFile((*source)->describe().calibrationToml, "camera", smallOptions());
  auto direct = vemd::pipelineFromCameraFile(toml, "camera", smallOptions());
  ASSERT_TRUE(viaCamera) << viaCamera.error();
  ASSERT_TRUE(direct);
  testing::FakeFrameGenerator reference = testing::syntheticFrames(camera, "sky", kRateHz);

  for (int k = 0; k < 5; ++k) {
    auto captured = (*source)->next();
    ASSERT_TRUE(captured) << captured.error().message;
    ASSERT_FALSE(viaCamera->frameProblem(captured->frame))
        << *viaCamera->frameProblem(captured->frame);
    const auto record = fake->delivered().at(captured->seq);
    vem::CapturedFrame same;
    reference({record.sequence, record.exposureUs, record.gain}, same.frame);
    same.seq = captured->seq;
    ASSERT_EQ(captured->frame.codes, same.frame.codes);

    const vem::ProcessedFrame& a = viaCamera->process(*captured);
    const vem::ProcessedFrame& b = direct->process(same);
    ASSERT_EQ(a.lights.lights.size(), b.lights.lights.size());
    EXPECT_EQ(a.lights.luminanceSr, b.lights.luminanceSr);
    EXPECT_GT(a.lights.luminanceSr, 0.0);
    for (std::size_t i = 0; i < a.lights.lights.size(); ++i) {
      ASSERT_EQ(a.lights.lights[i].dir, b.lights.lights[i].dir) << "light " << i;
      ASSERT_EQ(a.lights.lights[i].rgb, b.lights.lights[i].rgb) << "light " << i;
    }
    ASSERT_EQ(a.filtered.has_value(), b.filtered.has_value());
    if (a.filtered) {
      EXPECT_EQ(a.filtered->luminanceSr, b.filtered->luminanceSr);
    }
  }
}

}  // namespace
}  // namespace vem::cameras
