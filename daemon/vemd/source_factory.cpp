#include "vemd/source_factory.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "cameras/aravis/aravis_source.h"
#include "cameras/bracketing/bracketing_source.h"
#include "cameras/libcamera/libcamera_source.h"
#include "cameras/v4l2/v4l2_source.h"
#include "vemd/replay_source.h"
#include "vemd/synthetic_source.h"

namespace vem::vemd {

namespace {

constexpr const char* kExpectedSpec =
    "replay:FILE.vem, synthetic:SCENE, aravis:ID, v4l2:DEVICE or libcamera:ID";

struct KindName {
  std::string_view name;
  SourceSpec::Kind kind;
  const char* argument;  // what must follow the colon, for the message
};
constexpr KindName kKinds[] = {
    {"replay", SourceSpec::Kind::Replay, "a file"},
    {"synthetic", SourceSpec::Kind::Synthetic, "a scene"},
    {"aravis", SourceSpec::Kind::Aravis, "a camera id or IP address"},
    {"v4l2", SourceSpec::Kind::V4l2, "a device path or name"},
    {"libcamera", SourceSpec::Kind::Libcamera, "a camera id or index"},
};

bool isLiveCamera(SourceSpec::Kind kind) {
  return kind == SourceSpec::Kind::Aravis || kind == SourceSpec::Kind::V4l2 ||
         kind == SourceSpec::Kind::Libcamera;
}

// The camera file's text, which a live camera needs for its calibration.
std::expected<std::string, std::string> cameraFileText(const SourceConfig& config) {
  if (config.camera.empty()) {
    return std::unexpected(fmt::format(
        "source \"{}\": a live camera needs its camera file (--camera FILE or source.camera; "
        "docs/calibration.md makes one)",
        config.spec));
  }
  std::ifstream in(config.camera, std::ios::binary);
  if (!in) {
    return std::unexpected(
        fmt::format("{}: cannot read the camera file (source.camera)", config.camera));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

cameras::CameraSettings cameraSettings(const CameraConfig& camera, std::string calibrationToml) {
  cameras::CameraSettings s;
  s.pixelFormat = camera.pixelFormat;
  s.widthPx = int(camera.widthPx);
  s.heightPx = int(camera.heightPx);
  if (camera.exposureUs > 0.0) s.exposureUs = camera.exposureUs;
  if (camera.gain > 0.0) s.gain = camera.gain;
  if (camera.frameRateHz > 0.0) s.frameRateHz = camera.frameRateHz;
  s.buffers = int(camera.buffers);
  s.timeoutMs = camera.timeoutMs;
  s.calibrationToml = std::move(calibrationToml);
  return s;
}

template <typename Source>
std::expected<std::unique_ptr<FrameSource>, std::string> opened(
    std::expected<std::unique_ptr<Source>, SourceError> source) {
  if (!source) return std::unexpected(source.error().message);
  return std::unique_ptr<FrameSource>(std::move(*source));
}

std::expected<std::unique_ptr<FrameSource>, std::string> openCamera(
    const SourceSpec& spec, const cameras::CameraSettings& settings) {
  switch (spec.kind) {
    case SourceSpec::Kind::Aravis: return opened(cameras::AravisSource::open(spec.argument, settings));
    case SourceSpec::Kind::V4l2: return opened(cameras::V4l2Source::open(spec.argument, settings));
    case SourceSpec::Kind::Libcamera:
      return opened(cameras::LibcameraSource::open(spec.argument, settings));
    default: break;
  }
  return std::unexpected(std::string("not a live camera"));
}

std::expected<std::unique_ptr<FrameSource>, std::string> bracketed(
    std::unique_ptr<FrameSource> camera, const BracketingConfig& b, const CameraConfig& c) {
  cameras::BracketSettings settings;
  settings.count = int(b.count);
  settings.stopsApart = b.stops;
  settings.baseExposureUs = b.baseExposureUs;
  settings.gain = c.gain > 0.0 ? c.gain : 1.0;
  settings.matchTolerance = b.matchTolerance;
  return opened(cameras::BracketingSource::create(std::move(camera), settings));
}

}  // namespace

std::expected<SourceSpec, std::string> parseSourceSpec(std::string_view spec) {
  if (spec.empty()) {
    return std::unexpected(
        fmt::format("no source given: expected --source (or source.spec in the configuration) {}",
                    kExpectedSpec));
  }
  const std::size_t colon = spec.find(':');
  const std::string_view kind = spec.substr(0, colon);
  const std::string_view argument = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  for (const KindName& k : kKinds) {
    if (k.name != kind) continue;
    if (argument.empty()) {
      return std::unexpected(
          fmt::format("source \"{}\": expected {} after \"{}:\"", spec, k.argument, kind));
    }
    return SourceSpec{k.kind, std::string(argument)};
  }
  return std::unexpected(
      fmt::format("source \"{}\": unknown kind \"{}\" (expected {})", spec, kind, kExpectedSpec));
}

std::expected<std::unique_ptr<FrameSource>, std::string> makeSource(
    const SourceConfig& config, const CameraConfig& camera, const BracketingConfig& bracketing) {
  auto spec = parseSourceSpec(config.spec);
  if (!spec) return std::unexpected(spec.error());
  if (bracketing.count > 0 && spec->kind != SourceSpec::Kind::Synthetic &&
      !isLiveCamera(spec->kind)) {
    return std::unexpected(fmt::format(
        "source \"{}\": bracketing.count is {}, but bracketing needs a camera with exposure "
        "control (a live camera or a synthetic scene)",
        config.spec, bracketing.count));
  }
  std::expected<std::unique_ptr<FrameSource>, std::string> source;
  if (spec->kind == SourceSpec::Kind::Replay) {
    source = opened(ReplaySource::open(spec->argument, {config.rate, config.loop}));
  } else if (spec->kind == SourceSpec::Kind::Synthetic) {
    source = opened(SyntheticSource::create(
        spec->argument, {config.rate, config.camera, config.noiseCode, config.seed}));
  } else {
    auto calibration = cameraFileText(config);
    if (!calibration) return std::unexpected(calibration.error());
    source = openCamera(*spec, cameraSettings(camera, std::move(*calibration)));
  }
  if (!source || bracketing.count == 0) return source;
  return bracketed(std::move(*source), bracketing, camera);
}

}  // namespace vem::vemd
