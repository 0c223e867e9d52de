#include "client/vemview/viewer_options.h"

#include <iostream>
#include <map>
#include <regex>

#include <CLI/CLI.hpp>

#include "client/mqtt_url.h"
#include "util/cli_conventions.h"

namespace vem::view {
namespace {

// A word among `names` (any case) for an enum or bool option; in --help the value reads
// "gl|embree|reference" and a wrong word is one sentence naming the choices (CLI11's own
// transformer shows its map, "{embree->1,gl->0,reference->2} OR {1,0,2}", in both).
template <class T>
CLI::Option* choiceOf(CLI::Option* option, const std::vector<std::pair<std::string, T>>& names) {
  std::string list;
  for (const auto& [name, value] : names) list += (list.empty() ? "" : "|") + name;
  option->type_name(list);
  return option->transform(CLI::Validator(
      [names, list](std::string& text) -> std::string {
        for (const auto& [name, value] : names) {
          if (CLI::detail::to_lower(text) == name) {
            text = std::to_string(int(value));
            return {};
          }
        }
        return "'" + text + "' is not one of " + list;
      },
      ""));
}

// A number > 0, with a plain error (CLI::PositiveNumber names the range up to 1.8e308 in full).
CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !(value > 0.0)) {
          return "'" + text + "' is not a number greater than 0";
        }
        return {};
      },
      "");
}

void addInputOptions(CLI::App& app, ViewerOptions& o) {
  auto* connect = app.add_option(
      "--connect", o.connectUrl,
      "Take lights (and cube maps) from vemd's stream: ws[s]://HOST:PORT, or through an MQTT "
      "broker mqtt[s]://[USER@]HOST[:PORT]/PREFIX/CAMERA");
  app.add_option("--token", o.token, "Bearer token for the stream (ws, wss)");
  client::addMqttCliOptions(app, o.mqtt,
                            "wss, mqtts: trust the CA certificates of this PEM file instead of "
                            "the system's");
  auto* lights = app.add_option(
      "--lights", o.lightFile, "Take lights from a JSON-lines file (vemd --jsonl, vemtool lights)");
  auto* map = app.add_option("--map", o.mapFile,
                             "Compute lights from an environment map file (.exr, .hdr, .pfm)");
  connect->excludes(lights)->excludes(map);
  lights->excludes(map);
  app.add_option("--scene", o.scene,
                 "Scene file (.obj, .gltf, .glb) or built-in: default, diffuse, spheres, sphere, "
                 "mixed-reality (--plate's default: two spheres, no ground)")
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
  choiceOf<RendererKind>(
      app.add_option(
          "--renderer", o.renderer,
          "gl (OpenGL, shadow maps), embree (same lights, ray-traced shadows), reference "
          "(Monte Carlo over the whole map; needs --map)"),
      {{"gl", RendererKind::Gl},
       {"embree", RendererKind::Embree},
       {"reference", RendererKind::Reference}})
      ->default_str("gl");
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
  app.add_option("--cube-face-px", o.cubeFacePx,
                 "The cube map's face size, 8 to 512: a mirror's reflection is this sharp "
                 "(default: 512 with a mirror-like material, else 128)")
      ->check(CLI::Range(8, 512));
  choiceOf<bool>(app.add_option("--regions", o.regions, "Angular-region light culling"),
                 {{"on", true}, {"off", false}})
      ->default_str(o.regions ? "on" : "off");
  choiceOf<ShadingKind>(
      app.add_option("--shading", o.shading,
                     "lights (the sums over the lights, glossy L/H: paper 004) or ratio (the "
                     "prefiltered environment, shadowed by the lights' ratio)"),
      {{"lights", ShadingKind::Lights}, {"ratio", ShadingKind::Ratio}})
      ->default_str("lights");
  app.add_flag("--soft-shadows", o.softShadows,
               "With --shading ratio: a light that stands for a wide part of the sky casts that "
               "part's soft shadow (Embree: a ray per light and pixel; OpenGL: the shadow maps "
               "beyond N, up to --shadowed, look along directions drawn from the lights' parts)");
  app.add_option("--cluster", o.clusterBudget, "Cluster the lights toward about Q (0: off)")
      ->check(CLI::Range(0, 65536));
  app.add_option("--target-ms", o.targetFrameMs,
                 "Adapt the light count to hold this frame time (ms)")
      ->check(positiveNumber());
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
      ->check(positiveNumber())
      ->capture_default_str();
}

