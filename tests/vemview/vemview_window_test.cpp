// vemview's window as a user meets it (the built executable): under Xvfb (xvfb-run) a GLFW window
// opens, renders, and its --screenshot (the window's back buffer read before the overlay is drawn
// and before the swap) matches the headless run's PNG of the same frame; with no display at all
// the run ends with one sentence saying what to do. Skipped when xvfb-run is not installed.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "client/render/image_files.h"
#include "vemview/vemview_process.h"

namespace {

namespace fs = std::filesystem;

using vem::testing::CommandRun;

bool xvfbRunInstalled() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Each run is bounded by timeout(1), so a stuck X server fails the test instead of hanging it.
constexpr const char* kTimeout = "timeout 60 ";
const std::string kScene =
    " --width 160 --height 120 --frames 3 --scene spheres --count 32 --shadowed 8 ";

class VemviewWindow : public vem::testing::VemviewProcessTest {
 protected:
  // xvfb-run -a picks the first free display number; two runs starting at once can pick the same
  // one, and the loser's Xvfb fails to start: try again then.
  CommandRun runUnderXvfb(const std::string& args) const {
    const std::string prefix = std::string(kTimeout) + "xvfb-run -a -s \"-screen 0 1024x768x24\" ";
    CommandRun r;
    for (int attempt = 0; attempt < 3; ++attempt) {
      r = run(prefix, args);
      if (r.err.find("Xvfb failed to start") == std::string::npos) break;
    }
    return r;
  }
};

// The last PNG a headless --out run wrote (frames not redrawn write none).
fs::path lastPng(const fs::path& outDir) {
  fs::path last;
  for (const auto& entry : fs::directory_iterator(outDir)) {
    const fs::path& p = entry.path();
    if (p.extension() == ".png" && p.filename().string().starts_with("frame-") && p > last) {
      last = p;
    }
  }
  return last;
}

TEST_F(VemviewWindow, WindowUnderXvfbRendersWhatTheHeadlessRunRenders) {
  if (!xvfbRunInstalled()) {
    GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb)";
  }
  const CommandRun window = runUnderXvfb(kScene + "--screenshot " + path("shot.png"));
  ASSERT_EQ(window.exitCode, 0) << window.err;
  EXPECT_NE(window.err.find(", window"), std::string::npos) << window.err;
  const CommandRun headless = run(kTimeout, kScene + "--headless --out " + path("out"));
  ASSERT_EQ(headless.exitCode, 0) << headless.err;

  // Same camera (no --orbit), lights and tone: frame 0 is drawn, frames 1 and 2 are not redrawn,
  // so the window's last frame is the headless run's frame-000000.png (its last picture).
  const fs::path headlessPng = lastPng(dir_ / "out");
  ASSERT_EQ(headlessPng.filename(), "frame-000000.png");
  const auto shot = vem::render::loadSrgb8(dir_ / "shot.png");
  ASSERT_TRUE(shot.has_value()) << shot.error();
  const auto expected = vem::render::loadSrgb8(headlessPng);
  ASSERT_TRUE(expected.has_value()) << expected.error();
  ASSERT_EQ(shot->widthPx, 160);
  ASSERT_EQ(shot->heightPx, 120);
  ASSERT_EQ(shot->rgb.size(), expected->rgb.size());

  // Tolerance: the window tone-maps on the GPU (tone_map.frag.glsl), the PNG writer on the CPU
  // (render::toneMap); the two may round differently by one level. The overlay (top left, white
  // text on a dark box) or a wrong buffer would break both bounds by far.
  double sumAbs = 0.0;
  std::size_t within2 = 0;
  for (std::size_t i = 0; i < shot->rgb.size(); ++i) {
    const int d = std::abs(int(shot->rgb[i]) - int(expected->rgb[i]));
    sumAbs += d;
    within2 += d <= 2 ? 1 : 0;
  }
  const double bytes = double(shot->rgb.size());
  RecordProperty("mean_abs_levels", std::to_string(sumAbs / bytes));
  RecordProperty("share_within_2_levels", std::to_string(double(within2) / bytes));
  EXPECT_LT(sumAbs / bytes, 1.0) << "mean absolute difference in 8-bit levels";
  EXPECT_GE(double(within2) / bytes, 0.999) << "share of bytes within 2 levels";
  // Not a match of two empty pictures: the spheres are lit.
  const double meanLevel =
      double(std::accumulate(expected->rgb.begin(), expected->rgb.end(), std::uint64_t{0})) / bytes;
  EXPECT_GT(meanLevel, 20.0);
}

// The issue: "the window shows the plate with the synthetic objects in it". The composite of the
// simulated plate in a window, both renderers for the layers; its --screenshot (what the window
// shows, at the plate's size, before the overlay) is the headless run's picture.
TEST_F(VemviewWindow, CompositeWindowShowsWhatTheHeadlessCompositeWrites) {
  if (!xvfbRunInstalled()) {
    GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb)";
  }
  const std::string map = std::string(VEM_SHARED_DATA_DIR) + "/hdri/sky.exr";
  for (const std::string renderer : {"embree", "gl"}) {
    const std::string args = " --plate sim --renderer " + renderer + " --map " + map +
                             " --width 160 --count 64 --frames 2 ";
    const CommandRun window = runUnderXvfb(args + "--screenshot " + path(renderer + ".png"));
    ASSERT_EQ(window.exitCode, 0) << window.err;
    const CommandRun headless = run(kTimeout, args + "--headless --out " + path(renderer));
    ASSERT_EQ(headless.exitCode, 0) << headless.err;
    const auto shot = vem::render::loadSrgb8(dir_ / (renderer + ".png"));
    ASSERT_TRUE(shot.has_value()) << shot.error();
    const auto expected = vem::render::loadSrgb8(dir_ / renderer / "frame-000000.png");
    ASSERT_TRUE(expected.has_value()) << expected.error();
    ASSERT_EQ(shot->widthPx, 160);
    ASSERT_EQ(shot->heightPx, 120);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < shot->rgb.size(); ++i) {
      differing += std::abs(int(shot->rgb[i]) - int(expected->rgb[i])) > 1 ? 1U : 0U;
    }
    EXPECT_LT(double(differing) / double(shot->rgb.size()), 0.001) << renderer;
  }
}

TEST_F(VemviewWindow, WindowWithoutADisplayFailsWithOneSentence) {
  const CommandRun r = run(std::string(kTimeout) + "env -u DISPLAY -u WAYLAND_DISPLAY ",
                        " --width 64 --height 48 --frames 1 --scene spheres --count 16 "
                        "--shadowed 8");
  EXPECT_NE(r.exitCode, 0) << r.err;
  std::size_t errorLines = 0;
  std::string errorLine;
  std::size_t start = 0;
  while (start < r.err.size()) {
    const std::size_t end = std::min(r.err.find('\n', start), r.err.size());
    const std::string line = r.err.substr(start, end - start);
    if (line.starts_with("vemview: error: ")) {
      ++errorLines;
      errorLine = line;
    }
    start = end + 1;
  }
  EXPECT_EQ(errorLines, 1U) << r.err;
  EXPECT_NE(errorLine.find("no display"), std::string::npos) << r.err;
  EXPECT_NE(errorLine.find("DISPLAY"), std::string::npos) << r.err;
  EXPECT_NE(errorLine.find("--headless"), std::string::npos) << r.err;
}

}  // namespace
