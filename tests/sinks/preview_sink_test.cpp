// The preview image: a PNG of the polar map at the map's size times the scale, lights as green
// discs at their directions' pixels and sized by power, clusters as rings of the clustering radius,
// Reinhard tone mapping, one image every N frames, replaced atomically.
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include <opencv2/imgcodecs.hpp>

#include "sinks/sink_test_frames.h"
#include "vemd/sinks/preview_image.h"
#include "vemd/sinks/preview_sink.h"

namespace vem::testing {
namespace {

using vemd::PreviewSink;

constexpr int kW = 120;
constexpr int kH = 30;
constexpr int kScale = 4;
constexpr double kDeg = std::numbers::pi / 180.0;

class PreviewSinkTest : public SinkFiles {};

EnvMap greyMap(float level = 0.5F) {
  return EnvMap::filled(MapLayout::Hemisphere, kW, kH, glm::vec3(level));
}

LightSet lightsAt(std::initializer_list<std::pair<glm::vec3, float>> dirsAndPower) {
  LightSet set;
  std::uint32_t id = 0;
  for (const auto& [dir, power] : dirsAndPower) set.lights.push_back({id++, dir, glm::vec3(power)});
  return set;
}

bool isLightColour(const cv::Vec3b& bgr) { return bgr == vemd::kPreviewLightBgr; }

// Mean pixel position (continuous: pixel i covers [i, i + 1)) and count of exactly green pixels
// in a window.
struct Blob {
  double x = 0.0, y = 0.0;
  int pixels = 0;
};
Blob greenBlob(const cv::Mat& image, cv::Rect window) {
  Blob blob;
  window &= cv::Rect(0, 0, image.cols, image.rows);
  for (int y = window.y; y < window.br().y; ++y) {
    for (int x = window.x; x < window.br().x; ++x) {
      if (!isLightColour(image.at<cv::Vec3b>(y, x))) continue;
      blob.x += x + 0.5;
      blob.y += y + 0.5;
      ++blob.pixels;
    }
  }
  if (blob.pixels > 0) {
    blob.x /= blob.pixels;
    blob.y /= blob.pixels;
  }
  return blob;
}

vemd::PreviewStyle style() { return {.scale = kScale}; }

TEST_F(PreviewSinkTest, PngDecodesWithTheMapSizeTimesTheScale) {
  auto sink = PreviewSink::create(dir_ / "out", {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink) << sink.error().message;
  TestFrame frame(0);
  frame.polar = greyMap();
  ASSERT_TRUE(sink->consume(frame.processed));
  const cv::Mat png = cv::imread(sink->latestPath().string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.cols, kW * kScale);
  EXPECT_EQ(png.rows, kH * kScale);
  EXPECT_EQ(png.type(), CV_8UC3);
}

// theta 30.9 deg, phi 113.1 deg: map coordinates (37.7, 10.3), image (150.8, 41.2) at scale 4.
TEST_F(PreviewSinkTest, LightIsDrawnCentredOnThePixelOfItsDirection) {
  const glm::vec3 dir = unitDirection(30.9 * kDeg, 113.1 * kDeg);
  const glm::dvec2 coords = vemd::mapCoordsOfDirection(MapLayout::Hemisphere, kW, kH, dir);
  EXPECT_NEAR(coords.x, 37.7, 1e-4);
  EXPECT_NEAR(coords.y, 10.3, 1e-4);

  auto sink = PreviewSink::create(dir_, {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink);
  TestFrame frame(0);
  frame.polar = greyMap();
  frame.processed.lights = lightsAt({{dir, 1.0F}});
  ASSERT_TRUE(sink->consume(frame.processed));
  const cv::Mat png = cv::imread(sink->latestPath().string());
  ASSERT_FALSE(png.empty());

  EXPECT_TRUE(isLightColour(png.at<cv::Vec3b>(41, 150))) << png.at<cv::Vec3b>(41, 150);
  const Blob blob = greenBlob(png, cv::Rect(120, 10, 60, 60));
  ASSERT_GT(blob.pixels, 0);
  EXPECT_NEAR(blob.x, 150.8, 0.3) << "the disc is centred on the direction";
  EXPECT_NEAR(blob.y, 41.2, 0.3);
  // Not at the mirror images a sign error would give: phi -> -phi, theta from the horizon.
  EXPECT_FALSE(isLightColour(png.at<cv::Vec3b>(41, kW * kScale - 151)));
  EXPECT_FALSE(isLightColour(png.at<cv::Vec3b>(kH * kScale - 42, 150)));
  // And the rest is the map.
  EXPECT_EQ(png.at<cv::Vec3b>(100, 400), cv::Vec3b(109, 109, 109));
}

TEST_F(PreviewSinkTest, BrighterLightsGetLargerDots) {
  const LightSet lights = lightsAt({{unitDirection(45 * kDeg, 90 * kDeg), 1.0F},
                                    {unitDirection(45 * kDeg, 270 * kDeg), 100.0F}});
  const cv::Mat image = vemd::previewImage(greyMap(), lights, nullptr, style());
  const Blob dim = greenBlob(image, cv::Rect(60, 30, 120, 60));
  const Blob bright = greenBlob(image, cv::Rect(300, 30, 120, 60));
  ASSERT_GT(dim.pixels, 0);
  EXPECT_GT(bright.pixels, 4 * dim.pixels) << "area grows with power";
}

TEST_F(PreviewSinkTest, ClustersAreRingsOfTheClusteringRadius) {
  const glm::vec3 centre = unitDirection(45 * kDeg, 180 * kDeg);  // image (240, 60)
  Clustering clustering;
  clustering.clusters = lightsAt({{centre, 2.0F}});
  clustering.clusterOfLight = {0, 0};
  clustering.radiusRad = 0.4;
  const LightSet lights = lightsAt({{centre, 1.0F}, {unitDirection(47 * kDeg, 181 * kDeg), 1.0F}});
  const double radiusRad = clustering.radiusRad;
  const double radiusPx = radiusRad / (std::numbers::pi / 2) * kH * kScale;  // 30.6
  const cv::Mat image = vemd::previewImage(greyMap(), lights, &clustering, style());
  // Up the column through the centre (x = 239.5 continuous -> column 239 or 240), the most
  // orange pixel lies on the ring.
  int bestRow = -1;
  double bestDistance = 1e9;
  for (int y = 0; y < 60; ++y) {
    const cv::Vec3d bgr(image.at<cv::Vec3b>(y, 239));
    const double distance = cv::norm(bgr - cv::Vec3d(vemd::kPreviewClusterBgr));
    if (distance < bestDistance) {
      bestDistance = distance;
      bestRow = y;
    }
  }
  EXPECT_LT(bestDistance, 60.0) << "no orange ring above the cluster";
  EXPECT_NEAR(60.0 - (bestRow + 0.5), radiusPx, 1.5);
  EXPECT_TRUE(isLightColour(image.at<cv::Vec3b>(59, 239))) << "lights are drawn over the rings";
}

TEST_F(PreviewSinkTest, LightAtTheSeamWrapsAroundToBothEdges) {
  const LightSet lights = lightsAt({{unitDirection(45 * kDeg, 1 * kDeg), 1.0F}});
  const cv::Mat image = vemd::previewImage(greyMap(), lights, nullptr, style());
  EXPECT_TRUE(isLightColour(image.at<cv::Vec3b>(60, 0)));
  EXPECT_TRUE(isLightColour(image.at<cv::Vec3b>(60, kW * kScale - 1)));
}

// Reinhard with key 0.18 maps the log-average to 0.18 / 1.18 = 0.153, sRGB 0.427: grey 109,
// whatever the map's absolute level.
TEST_F(PreviewSinkTest, UniformMapOfAnyBrightnessToneMapsToTheSameMidGrey) {
  for (const float level : {1e-3F, 1.0F, 2e4F}) {
    const cv::Mat image = vemd::toneMappedMap(greyMap(level), 1);
    ASSERT_EQ(image.size(), cv::Size(kW, kH));
    EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(109, 109, 109)) << level;
    EXPECT_EQ(image.at<cv::Vec3b>(kH - 1, kW - 1), cv::Vec3b(109, 109, 109)) << level;
  }
}

TEST_F(PreviewSinkTest, BrightSkyStaysBrighterThanGroundAndColoursKeepTheirHue) {
  EnvMap map = greyMap(1.0F);
  for (int x = 0; x < kW; ++x) map.set(x, 0, glm::vec3(5000.0F, 2000.0F, 100.0F));
  const cv::Mat image = vemd::toneMappedMap(map, 1);
  const cv::Vec3b sun = image.at<cv::Vec3b>(0, 5);
  const cv::Vec3b ground = image.at<cv::Vec3b>(kH - 1, 5);
  EXPECT_GT(sun[2], ground[2]);
  EXPECT_GT(sun[2], sun[1]);  // red > green > blue, as in the map (BGR order)
  EXPECT_GT(sun[1], sun[0]);
}

TEST_F(PreviewSinkTest, NonFinitePixelsAreBlackAndDoNotSpoilTheRest) {
  EnvMap map = greyMap(1.0F);
  map.set(3, 3, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  map.set(4, 3, glm::vec3(std::numeric_limits<float>::infinity()));
  map.set(5, 3, glm::vec3(-1.0F));
  const cv::Mat image = vemd::toneMappedMap(map, 1);
  EXPECT_EQ(image.at<cv::Vec3b>(3, 3), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(image.at<cv::Vec3b>(3, 4), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(image.at<cv::Vec3b>(3, 5), cv::Vec3b(0, 0, 0));
  EXPECT_GT(image.at<cv::Vec3b>(20, 20)[1], 100);
}

TEST_F(PreviewSinkTest, OnlyEveryNthFrameIsDrawnAndNoTemporaryFileIsLeft) {
  auto sink = PreviewSink::create(dir_, {.every = 3, .numbered = true, .style = style()});
  ASSERT_TRUE(sink);
  for (int i = 0; i < 7; ++i) {
    TestFrame frame(i);
    ASSERT_TRUE(sink->consume(frame.processed));
  }
  EXPECT_EQ(sink->imagesWritten(), 3U);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
  std::ranges::sort(names);
  EXPECT_EQ(names, (std::vector<std::string>{"preview-1152921504606846977.png",
                                             "preview-1152921504606846980.png",
                                             "preview-1152921504606846983.png", "preview.png"}));
  EXPECT_EQ(sink->numberedPath(42).filename(), "preview-0000000042.png");
}

// A viewer that opened preview.png keeps reading the whole old image while a new one replaces it
// (rename), rather than a truncated or mixed file (rewriting in place).
TEST_F(PreviewSinkTest, ReaderOfTheOldPreviewKeepsAWholeImageWhileANewOneIsWritten) {
  auto sink = PreviewSink::create(dir_, {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink);
  TestFrame first(0);
  first.polar = greyMap();
  ASSERT_TRUE(sink->consume(first.processed));
  const std::vector<char> before = readBytes(sink->latestPath());
  std::ifstream viewer(sink->latestPath(), std::ios::binary);
  TestFrame second(1);
  second.polar = greyMap();
  second.processed.lights = lightsAt({{unitDirection(60 * kDeg, 10 * kDeg), 1.0F}});
  ASSERT_TRUE(sink->consume(second.processed));
  const std::vector<char> seen{std::istreambuf_iterator<char>(viewer),
                               std::istreambuf_iterator<char>()};
  EXPECT_EQ(seen, before);
  EXPECT_NE(readBytes(sink->latestPath()), before);
  EXPECT_FALSE(
      cv::imdecode(std::vector<unsigned char>(seen.begin(), seen.end()), cv::IMREAD_COLOR).empty());
}

TEST_F(PreviewSinkTest, FrameWithAnEmptyPolarMapIsSkipped) {
  auto sink = PreviewSink::create(dir_, {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink);
  TestFrame frame(0);
  const EnvMap empty;
  frame.processed.polar = &empty;
  ASSERT_TRUE(sink->consume(frame.processed));
  EXPECT_EQ(sink->imagesWritten(), 0U);
  EXPECT_FALSE(fs::exists(sink->latestPath()));
}

TEST_F(PreviewSinkTest, WriteFailureIsReportedOnceThenTheSinkIsQuiet) {
  const fs::path out = dir_ / "out";
  auto sink = PreviewSink::create(out, {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink);
  fs::remove_all(out);
  TestFrame frame(0);
  auto failed = sink->consume(frame.processed);
  ASSERT_FALSE(failed);
  EXPECT_EQ(failed.error().message, "preview: cannot write " + (out / "preview.png").string() +
                                        " (No such file or directory); no more previews are "
                                        "written");
  EXPECT_TRUE(sink->consume(frame.processed));
  EXPECT_TRUE(sink->close());
}

// rename() fails when preview.png is a folder holding a file: the temporary file must go again.
TEST_F(PreviewSinkTest, FailedReplaceLeavesNoTemporaryFileBehind) {
  auto sink = PreviewSink::create(dir_, {.every = 1, .numbered = false, .style = style()});
  ASSERT_TRUE(sink);
  fs::create_directories(sink->latestPath() / "occupied");
  TestFrame frame(0);
  auto failed = sink->consume(frame.processed);
  ASSERT_FALSE(failed);
  EXPECT_TRUE(failed.error().message.starts_with("preview: cannot write " +
                                                 sink->latestPath().string() + " ("))
      << failed.error().message;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
  EXPECT_EQ(names, std::vector<std::string>{"preview.png"});
}

}  // namespace
}  // namespace vem::testing
