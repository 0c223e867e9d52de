// Raw frames named on vemcalib's command line: FILE or FILE@EXPOSURE_US (the image file holds codes
// only; its exposure in microseconds and the gain come from the command line).
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frames/raw_frame.h"

namespace vem::calibtool {

inline constexpr double kDefaultExposureUs = 1000.0;

struct FrameArgument {
  std::filesystem::path path;
  double exposureUs = kDefaultExposureUs;
};

// Splits at the last '@' when what follows is a number; otherwise the whole text is the path.
// Fails (one sentence) for an exposure that is not a positive, finite number.
[[nodiscard]] std::expected<FrameArgument, std::string> parseFrameArgument(std::string_view text);

// Loads the frame (with `bits`-bit codes, else the image's depth) and sets its exposure and gain.
[[nodiscard]] std::expected<RawFrame, std::string> loadFrameArgument(std::string_view text,
                                                                     std::optional<int> bits,
                                                                     double gain);

// "1280 x 1024 RGB12"
[[nodiscard]] std::string describeFrame(const RawFrame& frame);

}  // namespace vem::calibtool
