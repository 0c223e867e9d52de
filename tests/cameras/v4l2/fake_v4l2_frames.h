// Writing pixel codes the way a V4L2 driver lays them out in a buffer, for the fake camera's
// frames: each format of cameras/v4l2/v4l2_formats.h at the format's bytesperline, the padding
// at the end of every row filled with 0xA5 (so a reader that ignores bytesperline reads garbage).
// Written independently of the backend's unpacker (a bit writer for the packed forms).
#pragma once

#include <linux/videodev2.h>

#include <cstdint>
#include <vector>

namespace vem::testing {

// `codes`: row-major, width x height values (RGB24: 3 per pixel, R G B; YUYV: the 2 bytes per
// pixel of the YUYV stream, Y0 U Y1 V ...).
[[nodiscard]] std::vector<std::uint8_t> encodeFakeFrame(const std::vector<std::uint16_t>& codes,
                                                        const v4l2_pix_format& format);

}  // namespace vem::testing
