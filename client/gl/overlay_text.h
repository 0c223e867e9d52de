// OverlayText: the window's status overlay as a small picture: text lines (the status line, the
// plan) rasterised with OpenCV's Hershey simplex font, white and anti-aliased, on a translucent
// black box, word-wrapped to fit the window. Pure: no GL, no files; overlay_pass.h uploads and
// blends it.
//
// Conventions: sizes in pixels; RGBA8 with premultiplied alpha (rgb <= a), row 0 at the top; the
// box is at most maxWidthPx x maxHeightPx (lines that do not fit below are left out).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vem::gl {

struct OverlayImage {
  int widthPx = 0;
  int heightPx = 0;
  std::vector<std::uint8_t> rgba;  // widthPx * heightPx * 4, premultiplied, row 0 at the top

  [[nodiscard]] bool empty() const { return widthPx == 0 || heightPx == 0; }
};

struct OverlayFont {
  double scale = 0.45;  // cv::putText fontScale (Hershey simplex: about 22 * scale px per line)
  int paddingPx = 4;    // inside the box, around the text
  int lineGapPx = 4;    // between lines
  std::uint8_t boxAlpha = 140;  // the black box behind the text (0..255)
};

// The font for a window `windowWidthPx` wide: smaller in small windows (scale 0.3 ... 0.5).
[[nodiscard]] OverlayFont overlayFontFor(int windowWidthPx);

// `text`'s lines ('\n'-separated, empty ones dropped), each split at spaces into lines no wider
// than maxWidthPx in `font` (a single word wider than that stays whole, clipped when drawn).
[[nodiscard]] std::vector<std::string> wrapOverlayLines(std::string_view text, int maxWidthPx,
                                                        const OverlayFont& font);

// The overlay picture of `text`; empty (0 x 0) for text with no visible characters or a box that
// cannot hold one line.
[[nodiscard]] OverlayImage rasteriseOverlay(std::string_view text, int maxWidthPx, int maxHeightPx,
                                            const OverlayFont& font);

}  // namespace vem::gl
