#include "support/test_cameras.h"

#include <cmath>

namespace vem::testing {

calib::PhotometricCalibration logSensorTruth(int channels) {
  calib::PhotometricCalibration p;
  p.blackLevelCode = 64.0;
  p.saturationCode = 4095.0;
  calib::LogResponse log;
  const double b = (4095.0 - 64.0) / std::log(1e8);  // eight decades over the code range
  for (int c = 0; c < 3; ++c) {
    const double tint = channels == 1 ? 1.0 : 1.0 + 0.03 * (c - 1);  // channels differ a little
    log.bCodePerLn[std::size_t(c)] = b * tint;
    log.aCode[std::size_t(c)] = 64.0 + b * tint * std::log(1e3);  // code at 1 cd/m^2
  }
  p.response = log;
  return p;
}

calib::KannalaBrandtLens wideLensTruth(int width, int height) {
  calib::KannalaBrandtLens lens = calib::equidistantLens(width, height, 190.0, 0.46 * height);
  const double f = lens.kPx[0];
  lens.kPx = {f, -0.012 * f, 0.0021 * f, -0.0004 * f, 0.00003 * f};
  lens.principalPointPx += glm::dvec2(3.7, -2.2);
  lens.aspect = 1.0008;
  return lens;
}

calib::CameraCalibration cameraTruth(int width, int height, int channels) {
  calib::CameraCalibration camera;
  camera.camera = {"simulated HDRC", "TRUTH-1", width, height, {channels, 12}};
  camera.photometric = logSensorTruth(channels);
  camera.lens = wideLensTruth(width, height);
  return camera;
}

std::vector<calib::PatchSpec> greyChart(int width, int height) {
  const double luminance[] = {0.5, 4.0, 30.0, 250.0, 2000.0, 20000.0, 10.0, 800.0};
  std::vector<calib::PatchSpec> patches;
  const int size = 24;
  const int step = width / 9;
  for (int i = 0; i < 8; ++i) {
    calib::PatchSpec p;
    p.name = (i < 6 ? "p" : "check") + std::to_string(i < 6 ? i + 1 : i - 5);
    p.x = step / 2 + i * step;
    p.y = height / 2 - size / 2;
    p.width = size;
    p.height = size;
    p.luminanceCdM2 = luminance[i];
    p.check = i >= 6;
    patches.push_back(p);
  }
  return patches;
}

}  // namespace vem::testing
