#include "client/vemview/viewer_options.h"

#include <map>

#include <CLI/CLI.hpp>

namespace vem::view {
namespace {

void addInputOptions(CLI::App& app, ViewerOptions& o) {
  auto* connect = app.add_option("--connect", o.connectUrl,
                                 "Take lights (and cube maps) from vemd's stream, ws://HOST:PORT");
  app.add_option("--token", o.token, "Bearer token for the stream");
  auto* lights = app.add_option(
      "--lights", o.lightFile, "Take lights from a JSON-lines file (vemd --jsonl, vemtool lights)");
  auto* map = app.add_option("--map", o.mapFile,
                             "Compute lights from an environment map file (.exr, .hdr, .pfm)");
  connect->excludes(lights)->excludes(map);
  lights->excludes(map);
  app.add_option("--scene", o.scene,
                 "Scene file (.obj, .gltf, .glb) or built-in: default, diffuse, spheres, sphere")
      ->capture_default_str();
  app.add_flag("--scene-allow-outside", o.sceneAllowOutside,
               "Let the scene file reference files outside its folder (OBJ mtllib, glTF buffer "
               "and image URIs: absolute paths, file: URIs, '..', links leading out); refused "
               "without it");
}

void addOutputOptions(CLI::App& app, ViewerOptions& o) {
  app.add_flag("--headless", o.headless, "Render without a window (EGL), write --out");
  app.add_option("--frames", o.frames, "Frames to render (0: until the window closes; headless 1)");
  app.add_option("--out", o.outDir, "Folder for frame-N.png, frame-N.exr and timing.jsonl");
  app.add_flag("!--no-png", o.png, "Do not write PNG frames");
  app.add_flag("!--no-exr", o.exr, "Do not write EXR frames");
  const std::map<std::string, RendererKind> kinds{{"gl", RendererKind::Gl},
                                                  {"embree", RendererKind::Embree},
                                                  {"reference", RendererKind::Reference}};
  app.add_option("--renderer", o.renderer,
                 "gl (OpenGL, shadow maps), embree (same lights, ray-traced shadows), reference "
                 "(Monte Carlo over the whole map; needs --map)")
      ->transform(CLI::CheckedTransformer(kinds, CLI::ignore_case));
  app.add_option("--width", o.widthPx, "Image width in pixels")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  app.add_option("--height", o.heightPx, "Image height in pixels")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
}

void addLightingOptions(CLI::App& app, ViewerOptions& o) {
  app.add_option("--count", o.lightCount, "Lights N (a prefix of the progressive set)")
      ->check(CLI::Range(1, 65536))
      ->capture_default_str();
  app.add_option("--shadowed", o.shadowedCount, "Lights with shadow maps S (0: no shadows)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  app.add_option("--shadow-map-px", o.shadowMapPx, "Resolution of one shadow map")
      ->check(CLI::Range(16, 4096))
      ->capture_default_str();
  app.add_option("--regions", o.regions, "Angular-region light culling (on/off)")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, bool>{{"on", true}, {"off", false}}))
      ->capture_default_str();
  app.add_option("--cluster", o.clusterBudget, "Cluster the lights toward about Q (0: off)")
      ->check(CLI::Range(0, 65536));
  app.add_option("--target-ms", o.targetFrameMs,
                 "Adapt the light count to hold this frame time (ms)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--background", o.background, "Show the environment cube map as background");
  app.add_option("--screenshot", o.screenshot,
                 "Window: save what the window shows after the last frame (PNG)");
}

void addCameraOptions(CLI::App& app, ViewerOptions& o) {
  app.add_option("--orbit", o.orbitDegPerFrame, "Orbit the camera by this many degrees a frame");
  app.add_option("--azimuth", o.azimuthDeg, "Camera azimuth in degrees")->capture_default_str();
  app.add_option("--elevation", o.elevationDeg, "Camera elevation in degrees")
      ->check(CLI::Range(-85.0, 85.0))
      ->capture_default_str();
  app.add_option("--reference-error", o.referenceError,
                 "Reference: stop at this relative standard error")
      ->check(CLI::Range(1e-4, 0.5))
      ->capture_default_str();
  app.add_option("--reference-max-spp", o.referenceMaxSamples,
                 "Reference: samples per pixel at most")
      ->check(CLI::Range(16, 1 << 20))
      ->capture_default_str();
  app.add_option("--timeout", o.streamTimeoutSec, "Seconds to wait for the stream's first frame")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

}  // namespace

std::expected<ViewerOptions, int> parseViewerOptions(int argc, char** argv) {
  CLI::App app{"vemview: draws a scene lit by vemd's lights, with shadows from many lights"};
  app.footer(
      "Examples:\n"
      "  vemview --map ../shared/data/hdri/park.exr                       # a window\n"
      "  vemview --headless --lights out/lights.jsonl --frames 1 --out out/render\n"
      "  vemview --connect ws://127.0.0.1:8765 --scene model.gltf --count 512 --shadowed 128");
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "vemview: error: " + std::string(e.what()) + " (see 'vemview --help')\n";
  });
  ViewerOptions o;
  addInputOptions(app, o);
  addOutputOptions(app, o);
  addLightingOptions(app, o);
  addCameraOptions(app, o);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return std::unexpected(app.exit(e));
  }
  if (o.headless && o.frames == 0) {
    o.frames = 1;
  }
  return o;
}

}  // namespace vem::view