void addPlateOptions(CLI::App& app, ViewerOptions& o) {
  app.add_option("--plate", o.plate,
                 "Composite the scene into the scene camera's picture: an image (PNG, JPEG, "
                 "EXR), an image sequence (frames/%04d.png), a video file (MP4, MKV), "
                 "v4l2:/dev/videoN, or sim (the simulated real world, no camera)");
  app.add_option("--plate-camera", o.plateCamera,
                 "The scene camera's calibration (vemcalib plate ...; not with --plate sim)");
  app.add_option("--local-scene", o.localScene,
                 "Proxy meshes of the real surfaces beyond the floor plane (.obj, .gltf, .glb)");
  app.add_option_function<std::vector<double>>(
         "--place",
         [&o](const std::vector<double>& v) {
           o.place = Placement{v[0], v[1], v[2], v[3]};
         },
         "Move the scene's objects to x,y,z (metres, the plate's world) and turn them by yaw "
         "degrees about +Y")
      ->delimiter(',')
      ->expected(4);
  app.add_option_function<double>(
         "--plate-sync-ms", [&o](double ms) { o.plateSyncWindowSec = ms / 1000.0; },
         "A live plate with vemd's stream: each picture takes the light frame captured nearest "
         "to it within this many ms (default 100), else the newest")
      ->check(CLI::Range(0.0, 10000.0));
  app.add_option("--video", o.videoFile, "Headless with --plate: also write the frames as a "
                                         "video (MP4, OpenCV's VideoWriter)");
}

// CLI11 names a value after its parser and its checks ("TEXT", "INT:INT in [16 - 8192]",
// "FLOAT:POSITIVE"); --help shows what the value is ("URL", "DEGREES") and, for a range, the
// range ("16..8192"). Choice lists are left to util/cli_conventions.h ("gl|embree|reference").
void plainValueNames(CLI::App& app) {
  static const std::map<std::string, std::string> kNames{
      {"--connect", "URL"},   {"--token", "TOKEN"},     {"--lights", "FILE"},
      {"--map", "FILE"},      {"--scene", "NAME|FILE"}, {"--frames", "N"},
      {"--out", "DIR"},       {"--screenshot", "FILE"}, {"--target-ms", "MS"},
      {"--orbit", "DEGREES"}, {"--azimuth", "DEGREES"}, {"--timeout", "SECONDS"},
      {"--plate", "SOURCE"},  {"--plate-camera", "FILE"}, {"--local-scene", "FILE"},
      {"--place", "X,Y,Z,YAW"}, {"--video", "FILE"}, {"--plate-sync-ms", "MS"}};
  static const std::regex kRange{R"(^\S+ in \[(\S+) - (\S+)\]$)"};
  for (CLI::Option* option : app.get_options()) {
    if (const auto named = kNames.find(option->get_name()); named != kNames.end()) {
      option->type_name(named->second);
    }
    for (int i = 0;; ++i) {
      CLI::Validator* check = nullptr;
      try {
        check = option->get_validator(i);
      } catch (const CLI::OptionNotFound&) {
        break;
      }
      const std::string description = check->get_description();
      std::smatch range;
      if (std::regex_match(description, range, kRange)) {
        option->type_name(range[1].str() + ".." + range[2].str());
        check->description("");
      } else if (description == "POSITIVE") {
        check->description("");  // the option's text says what it is
      }
    }
  }
}

