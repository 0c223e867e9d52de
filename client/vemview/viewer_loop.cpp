#include "client/vemview/viewer_loop.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "client/render/shading_lights.h"
#include "client/render/tone_mapping.h"
#include "client/scene/orbit_camera.h"
#include "client/vemview/adaptive_light_count.h"
#include "client/vemview/composite_frame_renderer.h"
#include "client/vemview/composite_setup.h"
#include "client/vemview/frame_renderer.h"
#include "client/vemview/frame_writer.h"
#include "client/vemview/light_frame_ring.h"
#include "client/vemview/light_input.h"
#include "client/vemview/render_plan.h"
#include "client/vemview/scene_argument.h"
#include "client/vemview/status_line.h"
#include "client/vemview/video_output.h"

namespace vem::view {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kIdleWait = std::chrono::milliseconds(15);

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::expected<std::unique_ptr<LightInput>, std::string> openInput(const ViewerOptions& o,
                                                                  bool cubeMap, int cubeFacePx) {
  if (!o.connectUrl.empty()) {
    auto security = client::readMqttSecurity(o.mqtt);
    if (!security) return std::unexpected(security.error());
    return openStreamInput(StreamInputOptions{o.connectUrl, o.token, std::move(*security), cubeMap,
                                              2.0, std::uint32_t(cubeFacePx)});
  }
  if (!o.lightFile.empty()) {
    return openLightFileInput(o.lightFile);
  }
  const std::string map = o.mapFile.empty() ? defaultMapPath() : o.mapFile;
  return openMapInput(map,
                      MapInputOptions{std::max<std::size_t>(o.lightCount, 1024), cubeMap,
                                      cubeFacePx});
}

PlanRequest requestFor(const ViewerOptions& o, const InputFacts& facts) {
  PlanRequest request;
  request.lightCount = o.lightCount;
  request.shadowedCount = o.shadowedCount;
  request.shadowMapPx = o.shadowMapPx;
  request.cubeFacePx = o.cubeFacePx;
  request.regions = o.regions;
  request.shadingByRatio = o.shading == ShadingKind::Ratio;
  request.softShadows = o.softShadows;
  request.clusterBudget = o.clusterBudget;
  request.backgroundWanted = o.background;
  request.targetFrameMs = o.targetFrameMs;
  request.inputClustered = facts.clustered;
  request.inputLayout = facts.layout;
  request.inputHasCubeMaps = facts.cubeMaps;
  return request;
}

scene::OrbitCamera cameraFor(const scene::Scene& scene, const ViewerOptions& o) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  return scene::viewingCamera(scene, float(o.azimuthDeg * kDeg), float(o.elevationDeg * kDeg));
}

// Everything one run holds; the loop below moves frames through it.
struct Viewer {
  Viewer(const ViewerOptions& o, RenderPlan p, std::unique_ptr<LightInput> in,
         scene::OrbitCamera startCamera)
      : options(o),
        plan(std::move(p)),
        input(std::move(in)),
        geometry(render::makeLightingGeometry()),
        camera(startCamera) {}

  const ViewerOptions& options;
  RenderPlan plan;
  std::unique_ptr<LightInput> input;
  std::unique_ptr<FrameRenderer> renderer;
  render::LightingGeometry geometry;
  scene::OrbitCamera camera;
  std::uint64_t cameraVersion = 1;
  std::optional<FrameWriter> writer;
  std::optional<VideoOutput> video;
  LightFrameRing recentLights;  // --plate: the light frames a picture may be aligned with
  std::optional<AdaptiveLightCount> adaptive;
  render::ToneSmoother tone{0.5};
  std::optional<FrameState> lastDrawn;
  render::ShadingLights shading;
  RenderedFrame last;
  StatusLine status{Clock::now()};  // restarted when the frame loop begins
};

// How many lights the frame's clusters stand for (0: its lights are not clusters).
std::size_t clusteredFrom(const Viewer& v, const InputFrame& frame, std::size_t count) {
  if (v.plan.lighting.clusterBudget > 0) {
    return std::min(count, frame.lights->lights.size());  // clustered here (--cluster)
  }
  return frame.clusteredFrom;  // clustered by vemd (a light file's "clustered_from"), or 0
}

