// Frames through the camera path make the same lights as the frames the camera drew: vemd's
// pipeline on AravisSource's frames equals the pipeline on the rendered frames, bit for bit, and
// the lights gather on the synthetic sun.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "aravis_test_rig.h"
#include "cameras/aravis/aravis_source.h"
#include "fake_gv_camera.h"
#include "sky_frames.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::testing {
namespace {

vem::ProcessingOptions smallOptions() {
  vem::ProcessingOptions o;
  o.mapWidth = 256;
  o.mapHeight = 64;
  o.lightCount = 256;
  o.clustering = false;
  return o;
}

// Angle (degrees) from `sun` to the mean direction of the densest knot of lights: the light with
// the most others within 2 degrees, and those others.
double densestKnotOffSunDeg(const LightSet& set, const glm::dvec3& sun) {
  const double cosKnot = std::cos(2.0 * M_PI / 180.0);
  std::vector<glm::dvec3> dirs;
  for (const Light& light : set.lights) dirs.push_back(glm::normalize(glm::dvec3(light.dir)));
  glm::dvec3 best(0.0);
  int bestCount = 0;
  for (const glm::dvec3& centre : dirs) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (const glm::dvec3& d : dirs) {
      if (glm::dot(d, centre) > cosKnot) {
        sum += d;
        ++count;
      }
    }
    if (count > bestCount) {
      bestCount = count;
      best = glm::normalize(sum);
    }
  }
  return std::acos(std::min(1.0, glm::dot(best, sun))) * 180.0 / M_PI;
}

TEST(AravisLights, PipelineOnCameraFramesEqualsPipelineOnTheDrawnFramesAndFindsTheSun) {
  const SkyFrames sky = renderSkyFrames(320, 256, {1, 16}, 3);
  auto fake = FakeGvCamera::start("VEM30", writeFakeGenicam({"Mono16"}));
  ASSERT_TRUE(fake);
  fake->serve(sky.frames);
  cameras::CameraSettings settings = fakeSettings("Mono16", 320, 256, 100.0);
  settings.calibrationToml = sky.cameraToml;
  auto source = cameras::AravisSource::open(kFakeAddress, settings);
  ASSERT_TRUE(source) << source.error().message;
  auto viaCamera =
      vemd::pipelineFromCameraFile((*source)->describe().calibrationToml, "camera", smallOptions());
  auto direct = vemd::pipelineFromCameraFile(sky.cameraToml, "direct", smallOptions());
  ASSERT_TRUE(viaCamera) << viaCamera.error();
  ASSERT_TRUE(direct) << direct.error();

  for (int i = 0; i < 6; ++i) {
    auto got = nextFrame(**source);
    ASSERT_TRUE(got) << got.error().message;
    ASSERT_FALSE(viaCamera->frameProblem(got->frame)) << *viaCamera->frameProblem(got->frame);
    const int index = drawnIndex(got->frame, sky.frames);
    ASSERT_GE(index, 0);
    vem::CapturedFrame drawn = *got;
    drawn.frame = sky.frames[std::size_t(index)];
    drawn.frame.exposureUs = got->frame.exposureUs;
    drawn.frame.gain = got->frame.gain;
    const LightSet camera = viaCamera->process(*got).lights;
    const LightSet truth = direct->process(drawn).lights;
    ASSERT_EQ(camera.lights.size(), truth.lights.size());
    for (std::size_t k = 0; k < truth.lights.size(); ++k) {
      ASSERT_EQ(camera.lights[k].dir, truth.lights[k].dir) << "light " << k;
      ASSERT_EQ(camera.lights[k].rgb, truth.lights[k].rgb) << "light " << k;
    }

    // The densest knot of lights (most neighbours within 2 degrees) sits on the sun.
    EXPECT_LT(densestKnotOffSunDeg(camera, sky.sunDirWorld[std::size_t(index)]), 1.0);
  }
}

}  // namespace
}  // namespace vem::testing
