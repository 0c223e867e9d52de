// `vemtool synth`: a synthetic recording. A scene of vem_synth (docs/synthetic-scenes.md) is
// rendered through a calibrated camera (the built-in example or --camera) frame by frame and
// recorded as raw frames (docs/vem-format.md), with the camera file in the header.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "util/cli_value_names.h"
#include "mapio/map_file.h"
#include "synth/scene_factory.h"
#include "synth/synthetic_camera.h"
#include "synthetic_recording.h"

namespace vem::tool {
namespace {

struct SynthOptions {
  std::string scene;
  int frames = 0;
  std::optional<double> rateHz;  // default: the scene's natural rate (scene_factory.h)
  std::optional<std::string> camera;
  std::string out;
  double startS = 0.0;
  double noiseCode = 0.0;
  std::uint64_t seed = 1;
  int samples = 1;
  double hdriScale = 1.0;
  double panDegPerS = 10.0;
  bool overwrite = false;
};


std::expected<std::unique_ptr<synth::SyntheticScene>, std::string> loadScene(
    const SynthOptions& o) {
  synth::SceneOptions options;
  options.seed = o.seed;
  options.hdriScale = o.hdriScale;
  options.hdriPanDegPerS = o.panDegPerS;
  if (const auto file = synth::hdriFileOf(o.scene)) {
    auto map = mapio::loadMap(std::string(*file));
    if (!map) return std::unexpected(map.error().message);
    options.hdri = std::make_shared<const EnvMap>(std::move(*map));
  }
  return synth::makeScene(o.scene, options);
}

int runSynth(SynthOptions o) {
  const auto scene = loadScene(o);
  if (!scene) return fail(scene.error());
  if (!o.rateHz) o.rateHz = synth::naturalRateHz(o.scene);
  if (!o.rateHz) return fail("scene '" + o.scene + "' has no natural rate: give --rate");
  const auto camera = loadRenderingCamera(o.camera);
  if (!camera) return fail(camera.error());
  if (o.scene == "exposure-jump" &&
      std::holds_alternative<calib::LogResponse>(camera->photometric->response)) {
    spdlog::warn(
        "the camera has a log response, which has no exposure: the jump leaves its codes "
        "unchanged (give --camera a linear camera to see it)");
  }
  auto pending = PendingRecording::create(
      o.out, renderedRecordingHeader(*camera, *o.rateHz, "vemtool synth"), o.overwrite);
  if (!pending) return fail(pending.error());

  synth::SyntheticCamera synthetic(*camera, {o.samples, {o.noiseCode, 0.0, o.seed}});
  RawFrame frame;
  std::chrono::steady_clock::duration rendering{};
  for (int k = 0; k < o.frames; ++k) {
    const auto seq = std::uint64_t(k);
    const double timeS = o.startS + double(k) / *o.rateHz;
    const auto begin = std::chrono::steady_clock::now();
    synthetic.render((*scene)->at(timeS), seq, frame);
    rendering += std::chrono::steady_clock::now() - begin;
    if (auto appended = pending->append(seq, frameTimestampNs(seq, *o.rateHz), frame); !appended) {
      return fail(appended.error());
    }
  }
  if (auto committed = pending->commit(); !committed) return fail(committed.error());

  const calib::CameraIdentity& id = camera->camera;
  const double msPerFrame =
      std::chrono::duration<double, std::milli>(rendering).count() / double(o.frames);
  std::cout << fmt::format(
      "wrote {}: {} frames of scene {} at {:g} Hz (t = {:g} to {:.3f} s) through {} ({} x {} {}), "
      "{} bytes; {:.1f} ms per frame to render\n",
      o.out, o.frames, (*scene)->name(), *o.rateHz, o.startS,
      o.startS + double(o.frames - 1) / *o.rateHz, id.model, id.sensorWidthPx, id.sensorHeightPx,
      pixelFormatName(id.pixelFormat), pending->bytesWritten(), msPerFrame);
  std::cout << fmt::format("next: vemtool export {} --frame 0 --out frame-0.exr\n", o.out);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addSynthCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* cmd = app.add_subcommand(
      "synth", "Record a synthetic scene through a calibrated camera into a VEM recording");
  cmd->footer(fmt::format(
      "Example:\n  vemtool synth --scene sky --frames 60 --out sky.vem\n"
      "  vemtool synth --scene hdri:../shared/data/hdri/park.exr --frames 90 --rate 30 --out "
      "park.vem\n"
      "Scenes: {} (docs/synthetic-scenes.md).\n"
      "Without --rate, frames come at the scene's natural rate, 30 Hz for every scene (the rate\n"
      "the fluorescent room's 100 Hz flicker was tuned for: it aliases to a 3-frame period).\n"
      "Frame k shows the scene at t = start + k / rate seconds and is stamped seq k, k x 1e9 /\n"
      "rate ns. The camera file goes into the header. The recording appears at --out only once\n"
      "complete; on any error nothing is left there.",
      synth::kSceneNames));
  cmd->add_option("--scene", o->scene,
                  "Scene: sky | clouds | hdri:FILE | fluorescent | exposure-jump")
      ->required();
  cmd->add_option("--frames", o->frames, "Number of frames")
      ->required()
      ->type_name(help::rangeName(1, 1000000))
      ->check(help::quiet(CLI::Range(1, 1000000)));
  cmd->add_option("--rate", o->rateHz,
                  "Frames per second (default: the scene's natural rate, 30 Hz for every scene)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--out", o->out, "The recording to write (.vem)")->required();
  cmd->add_option(
      "--camera", o->camera,
      "Camera file to render through (default: the built-in config/camera-example.toml)");
  cmd->add_option("--start", o->startS, "Scene time of the first frame, in seconds (default 0)");
  cmd->add_option("--noise", o->noiseCode, "Gaussian read noise in codes (default 0: exact codes)")
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--seed", o->seed, "Seed of the noise and of the clouds (default 1)");
  cmd->add_option("--samples", o->samples,
                  "Samples per pixel and axis (default 1: each pixel's centre)")
      ->type_name(help::rangeName(1, 8))
      ->check(help::quiet(CLI::Range(1, 8)));
  cmd->add_option("--hdri-scale", o->hdriScale,
                  "hdri:FILE: the map's values times this are cd/m2 (default 1)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--pan", o->panDegPerS, "hdri:FILE: degrees per second it turns (default 10)");
  cmd->add_flag("--overwrite", o->overwrite, "Replace an existing --out");
  cmd->callback([o, &exitCode] { exitCode = runSynth(*o); });
}

}  // namespace vem::tool
