// The window's text overlay: the picture (overlay_text.h) wraps to the window, keeps to its box
// and is premultiplied white on translucent black; the pass (overlay_pass.h) blends it into the
// top-left corner of its target only (catches a flipped row order, a wrong blend, a full-screen
// draw) and re-uploads only when the text changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "client/gl/gl_handle.h"
#include "client/gl/overlay_pass.h"
#include "client/gl/overlay_text.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

const std::string kStatus =
    "frame 20 | 29.5 frames/s | drawn 20 (31.2 ms last) | lights 256 | shadowed 64\n"
    "lights 256, shadow maps 64 at 256 px, regions on, glossy L/H pass (|H| 72; a material is "
    "glossy), cube map of 128 px (glossy reflections)";

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(OverlayText, LongLinesWrapAtSpacesAndKeepEveryWord) {
  const OverlayFont font = overlayFontFor(320);
  const std::vector<std::string> lines = wrapOverlayLines(kStatus, 300, font);
  EXPECT_GT(lines.size(), 2U);
  std::string joined;
  for (const std::string& line : lines) joined += line + " ";
  EXPECT_EQ(words(joined), words(kStatus));
  EXPECT_EQ(wrapOverlayLines("one\n\ntwo", 1000, font), (std::vector<std::string>{"one", "two"}));
}

TEST(OverlayText, PictureFitsItsBoxAndIsPremultipliedWhiteOnTranslucentBlack) {
  const OverlayFont font = overlayFontFor(320);
  const OverlayImage image = rasteriseOverlay(kStatus, 300, 200, font);
  ASSERT_FALSE(image.empty());
  EXPECT_LE(image.widthPx, 300);
  EXPECT_LE(image.heightPx, 200);
  ASSERT_EQ(image.rgba.size(), std::size_t(image.widthPx) * std::size_t(image.heightPx) * 4);
  std::size_t boxOnly = 0;
  std::size_t bright = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const std::uint8_t r = image.rgba[i];
    EXPECT_EQ(image.rgba[i + 1], r);
    EXPECT_EQ(image.rgba[i + 2], r);
    EXPECT_LE(r, image.rgba[i + 3]) << "premultiplied";
    EXPECT_GE(image.rgba[i + 3], font.boxAlpha);
    boxOnly += (r == 0 && image.rgba[i + 3] == font.boxAlpha) ? 1 : 0;
    bright += r > 200 ? 1 : 0;
  }
  EXPECT_GT(boxOnly, image.rgba.size() / 4 / 2) << "most of the box is background";
  EXPECT_GT(bright, 50U) << "the text is drawn (anti-aliased: few pixels are fully covered)";
}

TEST(OverlayText, LinesBelowTheBoxAreLeftOutAndNothingGivesNoPicture) {
  const OverlayFont font = overlayFontFor(320);
  const OverlayImage all = rasteriseOverlay(kStatus, 300, 400, font);
  const OverlayImage cut = rasteriseOverlay(kStatus, 300, all.heightPx / 2, font);
  ASSERT_FALSE(cut.empty());
  EXPECT_LT(cut.heightPx, all.heightPx);
  EXPECT_LE(cut.heightPx, all.heightPx / 2);
  EXPECT_TRUE(rasteriseOverlay("", 300, 200, font).empty());
  EXPECT_TRUE(rasteriseOverlay(" \n ", 300, 200, font).empty());
  EXPECT_TRUE(rasteriseOverlay(kStatus, 300, 5, font).empty());
  EXPECT_TRUE(rasteriseOverlay(kStatus, 4, 200, font).empty());
}

// An RGBA8 framebuffer filled with one grey level, standing in for the window's back buffer.
struct GreyTarget {
  GlTexture colour = GlTexture::create();
  GlFramebuffer framebuffer = GlFramebuffer::create();
};

GreyTarget greyTarget(int widthPx, int heightPx, float grey) {
  GreyTarget t;
  glBindTexture(GL_TEXTURE_2D, t.colour.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, widthPx, heightPx, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.colour.id(), 0);
  glViewport(0, 0, widthPx, heightPx);
  glClearColor(grey, grey, grey, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return t;
}

// The red channel, row 0 at the TOP.
std::vector<int> readRed(const GreyTarget& t, int widthPx, int heightPx) {
  std::vector<std::uint8_t> rgba(std::size_t(widthPx) * std::size_t(heightPx) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.framebuffer.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, widthPx, heightPx, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  std::vector<int> red(std::size_t(widthPx) * std::size_t(heightPx));
  for (int y = 0; y < heightPx; ++y) {
    for (int x = 0; x < widthPx; ++x) {
      red[std::size_t(y * widthPx + x)] = rgba[std::size_t(((heightPx - 1 - y) * widthPx + x) * 4)];
    }
  }
  return red;
}

TEST(OverlayPass, BlendsTheTextIntoTheTopLeftCornerOnly) {
  if (headlessContext() == nullptr) GTEST_SKIP() << "no headless EGL context";
  constexpr int kW = 320;
  constexpr int kH = 200;
  const GreyTarget target = greyTarget(kW, kH, 0.5F);
  auto pass = OverlayPass::create();
  ASSERT_TRUE(pass.has_value()) << pass.error();
  pass->draw(target.framebuffer.id(), {kW, kH}, "vemview\nlights 32 | shadowed 8");
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<int> red = readRed(target, kW, kH);
  const auto at = [&](int x, int y) { return red[std::size_t(y * kW + x)]; };
  const int grey = at(kW - 1, kH - 1);
  EXPECT_NEAR(grey, 128, 1);
  // The margin row and column stay as they were; inside the box the grey is darkened by the box
  // and brightened where the text is; the bottom half and the right edge are untouched.
  const int m = OverlayPass::kMarginPx;
  for (int x = 0; x < kW; ++x) EXPECT_EQ(at(x, m - 1), grey) << x;
  for (int y = 0; y < kH; ++y) EXPECT_EQ(at(m - 1, y), grey) << y;
  EXPECT_LT(at(m, m), grey - 40) << "the box's corner (alpha 140/255)";
  int brightest = 0;
  for (int y = m; y < m + 30; ++y) {
    for (int x = m; x < m + 80; ++x) brightest = std::max(brightest, at(x, y));
  }
  EXPECT_GT(brightest, 220) << "white text in the box";
  for (int y = kH / 2; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) ASSERT_EQ(at(x, y), grey) << x << "," << y;
  }
}

TEST(OverlayPass, UploadsOnlyWhenTheTextOrTheTargetChanges) {
  if (headlessContext() == nullptr) GTEST_SKIP() << "no headless EGL context";
  const GreyTarget target = greyTarget(200, 100, 0.0F);
  auto pass = OverlayPass::create();
  ASSERT_TRUE(pass.has_value()) << pass.error();
  pass->draw(target.framebuffer.id(), {200, 100}, "frame 1");
  pass->draw(target.framebuffer.id(), {200, 100}, "frame 1");
  EXPECT_EQ(pass->uploads(), 1);
  pass->draw(target.framebuffer.id(), {200, 100}, "frame 2");
  EXPECT_EQ(pass->uploads(), 2);
  pass->draw(target.framebuffer.id(), {150, 100}, "frame 2");
  EXPECT_EQ(pass->uploads(), 3);
}

}  // namespace
}  // namespace vem::gl::test
