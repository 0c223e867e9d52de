// The LibcameraCameraPort over libcamera itself (0.0.3's C++ API): CameraManager, Camera,
// FrameBufferAllocator, Request. Completions and the disconnect notification come on libcamera's
// own thread, straight from its signals (the port is no libcamera::Object, so its slots run on the
// emitting thread).
//
// libcamera allows one CameraManager per process: every port shares one, started when the first
// port is made and stopped when the last goes. Timestamps are FrameMetadata::timestamp, the V4L2
// buffer timestamp (CLOCK_MONOTONIC: the kernel's vb2 stamps buffers with ktime_get_ns()).
// Buffers are mapped whole (mmap of each plane's dmabuf, its size from lseek) for the port's life.
// Controls the camera does not list in Camera::controls() are left out of start() and requests.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "cameras/libcamera/libcamera_port.h"

namespace vem::cameras {

// A port, or why libcamera's camera manager did not start.
[[nodiscard]] std::expected<std::unique_ptr<LibcameraCameraPort>, std::string>
makeLibcameraSystemPort();

}  // namespace vem::cameras
