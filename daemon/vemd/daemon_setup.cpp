#include "vemd/daemon_setup.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "frames/raw_frame.h"
#include "util/printable.h"
#include "vemd/pipeline_setup.h"
#include "vemd/source_factory.h"

namespace vem::vemd {

namespace {

namespace fs = std::filesystem;

// `path` under `dir` when it is relative and a folder is given.
fs::path under(const std::string& dir, const std::string& path) {
  const fs::path p(path);
  return dir.empty() || p.is_absolute() ? p : fs::path(dir) / p;
}

std::optional<std::string> cameraMismatch(const SourceDescription& source,
                                          const calib::CameraIdentity& camera) {
  if (source.sensorWidthPx == camera.sensorWidthPx &&
      source.sensorHeightPx == camera.sensorHeightPx && source.pixelFormat == camera.pixelFormat) {
    return std::nullopt;
  }
  return fmt::format("{}: the frames are {} x {} {} but the calibration is for a {} x {} {} camera",
                     source.spec, source.sensorWidthPx, source.sensorHeightPx,
                     pixelFormatName(source.pixelFormat), camera.sensorWidthPx,
                     camera.sensorHeightPx, pixelFormatName(camera.pixelFormat));
}

// Creates the output folder, so that --out DIR works on a folder that does not exist yet.
std::optional<std::string> outputFolderProblem(const std::string& dir) {
  if (dir.empty()) return std::nullopt;
  std::error_code error;
  fs::create_directories(dir, error);
  if (!error && fs::is_directory(dir)) return std::nullopt;
  return fmt::format("output.dir: cannot use {} as the output folder ({})", dir,
                     error ? error.message() : "it is not a folder");
}

StartupFailure failed(std::string message) {
  return {StartupFailure::Cause::Failed, std::move(message)};
}

StartupFailure stopped(std::string_view step) {
  return {StartupFailure::Cause::Stopped, fmt::format("a stop was requested {}", step)};
}

double mebibytes(std::uint64_t bytes) { return double(bytes) / double(1 << 20); }

}  // namespace

std::string missingOutputRefused(std::string_view problem) {
  return fmt::format(
      "{}; vemd does not run without a configured output unless allowed to "
      "(--allow-missing-outputs, or output.allow_missing = true)",
      problem);
}

std::string missingOutputAllowed(std::string_view problem) {
  return fmt::format("{}; vemd runs without this output (output.allow_missing)", problem);
}

std::uint64_t framesHeld(std::size_t queueDepth) { return 2 * std::uint64_t(queueDepth) + 4; }

std::optional<std::string> frameMemoryProblem(const SourceDescription& source,
                                              std::size_t queueDepth) {
  const std::uint64_t frameBytes =
      std::uint64_t(source.sensorWidthPx) * std::uint64_t(source.sensorHeightPx) *
      std::uint64_t(source.pixelFormat.channels) * sizeof(std::uint16_t);
  if (frameBytes * framesHeld(queueDepth) <= kFrameMemoryBudgetBytes) return std::nullopt;
  std::uint64_t depthThatFits = 0;
  while (frameBytes * framesHeld(depthThatFits + 1) <= kFrameMemoryBudgetBytes) ++depthThatFits;
  const std::string remedy =
      depthThatFits > 0 ? fmt::format("set source.queue_depth to {} or less", depthThatFits)
                        : std::string("use a smaller frame size ([camera] width_px, height_px)");
  return fmt::format(
      "{}: its {} x {} {} frames take {:.1f} MiB each, and with source.queue_depth = {} vemd may "
      "hold {} of them ({:.0f} MiB), above its {:.0f} MiB budget for frames; {}",
      util::printable(source.spec), source.sensorWidthPx, source.sensorHeightPx,
      pixelFormatName(source.pixelFormat), mebibytes(frameBytes), queueDepth,
      framesHeld(queueDepth), mebibytes(frameBytes * framesHeld(queueDepth)),
      mebibytes(kFrameMemoryBudgetBytes), remedy);
}

LoopOptions loopOptions(const VemdConfig& config) {
  LoopOptions loop;
  loop.queueDepth = config.source.queueDepth;
  loop.maxFrames = config.source.frames;
  loop.reportEveryS = config.stats.everyS;
  loop.retryInitial = std::chrono::milliseconds(config.source.retryInitialMs);
  loop.retryMax = std::chrono::milliseconds(config.source.retryMaxMs);
  return loop;
}

SinkConfig sinkConfig(const OutputConfig& output) {
  SinkConfig sinks;
  if (!output.jsonl.empty()) sinks.jsonl = under(output.dir, output.jsonl);
  if (!output.record.empty()) sinks.record = under(output.dir, output.record);
  if (output.previewEvery > 0) {
    sinks.previewDir = output.dir.empty() ? fs::path(".") : fs::path(output.dir);
    sinks.previewEvery = int(output.previewEvery);
  }
  sinks.previewNumbered = output.previewNumbered;
  sinks.previewScale = int(output.previewScale);
  sinks.recordSyncEveryFrames = std::uint32_t(output.recordSyncEvery);
  return sinks;
}

RecordingContext recordingContext(const SourceDescription& source) {
  RecordingContext context;
  context.cameraModel = source.cameraModel;
  context.cameraSerial = source.cameraSerial;
  context.pixelFormat = source.pixelFormat;
  context.widthPx = source.sensorWidthPx;
  context.heightPx = source.sensorHeightPx;
  context.nominalRateHz = source.nominalRateHz;
  context.calibrationToml = source.calibrationToml;
  return context;
}

std::expected<Daemon, StartupFailure> buildDaemon(const VemdConfig& config,
                                                  const ExtraSinks& extraSinks,
                                                  const StopCheck& stopRequested) {
  const auto stop = [&] { return stopRequested && stopRequested(); };
  Daemon daemon;
  spdlog::info("starting: opening the source {}", util::printable(config.source.spec));
  auto source = makeSource(config.source, config.camera, config.bracketing);
  if (stop()) return std::unexpected(stopped("while opening the source"));
  if (!source) return std::unexpected(failed(source.error()));
  daemon.source = std::move(*source);
  const SourceDescription description = daemon.source->describe();
  if (auto problem = frameMemoryProblem(description, config.source.queueDepth)) {
    return std::unexpected(failed(*problem));
  }

  spdlog::info("starting: building the {} x {} polar remap for the {} x {} sensor",
               config.processing.mapWidth, config.processing.mapHeight, description.sensorWidthPx,
               description.sensorHeightPx);
  auto pipeline =
      pipelineFromCameraFile(description.calibrationToml, description.spec + " (its calibration)",
                             config.processing, stopRequested);
  if (stop()) return std::unexpected(stopped("while building the polar remap"));
  if (!pipeline) return std::unexpected(failed(pipeline.error()));
  if (auto mismatch = cameraMismatch(description, pipeline->calibration().camera)) {
    return std::unexpected(failed(*mismatch));
  }
  daemon.pipeline.emplace(std::move(*pipeline));

  if (auto problem = outputFolderProblem(config.output.dir)) {
    return std::unexpected(failed(*problem));
  }
  std::vector<std::string> missing;
  auto sinks = makeSinks(sinkConfig(config.output), recordingContext(description),
                         config.output.allowMissing ? &missing : nullptr);
  if (!sinks) return std::unexpected(failed(missingOutputRefused(sinks.error())));
  for (const std::string& problem : missing) {
    spdlog::warn("{}", util::printable(missingOutputAllowed(problem), 1024));
  }
  for (const auto& sink : *sinks) {
    if (std::string note = sink->note(); !note.empty()) {
      spdlog::info("{}", util::printable(note, 1024));
    }
  }
  const auto closeSinks = [&] {
    for (auto& sink : *sinks) (void)sink->close();  // a recording already created keeps its index
  };
  if (extraSinks) {
    if (auto added = extraSinks(description, *sinks); !added) {
      closeSinks();
      return std::unexpected(failed(added.error()));
    }
  }
  if (stop()) {
    closeSinks();
    return std::unexpected(stopped("while opening the sinks"));
  }
  daemon.sinks = SinkSet(std::move(*sinks));
  daemon.loop = loopOptions(config);
  return daemon;
}

}  // namespace vem::vemd
