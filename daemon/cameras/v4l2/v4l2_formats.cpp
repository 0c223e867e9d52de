#include "cameras/v4l2/v4l2_formats.h"

#include <linux/videodev2.h>

#include <algorithm>
#include <array>

namespace vem::cameras {

namespace {

struct Readable {
  std::uint32_t fourcc;
  PixelFormat native;  // what it gives when nothing else is asked
};

// Deepest first: the order "" (the deepest the camera offers) picks in.
constexpr std::array<Readable, 10> kReadable = {{
    {V4L2_PIX_FMT_Y16, {1, 16}},
    {V4L2_PIX_FMT_Y16_BE, {1, 16}},
    {V4L2_PIX_FMT_Y12, {1, 12}},
    {kV4l2PixFmtY12P, {1, 12}},
    {V4L2_PIX_FMT_Y10, {1, 10}},
    {V4L2_PIX_FMT_Y10P, {1, 10}},
    {V4L2_PIX_FMT_Y10BPACK, {1, 10}},
    {V4L2_PIX_FMT_RGB24, {3, 8}},
    {V4L2_PIX_FMT_YUYV, {3, 8}},
    {V4L2_PIX_FMT_GREY, {1, 8}},
}};

}  // namespace

std::string fourccName(std::uint32_t fourcc) {
  std::string name;
  for (int i = 0; i < 4; ++i) {
    const char c = char((fourcc >> (8 * i)) & 0x7f);
    name.push_back(c >= 32 && c < 127 ? c : '?');
  }
  while (!name.empty() && name.back() == ' ') name.pop_back();
  if (fourcc & (1u << 31)) name += "-BE";
  return name;
}

std::optional<PixelFormat> outputFormatOf(std::uint32_t fourcc, std::string_view requested) {
  const auto* entry = std::find_if(kReadable.begin(), kReadable.end(),
                                   [&](const Readable& r) { return r.fourcc == fourcc; });
  if (entry == kReadable.end()) return std::nullopt;
  if (requested.empty()) return entry->native;
  const auto wanted = parsePixelFormat(requested);
  if (!wanted) return std::nullopt;
  if (*wanted == entry->native) return entry->native;
  // YUYV's luma alone is Mono8.
  if (fourcc == V4L2_PIX_FMT_YUYV && *wanted == PixelFormat{1, 8}) return wanted;
  return std::nullopt;
}

std::vector<std::uint32_t> nativeCandidates(std::string_view requested) {
  std::vector<std::uint32_t> out;
  for (const Readable& r : kReadable) {
    if (outputFormatOf(r.fourcc, requested)) out.push_back(r.fourcc);
  }
  // Mono8: the camera's own grey before YUYV's luma.
  if (requested == "Mono8") std::ranges::reverse(out);
  return out;
}

std::optional<std::uint32_t> chooseNativeFormat(const std::vector<std::uint32_t>& offered,
                                                std::string_view requested) {
  for (std::uint32_t candidate : nativeCandidates(requested)) {
    if (std::ranges::find(offered, candidate) != offered.end()) return candidate;
  }
  return std::nullopt;
}

std::size_t packedRowBytes(std::uint32_t fourcc, int widthPx) {
  const auto w = std::size_t(std::max(widthPx, 0));
  switch (fourcc) {
    case V4L2_PIX_FMT_Y16:
    case V4L2_PIX_FMT_Y16_BE:
    case V4L2_PIX_FMT_Y12:
    case V4L2_PIX_FMT_Y10: return 2 * w;
    case kV4l2PixFmtY12P: return (3 * w + 1) / 2;
    case V4L2_PIX_FMT_Y10P:
    case V4L2_PIX_FMT_Y10BPACK: return (5 * w + 3) / 4;
    case V4L2_PIX_FMT_GREY: return w;
    case V4L2_PIX_FMT_RGB24: return 3 * w;
    case V4L2_PIX_FMT_YUYV: return 2 * w;
    default: return 0;
  }
}

std::size_t V4l2Layout::minimumBytes() const {
  if (heightPx <= 0) return 0;
  return bytesPerLine * std::size_t(heightPx - 1) + packedRowBytes(fourcc, widthPx);
}

}  // namespace vem::cameras