// One frame: returns false when the run must stop (window closed), an error for a failure.
std::expected<bool, std::string> step(Viewer& v, std::uint64_t frameIndex) {
  const auto frameStart = Clock::now();
  // Headless from a live stream, each frame is a new light frame (waiting up to --timeout); a
  // window polls, so that it stays responsive between light frames.
  // With --plate the plate's pictures pace the run: a stream that stops sending lights leaves the
  // last ones in use (their age in the status line), it does not end the run.
  const bool waitForNew = !v.lastDrawn || (v.options.headless && v.input->facts().live &&
                                           v.options.plate.empty());
  const auto wait = waitForNew ? std::chrono::milliseconds(int(v.options.streamTimeoutSec * 1000))
                               : std::chrono::milliseconds(5);
  std::optional<InputFrame> frame = v.input->next(wait);
  const bool stale = frame && waitForNew && v.lastDrawn && v.input->facts().live &&
                     frame->seq == v.lastDrawn->inputSeq;
  if (!frame || stale) {
    const std::string why = v.input->failure();
    return std::unexpected(why.empty()
                               ? fmt::format("{}: no {}lights arrived within {} s",
                                             v.input->facts().description, stale ? "new " : "",
                                             v.options.streamTimeoutSec)
                               : why);
  }
  const float drag = v.renderer->takeOrbitDragRad();
  const bool orbiting = v.options.orbitDegPerFrame != 0.0 && frameIndex > 0;
  if (drag != 0.0F || orbiting) {
    const double stepRad = orbiting ? v.options.orbitDegPerFrame * std::numbers::pi / 180.0 : 0.0;
    v.camera = scene::orbited(v.camera, drag + float(stepRad));
    ++v.cameraVersion;
  }
  const std::uint64_t ownInput = v.renderer->pollOwnInput();
  std::string lightSync;
  if (!v.options.plate.empty()) {
    // Time alignment: the light frame captured nearest to the picture, within the window.
    v.recentLights.push(*frame);
    if (const std::optional<double> pictureSec = v.renderer->ownInputCaptureUnixSec()) {
      const LightFrameRing::Choice choice =
          v.recentLights.nearest(*pictureSec, v.options.plateSyncWindowSec);
      frame = *choice.frame;
      lightSync = choice.withinWindow
                      ? "nearest"
                      : fmt::format("newest: none within {:.0f} ms",
                                    v.options.plateSyncWindowSec * 1000.0);
    }
  }
  const std::size_t count = v.adaptive ? v.adaptive->count() : v.plan.lighting.lightCount;
  const FrameState state{frame->seq, v.cameraVersion, count, ownInput};
  const FrameDecision decision = decideFrame(v.lastDrawn, state);
  FrameRecord record{frameIndex, frame->seq, decision.redraw, false, {}};
  double shadingMs = 0.0;
  if (decision.lightsChanged) {
    const auto start = Clock::now();
    render::LightingOptions lighting = v.plan.lighting;
    lighting.lightCount = count;
    v.shading = render::buildShadingLights(*frame->lights, v.geometry, lighting);
    shadingMs = msSince(start);
  }
  if (decision.redraw) {
    v.last = v.renderer->render(v.camera, v.shading, *frame);
    const double dtSec =
        1.0 / 30.0;  // tone smoothing in frame time (headless runs are not real time)
    v.tone.update(render::measureLuminance(v.last.image),
                  v.options.headless ? dtSec : msSince(frameStart) / 1000.0);
    v.lastDrawn = state;
    if (v.adaptive) {
      v.adaptive->update(v.last.renderMs);
    }
  }
  const render::ToneParams tone = v.tone.current().value_or(render::ToneParams{});
  record.timing = v.last.timing;
  record.timing["lights"] = v.shading.diffuse.lights.size();
  record.timing["shadowed"] = v.shading.shadowDirs.size();
  record.timing["shading_lights_ms"] = shadingMs;
  if (!lightSync.empty()) record.timing["light_sync"] = lightSync;
  record.timing["render_ms"] = decision.redraw ? v.last.renderMs : 0.0;
  LightCounts counts =
      lightCountsOf(v.shading, clusteredFrom(v, *frame, count), v.plan.lighting.shadowedCount);
  counts.strataShadowMaps = v.last.strataShadowMaps;
  counts.lightAgeSec = v.last.lightAgeSec;
  counts.plateState = v.last.plateState;
  v.status.add(decision.redraw, v.last.renderMs, counts);
  v.renderer->present(tone, v.status.overlay());
  record.displayReferred = v.last.displayReferred;
  if (v.video && decision.redraw) {
    const auto srgb = frameSrgb8(v.last.image, v.last.displayReferred, tone);
    if (auto written = v.video->write(srgb, v.last.image.widthPx, v.last.image.heightPx);
        !written) {
      return std::unexpected(written.error());
    }
  }
  if (v.writer) {
    if (auto written = v.writer->write(record, v.last.image, tone); !written) {
      return std::unexpected(written.error());
    }
  }
  v.status.showPlan(v.plan);
  v.status.maybePrint(Clock::now());
  if (!decision.redraw && !v.options.headless) {
    std::this_thread::sleep_for(kIdleWait);  // nothing changed: do not spin the window loop
  }
  if (v.renderer->ownInputEnded() && v.options.headless) {
    fmt::print(stderr, "vemview: the plate ended after frame {}; stopping\n", frameIndex);
    return false;
  }
  return v.renderer->open();
}

}  // namespace

