#include "cameras/v4l2/v4l2_unpack.h"

#include <linux/videodev2.h>

#include <algorithm>
#include <cstdint>

#include "util/contract.h"

namespace vem::cameras {

namespace {

using Row = const std::uint8_t*;
using Out = std::uint16_t*;

void le16(Row in, int w, std::uint16_t mask, Out out) {
  for (int u = 0; u < w; ++u) out[u] = std::uint16_t((in[2 * u] | (in[2 * u + 1] << 8)) & mask);
}

void be16(Row in, int w, Out out) {
  for (int u = 0; u < w; ++u) out[u] = std::uint16_t((in[2 * u] << 8) | in[2 * u + 1]);
}

// MIPI packing: groups of `n` pixels (4 for RAW10, 2 for RAW12) of `bits` bits: n high bytes, then
// one byte of low bits, pixel 0's lowest. A last partial group keeps the same order.
void mipi(Row in, int w, int n, int bits, Out out) {
  const int lowBits = bits - 8;
  const int lowMask = (1 << lowBits) - 1;
  for (int u0 = 0; u0 < w; u0 += n) {
    const int count = std::min(n, w - u0);
    const std::uint8_t low = in[count];
    for (int k = 0; k < count; ++k) {
      out[u0 + k] = std::uint16_t((in[k] << lowBits) | ((low >> (lowBits * k)) & lowMask));
    }
    in += count + 1;
  }
}

void bitPacked10(Row in, int w, Out out) {
  std::size_t bit = 0;
  for (int u = 0; u < w; ++u, bit += 10) {
    const std::size_t byte = bit / 8;
    const unsigned shift = unsigned(bit % 8);
    // 10 bits starting `shift` bits into in[byte], most significant first: within 2 bytes.
    const unsigned word = (unsigned(in[byte]) << 8) | (shift + 10 > 8 ? in[byte + 1] : 0u);
    out[u] = std::uint16_t((word >> (6 - shift)) & 0x3ff);
  }
}

void grey(Row in, int w, Out out) {
  for (int u = 0; u < w; ++u) out[u] = in[u];
}

void rgb24(Row in, int w, Out out) {
  for (int i = 0; i < 3 * w; ++i) out[i] = in[i];
}

std::uint16_t clip8(int value) { return std::uint16_t(std::clamp(value, 0, 255)); }

void yuyvToRgb(Row in, int w, Out out) {
  for (int u = 0; u < w; ++u) {
    const Row pair = in + 4 * (u / 2);
    const int c = 298 * (in[2 * u] - 16);
    const int d = pair[1] - 128;
    const int e = pair[3] - 128;
    out[3 * u + 0] = clip8((c + 409 * e + 128) >> 8);
    out[3 * u + 1] = clip8((c - 100 * d - 208 * e + 128) >> 8);
    out[3 * u + 2] = clip8((c + 516 * d + 128) >> 8);
  }
}

void yuyvToY(Row in, int w, Out out) {
  for (int u = 0; u < w; ++u) out[u] = in[2 * u];
}

void unpackRow(Row in, const V4l2Layout& layout, Out out) {
  const int w = layout.widthPx;
  switch (layout.fourcc) {
    case V4L2_PIX_FMT_Y16: return le16(in, w, 0xffff, out);
    case V4L2_PIX_FMT_Y16_BE: return be16(in, w, out);
    case V4L2_PIX_FMT_Y12: return le16(in, w, 0x0fff, out);
    case V4L2_PIX_FMT_Y10: return le16(in, w, 0x03ff, out);
    case kV4l2PixFmtY12P: return mipi(in, w, 2, 12, out);
    case V4L2_PIX_FMT_Y10P: return mipi(in, w, 4, 10, out);
    case V4L2_PIX_FMT_Y10BPACK: return bitPacked10(in, w, out);
    case V4L2_PIX_FMT_GREY: return grey(in, w, out);
    case V4L2_PIX_FMT_RGB24: return rgb24(in, w, out);
    case V4L2_PIX_FMT_YUYV:
      return layout.output.channels == 3 ? yuyvToRgb(in, w, out) : yuyvToY(in, w, out);
    default: break;
  }
  VEM_UNREACHABLE("unpackV4l2Frame: the layout's fourcc is one v4l2_formats.h reads");
}

}  // namespace

void unpackV4l2Frame(std::span<const std::byte> data, const V4l2Layout& layout, RawFrame& frame) {
  VEM_EXPECTS(data.size() >= layout.minimumBytes() &&
              layout.bytesPerLine >= packedRowBytes(layout.fourcc, layout.widthPx));
  frame.width = layout.widthPx;
  frame.height = layout.heightPx;
  frame.format = layout.output;
  const std::size_t rowCodes = std::size_t(layout.widthPx) * std::size_t(layout.output.channels);
  frame.codes.resize(rowCodes * std::size_t(layout.heightPx));
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(data.data());
  for (int v = 0; v < layout.heightPx; ++v) {
    unpackRow(bytes + std::size_t(v) * layout.bytesPerLine, layout,
              frame.codes.data() + std::size_t(v) * rowCodes);
  }
}

}  // namespace vem::cameras
