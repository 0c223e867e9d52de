#include "synth/scene_factory.h"

#include <cmath>

#include "synth/cloud_scene.h"
#include "synth/exposure_jump_scene.h"
#include "synth/fluorescent_scene.h"
#include "synth/hdri_scene.h"
#include "synth/sky_scene.h"

namespace vem::synth {
namespace {

constexpr std::string_view kHdriPrefix = "hdri:";

// Each scene's natural rate (scene_factory.h says why each is 30).
constexpr double kSkyRateHz = 30.0;
constexpr double kCloudsRateHz = 30.0;
constexpr double kFluorescentRateHz = 30.0;  // the 100 Hz ripple aliases to 10 Hz: 3 frames
constexpr double kExposureJumpRateHz = 30.0;
constexpr double kHdriRateHz = 30.0;

std::expected<std::unique_ptr<SyntheticScene>, std::string> makeHdriScene(
    std::string_view file, const SceneOptions& options) {
  if (!options.hdri || options.hdri->width <= 0 || options.hdri->height <= 0) {
    return std::unexpected("scene 'hdri:" + std::string(file) +
                           "' needs its map loaded (the caller reads the file)");
  }
  if (!(options.hdriScale > 0.0) || !std::isfinite(options.hdriScale)) {
    return std::unexpected("scene 'hdri:" + std::string(file) +
                           "': the map's scale must be a positive number");
  }
  HdriParams params;
  params.scale = options.hdriScale;
  params.panDegPerS = options.hdriPanDegPerS;
  return std::make_unique<HdriScene>(*options.hdri, std::string(file), params);
}

}  // namespace

std::optional<std::string_view> hdriFileOf(std::string_view spec) {
  if (!spec.starts_with(kHdriPrefix) || spec.size() == kHdriPrefix.size()) return std::nullopt;
  return spec.substr(kHdriPrefix.size());
}

std::optional<double> naturalRateHz(std::string_view spec) {
  if (spec == "sky") return kSkyRateHz;
  if (spec == "clouds") return kCloudsRateHz;
  if (spec == "fluorescent") return kFluorescentRateHz;
  if (spec == "exposure-jump") return kExposureJumpRateHz;
  if (hdriFileOf(spec)) return kHdriRateHz;
  return std::nullopt;
}

std::expected<std::unique_ptr<SyntheticScene>, std::string> makeScene(std::string_view spec,
                                                                      const SceneOptions& options) {
  if (spec == "sky") return std::make_unique<SkyScene>();
  if (spec == "clouds") {
    CloudParams params;
    params.seed = options.seed;
    return std::make_unique<CloudScene>(params);
  }
  if (spec == "fluorescent") return std::make_unique<FluorescentScene>();
  if (spec == "exposure-jump") return std::make_unique<ExposureJumpScene>();
  if (const auto file = hdriFileOf(spec)) return makeHdriScene(*file, options);
  if (spec.starts_with(kHdriPrefix)) {
    return std::unexpected(std::string("scene 'hdri:' names no file (expected hdri:FILE)"));
  }
  return std::unexpected("unknown scene '" + std::string(spec) + "' (expected one of " +
                         std::string(kSceneNames) + ")");
}

}  // namespace vem::synth
