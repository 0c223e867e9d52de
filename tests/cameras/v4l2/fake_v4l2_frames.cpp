#include "cameras/v4l2/fake_v4l2_frames.h"

#include <cstdio>
#include <cstdlib>

#include "cameras/v4l2/v4l2_formats.h"

namespace vem::testing {

namespace {

constexpr std::uint8_t kPadding = 0xA5;

// Appends bits most significant first.
class BitWriter {
 public:
  explicit BitWriter(std::uint8_t* out) : out_(out) {}
  void put(unsigned value, int bits) {
    for (int b = bits - 1; b >= 0; --b) {
      const unsigned bit = (value >> b) & 1u;
      out_[bit_ / 8] = std::uint8_t(out_[bit_ / 8] | (bit << (7 - bit_ % 8)));
      ++bit_;
    }
  }

 private:
  std::uint8_t* out_;
  std::size_t bit_ = 0;
};

void writeRow(const std::uint16_t* in, int w, std::uint32_t fourcc, std::uint8_t* out) {
  switch (fourcc) {
    case V4L2_PIX_FMT_Y16:
    case V4L2_PIX_FMT_Y12:
    case V4L2_PIX_FMT_Y10:
      for (int u = 0; u < w; ++u) {
        out[2 * u] = std::uint8_t(in[u] & 0xff);
        out[2 * u + 1] = std::uint8_t(in[u] >> 8);
      }
      return;
    case V4L2_PIX_FMT_Y16_BE:
      for (int u = 0; u < w; ++u) {
        out[2 * u] = std::uint8_t(in[u] >> 8);
        out[2 * u + 1] = std::uint8_t(in[u] & 0xff);
      }
      return;
    case V4L2_PIX_FMT_Y10P:
    case cameras::kV4l2PixFmtY12P: {
      const bool ten = fourcc == V4L2_PIX_FMT_Y10P;
      const int group = ten ? 4 : 2;
      const int low = ten ? 2 : 4;
      std::size_t o = 0;
      for (int u0 = 0; u0 < w; u0 += group) {
        std::uint8_t lows = 0;
        int k = 0;
        for (; k < group && u0 + k < w; ++k) {
          out[o++] = std::uint8_t(in[u0 + k] >> low);
          lows = std::uint8_t(lows | ((in[u0 + k] & ((1 << low) - 1)) << (low * k)));
        }
        out[o++] = lows;
      }
      return;
    }
    case V4L2_PIX_FMT_Y10BPACK: {
      for (std::size_t i = 0; i < cameras::packedRowBytes(fourcc, w); ++i) out[i] = 0;
      BitWriter bits(out);
      for (int u = 0; u < w; ++u) bits.put(in[u], 10);
      return;
    }
    case V4L2_PIX_FMT_GREY:
      for (int u = 0; u < w; ++u) out[u] = std::uint8_t(in[u]);
      return;
    case V4L2_PIX_FMT_RGB24:
      for (int i = 0; i < 3 * w; ++i) out[i] = std::uint8_t(in[i]);
      return;
    case V4L2_PIX_FMT_YUYV:
      for (int i = 0; i < 2 * w; ++i) out[i] = std::uint8_t(in[i]);
      return;
    default: break;
  }
  std::fprintf(stderr, "encodeFakeFrame: no writer for %s\n", cameras::fourccName(fourcc).c_str());
  std::abort();
}

int valuesPerPixel(std::uint32_t fourcc) {
  if (fourcc == V4L2_PIX_FMT_RGB24) return 3;
  if (fourcc == V4L2_PIX_FMT_YUYV) return 2;
  return 1;
}

}  // namespace

std::vector<std::uint8_t> encodeFakeFrame(const std::vector<std::uint16_t>& codes,
                                          const v4l2_pix_format& format) {
  const int w = int(format.width);
  const int h = int(format.height);
  const std::size_t perRow = std::size_t(w) * std::size_t(valuesPerPixel(format.pixelformat));
  if (codes.size() != perRow * std::size_t(h)) {
    std::fprintf(stderr, "encodeFakeFrame: %zu codes for %dx%d\n", codes.size(), w, h);
    std::abort();
  }
  std::vector<std::uint8_t> bytes(std::size_t(format.bytesperline) * std::size_t(h), kPadding);
  for (int v = 0; v < h; ++v) {
    writeRow(codes.data() + std::size_t(v) * perRow, w, format.pixelformat,
             bytes.data() + std::size_t(v) * format.bytesperline);
  }
  return bytes;
}

}  // namespace vem::testing
