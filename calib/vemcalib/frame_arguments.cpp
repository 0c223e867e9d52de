#include "frame_arguments.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "calib/io/raw_frame_file.h"

namespace vem::calibtool {

std::expected<FrameArgument, std::string> parseFrameArgument(std::string_view text) {
  const std::size_t at = text.rfind('@');
  if (at == std::string_view::npos) return FrameArgument{std::filesystem::path(text)};
  const std::string_view suffix = text.substr(at + 1);
  double exposureUs = 0.0;
  const auto [end, error] =
      std::from_chars(suffix.data(), suffix.data() + suffix.size(), exposureUs);
  if (error != std::errc{} || end != suffix.data() + suffix.size())
    return FrameArgument{std::filesystem::path(text)};
  if (!(exposureUs > 0.0) || !std::isfinite(exposureUs))
    return std::unexpected(
        fmt::format("{}: the exposure after '@' must be a positive number of microseconds, not {}",
                    text, suffix));
  return FrameArgument{std::filesystem::path(text.substr(0, at)), exposureUs};
}

std::expected<RawFrame, std::string> loadFrameArgument(std::string_view text,
                                                       std::optional<int> bits, double gain) {
  const auto argument = parseFrameArgument(text);
  if (!argument) return std::unexpected(argument.error());
  auto frame = calib::io::loadRawFrame(argument->path, bits);
  if (!frame) return std::unexpected(frame.error().message);
  frame->exposureUs = argument->exposureUs;
  frame->gain = gain;
  return std::move(*frame);
}

std::string describeFrame(const RawFrame& frame) {
  return fmt::format("{} x {} {}", frame.width, frame.height, pixelFormatName(frame.format));
}

}  // namespace vem::calibtool
