#include "fake_frame_generators.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "synth/scene_factory.h"
#include "synth/synthetic_camera.h"

namespace vem::cameras::testing {

namespace {

struct SyntheticRig {
  std::unique_ptr<synth::SyntheticScene> scene;
  synth::SyntheticCamera camera;
  double rateHz;

  void render(const FakeFrameParams& params, vem::RawFrame& frame) {
    synth::SceneState state = scene->at(double(params.sequence) / rateHz);
    state.exposureUs = params.exposureUs;
    state.gain = params.gain;
    camera.render(state, params.sequence, frame);
  }
};

std::shared_ptr<SyntheticRig> makeRig(const calib::CameraCalibration& camera,
                                      const std::string& sceneName, double rateHz) {
  auto scene = synth::makeScene(sceneName, {});
  if (!scene) {
    std::fprintf(stderr, "syntheticFrames: %s\n", scene.error().c_str());
    std::abort();
  }
  return std::make_shared<SyntheticRig>(
      SyntheticRig{std::move(*scene), synth::SyntheticCamera(camera), rateHz});
}

}  // namespace

std::uint16_t patternCode(const FakeFrameParams& params, vem::PixelFormat format, int u, int v,
                          int channel) {
  const std::uint64_t mixed = std::uint64_t(u) * 7 + std::uint64_t(v) * 131 +
                              std::uint64_t(channel) * 1009 + std::uint64_t(params.sequence) * 37 +
                              std::uint64_t(std::llround(params.exposureUs)) * 3 +
                              std::uint64_t(std::llround(params.gain * 16.0));
  return std::uint16_t(mixed % (std::uint64_t(format.maxCode()) + 1));
}

FakeFrameGenerator patternFrames() {
  return [](const FakeFrameParams& params, vem::RawFrame& frame) {
    for (int v = 0; v < frame.height; ++v) {
      for (int u = 0; u < frame.width; ++u) {
        for (int c = 0; c < frame.format.channels; ++c) {
          frame.codes[frame.index(u, v, c)] = patternCode(params, frame.format, u, v, c);
        }
      }
    }
  };
}

FakeFrameGenerator syntheticFrames(const calib::CameraCalibration& camera, const std::string& scene,
                                   double rateHz) {
  std::shared_ptr<SyntheticRig> rig = makeRig(camera, scene, rateHz);
  return [rig](const FakeFrameParams& params, vem::RawFrame& frame) { rig->render(params, frame); };
}

}  // namespace vem::cameras::testing