// Why --plate cannot run with the other options given, in one sentence, or empty.
std::string plateOptionsRefused(const CLI::App& app, const ViewerOptions& o) {
  if (o.renderer == RendererKind::Reference) {
    return "--plate composites with the lights: give --renderer gl or embree, not reference";
  }
  if (app.count("--shading") > 0 && o.shading != ShadingKind::Ratio) {
    return "--plate shades by ratio (the differential render's model): leave --shading out";
  }
  if (o.plate == "sim" && !o.plateCamera.empty()) {
    return "--plate sim films the simulated world with its own camera: leave --plate-camera out";
  }
  if (o.plate != "sim" && o.plateCamera.empty()) {
    return "--plate " + o.plate + " needs the scene camera's calibration: give --plate-camera "
           "FILE (vemcalib plate ...)";
  }
  if (o.plate == "sim" && (!o.connectUrl.empty() || !o.lightFile.empty())) {
    return "--plate sim renders the simulated world under an environment map: give --map FILE "
           "or no input (the default map), not --connect or --lights";
  }
  return {};
}

}  // namespace

std::expected<ViewerOptions, int> parseViewerOptions(int argc, char** argv) {
  CLI::App app{"vemview: draws a scene lit by vemd's lights, with shadows from many lights"};
  ViewerOptions o;
  addInputOptions(app, o);
  addOutputOptions(app, o);
  addLightingOptions(app, o);
  addCameraOptions(app, o);
  addPlateOptions(app, o);
  plainValueNames(app);
  app.footer(  // the conventions put the exit statuses below it
      "Examples:\n"
      "  vemview --map ../shared/data/hdri/esplanade.exr                  # a window\n"
      "  vemview --headless --lights out/lights.jsonl --frames 1 --out out/render\n"
      "  vemview --connect ws://127.0.0.1:8765 --scene model.gltf --count 512 --shadowed 128\n"
      "  vemview --connect mqtt://viewer@broker/vemcast/stage --password-file viewer.pass");
  cli::applyConventions(app, "vemview");  // plain help, the exit statuses, one error line
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return std::unexpected(cli::exitStatusFor(app, e));
  }
  if (!o.plate.empty()) {
    if (auto refused = plateOptionsRefused(app, o); !refused.empty()) {
      std::cerr << "vemview: error: " << refused << "\n";
      return std::unexpected(cli::kExitUsage);
    }
    o.shading = ShadingKind::Ratio;  // the differential render shades by ratio (issue 20)
    if (app.count("--scene") == 0) o.scene = "mixed-reality";
  } else if (!o.plateCamera.empty() || !o.localScene.empty() || o.place || !o.videoFile.empty() ||
             app.count("--plate-sync-ms") > 0) {
    std::cerr << "vemview: error: --plate-camera, --local-scene, --place and --video composite "
                 "into a plate: give --plate SOURCE too\n";
    return std::unexpected(cli::kExitUsage);
  }
  if (!client::isMqttUrl(o.connectUrl) && client::anyMqttOnlyOption(o.mqtt)) {
    std::cerr << "vemview: error: --username, --password-file, --cert and --key are for an "
                 "MQTT broker: give --connect mqtt://... or mqtts://...\n";
    return std::unexpected(cli::kExitUsage);
  }
  if (o.renderer == RendererKind::Reference && (!o.connectUrl.empty() || !o.lightFile.empty())) {
    std::cerr << "vemview: error: --renderer reference integrates an environment map: give it "
                 "--map FILE, not --connect or --lights (see 'vemview --help')\n";
    return std::unexpected(cli::kExitUsage);
  }
  if (o.shading == ShadingKind::Ratio && o.renderer == RendererKind::Reference) {
    std::cerr << "vemview: error: --shading ratio is a way of shading with the lights: give it "
                 "--renderer gl or embree, not reference (which integrates the map itself)\n";
    return std::unexpected(cli::kExitUsage);
  }
  if (o.softShadows && o.shading != ShadingKind::Ratio) {
    std::cerr << "vemview: error: --soft-shadows shades by ratio: give it --shading ratio too\n";
    return std::unexpected(cli::kExitUsage);
  }
  if (o.headless && o.frames == 0) {
    o.frames = 1;
  }
  return o;
}

}  // namespace vem::view
