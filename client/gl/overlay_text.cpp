#include "client/gl/overlay_text.h"

#include <algorithm>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace vem::gl {
namespace {

constexpr int kFontFace = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kThickness = 1;

int textWidthPx(const std::string& text, const OverlayFont& font) {
  int baseline = 0;
  return cv::getTextSize(text, kFontFace, font.scale, kThickness, &baseline).width;
}

struct LineMetrics {
  int ascentPx = 0;   // baseline to the top of the tallest glyph
  int descentPx = 0;  // baseline to the bottom of descenders
  [[nodiscard]] int heightPx() const { return ascentPx + descentPx; }
};

LineMetrics lineMetrics(const OverlayFont& font) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize("Agjy|(", kFontFace, font.scale, kThickness, &baseline);
  return {size.height, baseline + kThickness};
}

std::vector<std::string> splitWords(std::string_view line) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start < line.size()) {
    const std::size_t end = std::min(line.find(' ', start), line.size());
    if (end > start) words.emplace_back(line.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

void wrapOneLine(std::string_view line, int maxWidthPx, const OverlayFont& font,
                 std::vector<std::string>& out) {
  std::string current;
  for (const std::string& word : splitWords(line)) {
    std::string candidate = current.empty() ? word : current + " " + word;
    if (!current.empty() && textWidthPx(candidate, font) > maxWidthPx) {
      out.push_back(std::move(current));
      current = word;
    } else {
      current = std::move(candidate);
    }
  }
  if (!current.empty()) out.push_back(std::move(current));
}

// White text on the translucent black box, premultiplied: rgb = 255 * coverage,
// alpha = coverage + boxAlpha * (1 - coverage).
OverlayImage compose(const cv::Mat& coverage, std::uint8_t boxAlpha) {
  OverlayImage image{coverage.cols, coverage.rows, {}};
  image.rgba.resize(std::size_t(image.widthPx) * std::size_t(image.heightPx) * 4);
  std::size_t at = 0;
  for (int y = 0; y < coverage.rows; ++y) {
    const std::uint8_t* row = coverage.ptr<std::uint8_t>(y);
    for (int x = 0; x < coverage.cols; ++x, at += 4) {
      const int c = row[x];
      const int alpha = c + (boxAlpha * (255 - c) + 127) / 255;
      image.rgba[at + 0] = std::uint8_t(c);
      image.rgba[at + 1] = std::uint8_t(c);
      image.rgba[at + 2] = std::uint8_t(c);
      image.rgba[at + 3] = std::uint8_t(alpha);
    }
  }
  return image;
}

}  // namespace

OverlayFont overlayFontFor(int windowWidthPx) {
  OverlayFont font;
  font.scale = std::clamp(double(windowWidthPx) / 1280.0, 0.3, 0.5);
  return font;
}

std::vector<std::string> wrapOverlayLines(std::string_view text, int maxWidthPx,
                                          const OverlayFont& font) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    wrapOneLine(text.substr(start, end - start), maxWidthPx, font, lines);
    start = end + 1;
  }
  return lines;
}

OverlayImage rasteriseOverlay(std::string_view text, int maxWidthPx, int maxHeightPx,
                              const OverlayFont& font) {
  const int innerWidthPx = maxWidthPx - 2 * font.paddingPx;
  const LineMetrics metrics = lineMetrics(font);
  const int stepPx = metrics.heightPx() + font.lineGapPx;
  const int fitting = (maxHeightPx - 2 * font.paddingPx + font.lineGapPx) / stepPx;
  if (innerWidthPx <= 0 || fitting <= 0) return {};
  std::vector<std::string> lines = wrapOverlayLines(text, innerWidthPx, font);
  if (lines.size() > std::size_t(fitting)) lines.resize(std::size_t(fitting));
  if (lines.empty()) return {};
  int widestPx = 0;
  for (const std::string& line : lines) widestPx = std::max(widestPx, textWidthPx(line, font));
  const int widthPx = std::min(widestPx + 2 * font.paddingPx, maxWidthPx);
  const int heightPx = int(lines.size()) * stepPx - font.lineGapPx + 2 * font.paddingPx;
  cv::Mat coverage(heightPx, widthPx, CV_8UC1, cv::Scalar(0));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const cv::Point origin(font.paddingPx, font.paddingPx + int(i) * stepPx + metrics.ascentPx);
    cv::putText(coverage, lines[i], origin, kFontFace, font.scale, cv::Scalar(255), kThickness,
                cv::LINE_AA);
  }
  return compose(coverage, font.boxAlpha);
}

}  // namespace vem::gl
