// Finding V4L2 cameras: the capture devices among /dev/video* (for `vemd --list-devices`), and a
// camera by its card name (`--source v4l2:NAME`, the name VIDIOC_QUERYCAP gives, which survives
// an unplug that renumbers the node). Nodes that are not single-planar streaming capture devices
// (a UVC camera's metadata node, an output or codec node) are left out; nodes that cannot be
// opened (permissions) are listed with the reason, so a user sees why a camera is missing.
#pragma once

#include <expected>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "cameras/v4l2/v4l2_device.h"

namespace vem::cameras {

// /dev/video0, /dev/video1, ... /dev/video10 (numeric order) that exist under `dir`.
[[nodiscard]] std::vector<std::string> videoNodePaths(const std::string& dir = "/dev");

// Every capture device under /dev; a sentence when /dev cannot be read.
[[nodiscard]] std::expected<std::vector<DeviceInfo>, std::string> listV4l2Devices();
// The same over given nodes and opener (tests pass fakes). Modes read "Y16 1280x1024 (as
// Mono16)", "YUYV 640x480 (as RGB8)", "MJPG 1920x1080 (not readable)".
[[nodiscard]] std::vector<DeviceInfo> listV4l2Devices(const std::vector<std::string>& paths,
                                                      const V4l2Opener& opener);

// The first node among `paths` whose card name is `name`; ENOENT when none is.
[[nodiscard]] std::expected<std::unique_ptr<V4l2Device>, int> openV4l2ByCardName(
    const std::string& name, const std::vector<std::string>& paths, const V4l2Opener& opener);

// An opener for `--source v4l2:TARGET`: a path ("/dev/video0") is opened as is, anything else is
// a card name looked up among /dev/video* at every call.
[[nodiscard]] V4l2Opener systemV4l2Opener();

}  // namespace vem::cameras