int runViewer(const ViewerOptions& options) {
  std::optional<FrameWriter> writer;
  if (!options.outDir.empty()) {
    auto opened = FrameWriter::open(options.outDir, options.png, options.exr);
    if (!opened) {
      spdlog::error("{}", opened.error());
      return EXIT_FAILURE;
    }
    writer.emplace(std::move(*opened));
  }
  auto scene = loadSceneArgument(options.scene, options.sceneAllowOutside);
  if (!scene) {
    spdlog::error("{}", scene.error());
    return EXIT_FAILURE;
  }
  const RenderPlan wanted = planFor(*scene, requestFor(options, InputFacts{}));
  auto input = openInput(options, wanted.cubeMap, wanted.cubeFacePx);
  if (!input) {
    spdlog::error("{}", input.error());
    return EXIT_FAILURE;
  }
  std::optional<CompositeSetup> composite;
  if (!options.plate.empty()) {
    const std::optional<InputFrame> first = (*input)->next(
        std::chrono::milliseconds(int(options.streamTimeoutSec * 1000)));
    if (!first) {
      spdlog::error("{}: no lights arrived within {} s", (*input)->facts().description,
                    options.streamTimeoutSec);
      return EXIT_FAILURE;
    }
    auto setup = setUpComposite(options, *scene, *first);
    if (!setup) {
      spdlog::error("{}", setup.error());
      return EXIT_FAILURE;
    }
    composite = std::move(*setup);
  }
  const scene::Scene& drawn = composite ? composite->composition.withObjects : *scene;
  RenderPlan plan = planFor(drawn, requestFor(options, (*input)->facts()));
  if (composite) plan.composite = composite->plan;
  Viewer v(options, std::move(plan), std::move(*input), cameraFor(*scene, options));
  fmt::print(stderr, "vemview: scene {} ({} meshes, {} triangles), input {}\n", scene->name,
             scene->meshes.size(), scene::triangleCount(*scene), v.input->facts().description);
  auto renderer = composite ? makeCompositeFrameRenderer(options, v.plan, composite->composition,
                                                         v.geometry, std::move(composite->plate),
                                                         std::move(composite->view))
                            : makeFrameRenderer(options, v.plan, *scene, v.geometry);
  if (!renderer) {
    spdlog::error("{}", renderer.error());
    return EXIT_FAILURE;
  }
  v.renderer = std::move(*renderer);
  if (const auto capacity = v.renderer->shadowMapCapacity()) {
    v.plan = withShadowMapCapacity(std::move(v.plan), *capacity);  // what the atlas really holds
  }
  fmt::print(stderr, "vemview: renderer {}\n", v.renderer->name());
  v.writer = std::move(writer);
  if (!options.videoFile.empty()) v.video.emplace(options.videoFile);
  if (v.plan.targetFrameMs) {
    v.adaptive.emplace(*v.plan.targetFrameMs, v.plan.lighting.lightCount, 4, 4096);
  }
  v.status = StatusLine(Clock::now());  // rates count from here, not from the set-up
  v.status.showPlan(v.plan);
  for (std::uint64_t i = 0; options.frames == 0 || i < options.frames; ++i) {
    auto going = step(v, i);
    if (!going) {
      spdlog::error("{}", going.error());
      return EXIT_FAILURE;
    }
    if (!*going) {
      break;
    }
  }
  v.status.printSummary(Clock::now(), v.writer ? v.writer->lastPng().string() : std::string());
  return EXIT_SUCCESS;
}

}  // namespace vem::view
