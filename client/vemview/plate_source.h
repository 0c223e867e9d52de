// PlateSource: the pictures of the scene camera ("the plate", issue 21) that vemview composites
// synthetic objects into (--plate SOURCE), one PlateFrame at a time.
//
// SOURCE is one of:
// - an image file: PNG, JPEG (8 or 16 bit, sRGB) or OpenEXR (linear); a still plate, the same
//   frame every time;
// - an image sequence: a printf pattern such as frames/%04d.png (OpenCV's image-sequence
//   capture);
// - a video file: MP4, MKV, ... through OpenCV's VideoCapture with FFmpeg;
// - sim: the simulated real world (client/scene/mixed_reality_world.h) filmed by its plate camera,
//   rendered once by the Monte Carlo reference under the input's map (simulated_plate.h; opened by
//   the viewer, which has the map);
// - a live camera: v4l2:/dev/videoN, through OpenCV's VideoCapture with its V4L2 backend. Not the
//   project's own V4L2 backend (daemon/cameras/v4l2): that one delivers the light probe's raw
//   sensor codes to the photometric pipeline; a plate is a colour picture, which OpenCV decodes
//   from whatever the camera sends (YUYV, MJPEG), and the client layer does not reach into the
//   daemon's cameras.
// Colour: 8- and 16-bit pictures are sRGB and are decoded to linear light once, here
// (displayReferred: 1 is the camera's white, and what is not changed comes out as it came in);
// OpenEXR is linear already.
// Time: captureTimeSec is the video's own clock (its position) for files, the system clock
// (CLOCK_REALTIME, as the light probe's capture times on vemd's stream) at arrival for a live
// camera, 0 for a still.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>

#include "client/render/linear_image.h"

namespace vem::view {

struct PlateFrame {
  render::LinearImage linear;  // covered everywhere
  bool displayReferred = true;
  double captureTimeSec = 0.0;
  bool captureOnSystemClock = false;  // a live camera's: comparable with the lights' capture time
  std::uint64_t seq = 0;              // changes exactly when the picture does
};

class PlateSource {
 public:
  virtual ~PlateSource() = default;
  [[nodiscard]] virtual std::string description() const = 0;  // "video plate.mp4 (640 x 480)"
  [[nodiscard]] virtual bool live() const { return false; }
  // The pictures' size (a video's and a camera's as they announce it).
  [[nodiscard]] virtual int widthPx() const = 0;
  [[nodiscard]] virtual int heightPx() const = 0;
  // The next picture; nothing when the source has none now (a live camera that stopped, a video
  // that ended: ended() tells which). A still returns its one picture every time.
  [[nodiscard]] virtual std::optional<PlateFrame> next() = 0;
  [[nodiscard]] virtual bool ended() const { return false; }
};

// A still plate: `frame` every time (an image file's, the simulated plate's).
[[nodiscard]] std::unique_ptr<PlateSource> stillPlate(std::string description, PlateFrame frame);

// The source SOURCE names (above), opened and its first frame read; one sentence naming SOURCE
// when it cannot be.
[[nodiscard]] std::expected<std::unique_ptr<PlateSource>, std::string> openPlateSource(
    const std::string& source);

}  // namespace vem::view
