#include "vemd/synthetic_source.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "calib/io/camera_file.h"
#include "mapio/map_file.h"
#include "synth/default_camera.h"
#include "synth/scene_factory.h"

namespace vem::vemd {

namespace {

constexpr std::size_t kMaxSpareBuffers = 8;

SourceError noDevice(std::string message) {
  return SourceError{SourceErrorCause::NoDevice, std::move(message)};
}

std::expected<std::unique_ptr<synth::SyntheticScene>, std::string> loadScene(
    const std::string& spec, const SyntheticOptions& options) {
  synth::SceneOptions sceneOptions;
  sceneOptions.seed = options.seed;
  if (const auto file = synth::hdriFileOf(spec)) {
    auto map = mapio::loadMap(std::string(*file));
    if (!map) return std::unexpected(map.error().message);
    sceneOptions.hdri = std::make_shared<const EnvMap>(std::move(*map));
  }
  return synth::makeScene(spec, sceneOptions);
}

// The camera file's text and its name in messages.
std::expected<std::pair<std::string, std::string>, std::string> cameraText(
    const std::string& file) {
  if (file.empty()) {
    return std::pair{std::string(synth::exampleCameraToml()),
                     std::string(synth::kExampleCameraSource)};
  }
  auto loaded = calib::io::loadCameraFile(file);
  if (!loaded) return std::unexpected(loaded.error().message);
  // The text the pipeline parses again: the file as vemcalib would write it.
  return std::pair{calib::io::formatCameraFile(*loaded), file};
}

}  // namespace

std::expected<std::unique_ptr<SyntheticSource>, SourceError> SyntheticSource::create(
    const std::string& scene, const SyntheticOptions& options) {
  const std::string spec = "synthetic:" + scene;
  auto made = loadScene(scene, options);
  if (!made) return std::unexpected(noDevice(fmt::format("{}: {}", spec, made.error())));
  auto text = cameraText(options.cameraFile);
  if (!text) return std::unexpected(noDevice(text.error()));
  auto camera = calib::io::parseCameraFile(text->first, text->second);
  if (!camera) return std::unexpected(noDevice(camera.error().message));
  if (auto problem = synth::syntheticCameraProblem(*camera)) {
    return std::unexpected(noDevice(fmt::format("{}: {}", text->second, *problem)));
  }
  return std::unique_ptr<SyntheticSource>(new SyntheticSource(
      spec, std::move(*made), std::move(*camera), std::move(text->first), options));
}

SyntheticSource::SyntheticSource(std::string spec, std::unique_ptr<synth::SyntheticScene> scene,
                                 calib::CameraCalibration camera, std::string cameraToml,
                                 const SyntheticOptions& options)
    : spec_(std::move(spec)),
      scene_(std::move(scene)),
      cameraToml_(std::move(cameraToml)),
      options_(options),
      camera_(std::move(camera), {1, {options.readNoiseCode, 0.0, options.seed}}),
      schedule_(options.rate.mode == SourceRate::Mode::Max ? -1 : std::llround(1e9 / rateHz())) {}

double SyntheticSource::rateHz() const {
  return options_.rate.mode == SourceRate::Mode::Fixed ? options_.rate.hz
                                                       : SyntheticOptions::kNominalRateHz;
}

SourceDescription SyntheticSource::describe() const {
  const calib::CameraIdentity& id = camera_.calibration().camera;
  SourceDescription d;
  d.spec = spec_;
  d.cameraModel = id.model;
  d.cameraSerial = id.serial;
  d.sensorWidthPx = id.sensorWidthPx;
  d.sensorHeightPx = id.sensorHeightPx;
  d.pixelFormat = id.pixelFormat;
  d.calibrationToml = cameraToml_;
  d.nominalRateHz = rateHz();
  d.liveClock = true;
  d.paced = options_.rate.mode != SourceRate::Mode::Max;
  return d;
}

std::expected<CapturedFrame, SourceError> SyntheticSource::next() {
  if (!rendered_) {
    rendered_.emplace();
    if (!spareCodes_.empty()) {
      rendered_->codes = std::move(spareCodes_.back());
      spareCodes_.pop_back();
    }
    const double timeS = double(seq_) / rateHz();
    camera_.render(scene_->at(timeS), seq_, *rendered_);
    dueNs_ = schedule_.dueNs(0, monotonicNowNs());
  }
  if (!pacer_.sleepUntil(dueNs_)) {
    return std::unexpected(
        SourceError{SourceErrorCause::Timeout,
                    fmt::format("{}: interrupted while waiting for the next frame", spec_)});
  }
  CapturedFrame out;
  out.frame = std::move(*rendered_);
  rendered_.reset();
  out.seq = seq_++;
  out.arrivalNs = monotonicNowNs();
  out.captureTsNs = options_.rate.mode == SourceRate::Mode::Max ? out.arrivalNs : dueNs_;
  return out;
}

void SyntheticSource::recycle(CapturedFrame&& spent) {
  if (spareCodes_.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    spareCodes_.push_back(std::move(spent.frame.codes));
  }
}

void SyntheticSource::interrupt() { pacer_.interrupt(); }

}  // namespace vem::vemd
