// What a V4L2 device says about itself: VIDIOC_QUERYCAP (is it a streaming capture device, its
// card name and bus), VIDIOC_ENUM_FMT (the pixel formats it offers) and VIDIOC_ENUM_FRAMESIZES
// (the sizes of one format). Used to open a camera and to list the cameras for --list-devices.
// Single-planar capture only (V4L2_BUF_TYPE_VIDEO_CAPTURE); multi-planar devices are refused.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include "cameras/v4l2/v4l2_device.h"

namespace vem::cameras {

struct V4l2Identity {
  std::string card;     // "UVC Camera (046d:0825)": the model as the driver names it
  std::string busInfo;  // "usb-0000:00:14.0-1": where it is attached
  std::string driver;   // "uvcvideo"
};

struct V4l2FrameSize {
  int widthPx = 0;
  int heightPx = 0;
};

// QUERYCAP; a sentence fragment when the device cannot capture by streaming
// ("/dev/video1 is not a video capture device (a metadata or output node?)").
[[nodiscard]] std::expected<V4l2Identity, std::string> queryCaptureIdentity(
    V4l2Device& device, const std::string& path);

// ENUM_FMT over the capture formats, in the driver's order.
[[nodiscard]] std::vector<std::uint32_t> enumerateFormats(V4l2Device& device);

// ENUM_FRAMESIZES of `fourcc`: discrete sizes in the driver's order, or the largest of a stepwise
// or continuous range; empty when the driver does not enumerate sizes.
[[nodiscard]] std::vector<V4l2FrameSize> enumerateFrameSizes(V4l2Device& device,
                                                             std::uint32_t fourcc);

}  // namespace vem::cameras
