#include "vemd/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/default_pattern.h"
#include "util/contract.h"

namespace vem::vemd {

namespace {

// Microseconds between successive lap() calls.
class StageClock {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double micros = std::chrono::duration<double, std::micro>(now - last_).count();
    last_ = now;
    return micros;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

std::optional<std::string> processingOptionsProblem(const ProcessingOptions& o) {
  if (o.mapWidth < kMinMapSide || o.mapWidth > kMaxMapWidth || o.mapHeight < kMinMapSide ||
      o.mapHeight > kMaxMapHeight) {
    return fmt::format(
        "the polar map must be {} to {} pixels wide and {} to {} high (start-up time and memory "
        "grow with width x height), not {} x {}",
        kMinMapSide, kMaxMapWidth, kMinMapSide, kMaxMapHeight, o.mapWidth, o.mapHeight);
  }
  if (o.lightCount < 1 || o.lightCount > kMaxLights) {
    return fmt::format("the light count must be 1 to {}, not {}", kMaxLights, o.lightCount);
  }
  if (o.clusterBudget < 1) {
    return fmt::format("the cluster budget must be 1 or more, not {}", o.clusterBudget);
  }
  if (!std::isfinite(o.clusterCorrectionFactor) || o.clusterCorrectionFactor <= 0.0) {
    return fmt::format("the cluster correction factor must be a positive number, not {}",
                       o.clusterCorrectionFactor);
  }
  return std::nullopt;
}

std::expected<Pipeline, std::string> Pipeline::create(calib::CameraCalibration calibration,
                                                      const std::string& sourceName,
                                                      const ProcessingOptions& options,
                                                      const std::function<bool()>& stopRequested) {
  if (auto problem = processingOptionsProblem(options)) return std::unexpected(*problem);
  if (!calibration.photometric) {
    return std::unexpected(fmt::format(
        "{}: the camera file has no photometric section (run vemcalib photometric)", sourceName));
  }
  if (!calibration.lens) {
    return std::unexpected(fmt::format(
        "{}: the camera file has no geometric section (run vemcalib fisheye)", sourceName));
  }
  auto remap = calib::buildPolarRemap(*calibration.lens, calibration.orientation,
                                      calibration.camera.sensorWidthPx,
                                      calibration.camera.sensorHeightPx, MapLayout::Hemisphere,
                                      options.mapWidth, options.mapHeight, stopRequested);
  if (!remap) {
    return std::unexpected(fmt::format("{}: stopped while building the {} x {} polar remap",
                                       sourceName, options.mapWidth, options.mapHeight));
  }
  return Pipeline(std::move(calibration), options, std::move(*remap));
}

Pipeline::Pipeline(calib::CameraCalibration calibration, const ProcessingOptions& options,
                   calib::PolarRemap remap)
    : calibration_(std::move(calibration)),
      options_(options),
      remap_(std::move(remap)),
      filter_(presetTaps(options.filter)),
      clusteringParams_{options.clusterBudget, options.clusterCorrectionFactor,
                        MapLayout::Hemisphere} {
  for (const char* stage : kStageNames) result_.timings.push_back({stage, 0.0});
}

std::expected<void, std::string> Pipeline::reconfigure(const ProcessingOptions& options) {
  if (auto problem = processingOptionsProblem(options)) return std::unexpected(*problem);
  if (options.mapWidth != options_.mapWidth || options.mapHeight != options_.mapHeight) {
    remap_ = calib::buildPolarRemap(*calibration_.lens, calibration_.orientation,
                                    calibration_.camera.sensorWidthPx,
                                    calibration_.camera.sensorHeightPx, MapLayout::Hemisphere,
                                    options.mapWidth, options.mapHeight);
  }
  if (options.filter != options_.filter) filter_ = TemporalFilter(presetTaps(options.filter));
  clusteringParams_ = {options.clusterBudget, options.clusterCorrectionFactor,
                       MapLayout::Hemisphere};
  options_ = options;
  return {};
}

std::optional<std::string> Pipeline::frameProblem(const RawFrame& frame) const {
  const calib::CameraIdentity& camera = calibration_.camera;
  if (frame.width != camera.sensorWidthPx || frame.height != camera.sensorHeightPx ||
      frame.format != camera.pixelFormat) {
    return fmt::format("the frame is {} x {} {} but the camera is {} x {} {}", frame.width,
                       frame.height, pixelFormatName(frame.format), camera.sensorWidthPx,
                       camera.sensorHeightPx, pixelFormatName(camera.pixelFormat));
  }
  const std::size_t expected =
      std::size_t(frame.width) * std::size_t(frame.height) * std::size_t(frame.format.channels);
  if (frame.codes.size() != expected) {
    return fmt::format("the frame holds {} codes, not width x height x channels = {}",
                       frame.codes.size(), expected);
  }
  if (frame.format.bits < 16 && !frame.codes.empty()) {
    const std::uint16_t highest = std::ranges::max(frame.codes);
    if (highest > frame.format.maxCode()) {
      return fmt::format("the frame holds code {}, above {}'s largest code {}", highest,
                         pixelFormatName(frame.format), frame.format.maxCode());
    }
  }
  return std::nullopt;
}

const ProcessedFrame& Pipeline::process(const CapturedFrame& captured) {
  VEM_EXPECTS(captured.frame.width == remap_.sensorWidth &&
              captured.frame.height == remap_.sensorHeight &&
              captured.frame.format == calibration_.camera.pixelFormat);
  result_.captured = &captured;
  StageClock clock;
  calibrate(captured.frame);
  result_.timings[0].micros = clock.lap();
  tables_ = buildSamplingTables(polar_, std::move(tables_));
  result_.timings[1].micros = clock.lap();
  sample();
  result_.timings[2].micros = clock.lap();
  filter(captured.seq);
  result_.timings[3].micros = clock.lap();
  cluster();
  result_.timings[4].micros = clock.lap();
  return result_;
}

// Codes to luminance (the table follows exposure and gain), then the fisheye into the polar map.
void Pipeline::calibrate(const RawFrame& frame) {
  const bool sameSettings =
      lutValid_ && lut_.exposureUs == frame.exposureUs && lut_.gain == frame.gain;
  if (!sameSettings) {
    lut_ = calib::buildCodeToLuminanceLut(*calibration_.photometric, frame.format, frame.exposureUs,
                                          frame.gain);
    lutValid_ = true;
    ++lutRebuilds_;
  }
  calib::applyPolarRemap(remap_, frame, lut_, polar_);
  result_.polar = &polar_;
}

void Pipeline::sample() {
  const auto pattern = defaultSamplingPattern(MapLayout::Hemisphere).first(options_.lightCount);
  if (cells_.count != pattern.size() || cellsSampler_ != options_.sampler) {
    cells_ = lightCellsFor(MapLayout::Hemisphere, pattern, options_.sampler);
    cellsSampler_ = options_.sampler;
  }
  result_.lights = generateLights(tables_, pattern, options_.sampler, cells_);
}

// The filter's output stands for the frame delayFrames() ago; a stale seq publishes nothing.
void Pipeline::filter(std::uint64_t seq) {
  FilterResult filtered = filter_.push(seq, result_.lights);
  const auto delay = std::uint64_t(std::llround(filter_.delayFrames()));
  result_.filtered = std::move(filtered.lights);
  result_.filteredSeq = seq >= delay ? seq - delay : 0;
}

void Pipeline::cluster() {
  if (!options_.clustering || !result_.filtered) {
    result_.clustering.reset();
    return;
  }
  result_.clustering = clusterLights(*result_.filtered, clusteringParams_);
}

}  // namespace vem::vemd
