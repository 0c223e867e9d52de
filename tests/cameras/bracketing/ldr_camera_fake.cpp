#include "cameras/bracketing/ldr_camera_fake.h"

#include "calib/core/bracket_simulation.h"
#include "calib/io/camera_file.h"
#include "support/test_cameras.h"

namespace vem::testing {

calib::CameraCalibration ldrCamera(int width, int height, int channels, double scaleCdM2) {
  calib::CameraCalibration camera;
  camera.camera = {"simulated LDR", "LDR-1", width, height, {channels, 8}};
  camera.photometric = calib::ldrCameraPhotometric(scaleCdM2);
  camera.lens = wideLensTruth(width, height);
  return camera;
}

LdrFakeCamera::LdrFakeCamera(calib::CameraCalibration camera,
                             std::shared_ptr<const synth::SyntheticScene> scene,
                             LdrFakeOptions options)
    : scene_(std::move(scene)),
      camera_(camera, synth::SyntheticCameraOptions{options.samplesPerAxis, options.noise}),
      toml_(calib::io::formatCameraFile(camera)),
      options_(std::move(options)),
      current_(options_.initialExposureUs, options_.initialGain) {}

vem::SourceDescription LdrFakeCamera::describe() const {
  const calib::CameraIdentity& id = camera_.calibration().camera;
  vem::SourceDescription d;
  d.spec = options_.spec;
  d.cameraModel = id.model;
  d.cameraSerial = id.serial;
  d.sensorWidthPx = id.sensorWidthPx;
  d.sensorHeightPx = id.sensorHeightPx;
  d.pixelFormat = id.pixelFormat;
  d.calibrationToml = toml_;
  d.nominalRateHz = options_.rateHz;
  d.liveClock = true;
  d.paced = false;
  return d;
}

std::expected<void, std::string> LdrFakeCamera::setExposure(double exposureUs, double gain) {
  requests.emplace_back(exposureUs, gain);
  if (refuseRequests) return std::unexpected(options_.spec + ": exposure is locked");
  pending_.emplace_back(seq_ + std::uint64_t(options_.latencyFrames), std::pair{exposureUs, gain});
  return {};
}

std::pair<double, double> LdrFakeCamera::exposureAt(std::uint64_t seq) {
  while (!pending_.empty() && pending_.front().first <= seq) {
    current_ = pending_.front().second;
    pending_.pop_front();
  }
  return current_;
}

std::int64_t LdrFakeCamera::captureTsNs(std::uint64_t seq) const {
  return 1'000'000'000LL + std::int64_t(double(seq) * 1e9 / options_.rateHz);
}

std::expected<vem::CapturedFrame, vem::SourceError> LdrFakeCamera::next() {
  const int call = calls++;
  if (const auto error = errorsAtCall.find(call); error != errorsAtCall.end()) {
    return std::unexpected(error->second);
  }
  while (lostFrames.contains(seq_)) (void)exposureAt(seq_++);  // captured, lost on the way
  auto [exposureUs, gain] = exposureAt(seq_);
  if (const auto o = exposureOverrideUs.find(seq_); o != exposureOverrideUs.end()) {
    exposureUs = o->second;
  }
  synth::SceneState state = scene_->at(timeS(seq_));
  state.exposureUs = exposureUs;
  state.gain = gain;
  vem::CapturedFrame out;
  camera_.render(state, seq_, out.frame);
  out.seq = seq_;
  out.captureTsNs = captureTsNs(seq_);
  out.arrivalNs = out.captureTsNs + 2'000'000;
  ++seq_;
  return out;
}

void LdrFakeCamera::recycle(vem::CapturedFrame&&) { ++recycled; }

}  // namespace vem::testing
