// ViewerOptions: vemview's command line (CLI11), checked. `vemview --help` lists every option with
// its default; docs/vemview.md explains them.
#pragma once

#include <cstddef>
#include <expected>
#include <optional>
#include <string>

#include "client/mqtt_cli_options.h"

namespace vem::view {

enum class RendererKind { Gl, Embree, Reference };
// How the lights shade (issue 20): the paper's sums over the lights (glossy L/H), or the
// prefiltered environment with the lights' shadowing ratio (embree_frame_renderer.h).
enum class ShadingKind { Lights, Ratio };

// --place x,y,z,yaw: the objects moved to (x, y, z) metres of the plate's world and turned by yaw
// degrees about +Y.
struct Placement {
  double xM = 0.0;
  double yM = 0.0;
  double zM = 0.0;
  double yawDeg = 0.0;
};

struct ViewerOptions {
  // Input: exactly one of these (none: the map of kDefaultMap from the shared data).
  std::string connectUrl;
  std::string token;
  client::MqttCliOptions mqtt;  // --username, --password-file, --ca-file, --cert, --key
  std::string lightFile;
  std::string mapFile;
  std::string scene = "default";   // a file (.obj, .gltf, .glb) or a built-in scene name
  bool sceneAllowOutside = false;  // the scene file may reference files outside its folder
  // Output.
  bool headless = false;
  std::size_t frames = 0;  // 0: until the window closes (window) / 1 (headless)
  std::string outDir;
  bool png = true;
  bool exr = true;
  RendererKind renderer = RendererKind::Gl;
  int widthPx = 640;
  int heightPx = 480;
  // Lighting.
  std::size_t lightCount = 1024;
  std::size_t shadowedCount = 64;
  int shadowMapPx = 256;
  int cubeFacePx = 0;  // the cube map's level 0 (a mirror's reflection is this sharp); 0: the plan's
  bool regions = true;
  ShadingKind shading = ShadingKind::Lights;
  bool softShadows = false;  // --soft-shadows (by ratio)
  int clusterBudget = 128;
  std::optional<double> targetFrameMs;
  bool background = false;
  std::string screenshot;  // window only: the last frame as shown
  // Camera.
  double orbitDegPerFrame = 0.0;
  double azimuthDeg = 35.0;
  double elevationDeg = 20.0;
  // Reference renderer.
  double referenceError = 0.01;
  std::size_t referenceMaxSamples = 4096;
  double streamTimeoutSec = 10.0;
  // Mixed reality (issue 21; composite_frame_renderer.h): the scene camera's picture to composite
  // the scene into (plate_source.h: an image, an image sequence, a video, v4l2:/dev/videoN, or
  // sim), its calibration (a plate-camera file; none with sim), the real surfaces beyond the
  // floor plane, where the objects stand, and a video of the composite.
  std::string plate;
  std::string plateCamera;
  std::string localScene;
  std::optional<Placement> place;
  std::string videoFile;
  // A live plate with vemd's stream: each picture takes the light frame captured nearest to it
  // within this window (else the newest, and the frame says so).
  double plateSyncWindowSec = 0.1;
};

// The options, or the exit status (util/cli_conventions.h: 0 after --help, 2 for a usage error)
// with its message already printed.
[[nodiscard]] std::expected<ViewerOptions, int> parseViewerOptions(int argc, char** argv);

}  // namespace vem::view
