// makeSource: the frame source a `--source` spec names, opened and ready:
//   replay:FILE       a VEM recording (replay_source.h), at source.rate, looping with source.loop
//   synthetic:SCENE   a synthetic scene through a simulated camera (synthetic_source.h)
//   aravis:ID         a GenICam camera through Aravis (daemon/cameras/aravis/)
//   v4l2:DEVICE       a V4L2 camera, /dev/videoN or its card name (daemon/cameras/v4l2/)
//   libcamera:ID      a libcamera camera, by id or index (daemon/cameras/libcamera/)
// Live cameras take `camera` (the [camera] settings) and need source.camera, the camera file
// with their calibration. With bracketing.count > 0 the camera (or synthetic scene) is wrapped
// in exposure bracketing (daemon/cameras/bracketing/): groups of exposures merged into HDR frames.
// Fails with one sentence naming the spec and what was expected, or why the source cannot open.
#pragma once

#include <expected>
#include <memory>
#include <string>
#include <string_view>

#include "frames/frame_source.h"
#include "vemd/vemd_config.h"

namespace vem::vemd {

struct SourceSpec {
  enum class Kind { Replay, Synthetic, Aravis, V4l2, Libcamera };
  Kind kind = Kind::Replay;
  std::string argument;  // the file, or the scene
};

// "KIND:ARGUMENT" split; a sentence when the kind is unknown or the argument missing.
[[nodiscard]] std::expected<SourceSpec, std::string> parseSourceSpec(std::string_view spec);

[[nodiscard]] std::expected<std::unique_ptr<FrameSource>, std::string> makeSource(
    const SourceConfig& config, const CameraConfig& camera = {},
    const BracketingConfig& bracketing = {});

}  // namespace vem::vemd
