#include "sky_frames.h"

#include <cmath>

#include "calib/io/camera_file.h"
#include "support/test_cameras.h"
#include "synth/sky_scene.h"
#include "synth/synthetic_camera.h"

namespace vem::testing {

namespace {

constexpr double kSecondsBetweenFrames = 4.0;

// The 12-bit log truth stretched (or squeezed) to `bits`.
calib::CameraCalibration testCamera(int width, int height, vem::PixelFormat format) {
  calib::CameraCalibration camera = cameraTruth(width, height, format.channels);
  camera.camera.pixelFormat = format;
  const double scale = std::ldexp(1.0, format.bits - 12);
  auto& p = *camera.photometric;
  p.blackLevelCode *= scale;
  p.saturationCode = double(format.maxCode());
  auto& log = std::get<calib::LogResponse>(p.response);
  for (double& a : log.aCode) a *= scale;
  for (double& b : log.bCodePerLn) b *= scale;
  return camera;
}

}  // namespace

SkyFrames renderSkyFrames(int widthPx, int heightPx, vem::PixelFormat format, int count) {
  const calib::CameraCalibration camera = testCamera(widthPx, heightPx, format);
  SkyFrames out;
  out.cameraToml = calib::io::formatCameraFile(camera);
  synth::SyntheticCamera simulated(
      camera, {4, {}});  // 16 samples: the 0.53-degree sun never falls between them
  const synth::SkyScene scene;
  for (int i = 0; i < count; ++i) {
    const synth::SceneState state = scene.at(kSecondsBetweenFrames * i);
    out.frames.push_back(simulated.render(state, std::uint64_t(i)));
    out.sunDirWorld.push_back(*state.sunDirWorld);
  }
  return out;
}

}  // namespace vem::testing
