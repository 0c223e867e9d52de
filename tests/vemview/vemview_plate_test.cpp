// vemview --plate as a user meets it (the built executable, headless): synthetic objects
// composited into a scene camera's picture (issue 21). The plate is the simulated real world
// (client/scene/mixed_reality_world.h), rendered here by the Monte Carlo reference, exposed and
// written as an 8-bit sRGB picture; its plate-camera file is the world's camera at 160 x 120.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "calib/core/plate_camera.h"
#include "calib/io/plate_camera_file.h"
#include "client/embree/embree_scene.h"
#include "client/embree/reference_renderer.h"
#include "client/render/image_files.h"
#include "client/render/tone_mapping.h"
#include "client/scene/mixed_reality_world.h"
#include "mapio/map_file.h"
#include "vemview/golden_compare.h"
#include "vemview/vemview_process.h"

namespace {

namespace fs = std::filesystem;
using vem::testing::CommandRun;

constexpr int kPlateW = 160;
constexpr int kPlateH = 120;

std::string skyMap() { return std::string(VEM_SHARED_DATA_DIR) + "/hdri/sky.exr"; }

std::vector<nlohmann::json> jsonLines(const fs::path& path) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// The plate and its camera, made once for the suite.
struct PlateFixture {
  std::vector<std::uint8_t> srgb;  // kPlateW x kPlateH, RGB
  double gain = 1.0;               // plate linear value per unit of the map's radiance
  fs::path folder;
};

const PlateFixture& plateFixture() {
  static const PlateFixture fixture = [] {
    PlateFixture f;
    f.folder = fs::temp_directory_path() / ("vemview_plate_" + std::to_string(::getpid()));
    fs::create_directories(f.folder);
    const vem::scene::MixedRealityWorld world = vem::scene::mixedRealityWorld();
    auto map = vem::mapio::loadMap(skyMap());
    auto scene = vem::embree::EmbreeScene::build(world.realSurfaces);
    if (!map || !scene) return f;
    vem::embree::ReferenceOptions options;
    options.targetRelativeError = 0.05;
    vem::render::LinearImage image =
        vem::embree::renderReference(*scene, vem::scene::plateViewCamera(world), kPlateW, kPlateH,
                                     *map, options)
            .image;
    double meanY = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) meanY += double(image.rgb[3 * i + 1]);
    meanY /= double(image.pixelCount());
    f.gain = 0.35 / meanY;  // the camera's exposure: the mean at 0.35 of its white
    for (float& v : image.rgb) v = float(double(v) * f.gain);
    f.srgb = vem::render::displaySrgb8(image);
    (void)vem::render::saveSrgbPng(f.srgb, kPlateW, kPlateH, f.folder / "plate.png");
    // The world's camera at 160 x 120 (a quarter of 640 x 480), no distortion.
    vem::calib::PlateCamera camera;
    camera.camera.model = "simulated";
    camera.camera.serial = "world";
    camera.camera.sensorWidthPx = kPlateW;
    camera.camera.sensorHeightPx = kPlateH;
    camera.camera.pixelFormat = vem::PixelFormat{3, 8};
    const double s = double(kPlateW) / double(world.intrinsics.widthPx);
    camera.intrinsics = {kPlateW,
                         kPlateH,
                         world.intrinsics.fxPx * s,
                         world.intrinsics.fyPx * s,
                         (world.intrinsics.cxPx + 0.5) * s - 0.5,
                         (world.intrinsics.cyPx + 0.5) * s - 0.5,
                         vem::calib::PlateLensModel::BrownConrady,
                         {}};
    camera.pose = vem::calib::plateLookingAt({0.25, 0.95, 2.1}, {-0.05, 0.28, 0.0});
    camera.colour = vem::calib::PlateColourMatch{{f.gain, f.gain, f.gain}, 0.0, 1, ""};
    (void)vem::calib::io::savePlateCameraFile(camera, f.folder / "plate-camera.toml");
    return f;
  }();
  return fixture;
}

class VemviewPlate : public vem::testing::VemviewProcessTest {
 protected:
  static void TearDownTestSuite() { fs::remove_all(plateFixture().folder); }
  CommandRun run(const std::string& args) const { return VemviewProcessTest::run("", args); }
  static std::string plate() { return (plateFixture().folder / "plate.png").string(); }
  static std::string plateCamera() {
    return (plateFixture().folder / "plate-camera.toml").string();
  }
  std::string common() const {
    return " --headless --count 64 --map " + skyMap() + " --plate-camera " + plateCamera() + " ";
  }
  void expectRefused(const std::string& args, const std::string& part, int status) const {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, status) << args << "\n" << r.err;
    // One error line (a warning about the map may come before it), naming `part`.
    const std::size_t at = r.err.find("vemview: error: ");
    ASSERT_NE(at, std::string::npos) << r.err;
    const std::string line = r.err.substr(at);
    EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find("error", at + 16), std::string::npos) << r.err;
    EXPECT_NE(line.find(part), std::string::npos) << r.err;
  }
};

TEST_F(VemviewPlate, PlateLargerThanTheRenderComesOutAtItsOwnSizeUntouchedWhereNothingChanged) {
  ASSERT_FALSE(plateFixture().srgb.empty());
  const CommandRun r = run(common() + "--plate " + plate() + " --width 80 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("composite into image"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("differential"), std::string::npos) << r.err;
  const auto out = vem::render::loadSrgb8(fs::path(path("out")) / "frame-000000.png");
  ASSERT_TRUE(out.has_value()) << out.error();
  ASSERT_EQ(out->widthPx, kPlateW);  // the plate's size, not the render's 80 x 60
  ASSERT_EQ(out->heightPx, kPlateH);
  // Away from the objects and their shadows the composite is the plate, byte for byte: decoded
  // once, composited in linear light, encoded once, with no tone mapping in between.
  std::size_t same = 0;
  std::size_t withinOne = 0;
  std::size_t darker = 0;
  for (std::size_t i = 0; i < out->rgb.size(); ++i) {
    const int d = int(out->rgb[i]) - int(plateFixture().srgb[i]);
    same += d == 0 ? 1U : 0U;
    withinOne += std::abs(d) <= 1 ? 1U : 0U;
    darker += d < -8 ? 1U : 0U;
  }
  std::printf("same %.3f, within one level %.3f, darker by 8 levels %zu\n",
              double(same) / double(out->rgb.size()), double(withinOne) / double(out->rgb.size()),
              darker);
  EXPECT_GT(double(same) / double(out->rgb.size()), 0.5);
  EXPECT_GT(darker, 150U);  // the spheres' shadows on the real floor (and the spheres)
  const auto lines = jsonLines(fs::path(path("out")) / "timing.jsonl");
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_GT(lines[0]["object_px"].get<int>(), 1000);
}

TEST_F(VemviewPlate, UnchangedLightsReuseTheRenderWithoutTheObjects) {
  const CommandRun r = run(common() + "--plate " + plate() +
                           " --width 80 --frames 3 --orbit 0 "
                           "--out " +
                           path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = jsonLines(fs::path(path("out")) / "timing.jsonl");
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_FALSE(lines[0]["without_reused"].get<bool>());
  // Nothing changed after the first frame: the plan does not redraw at all.
  EXPECT_FALSE(lines[1]["drawn"].get<bool>());
}

TEST_F(VemviewPlate, VideoPlateThatEndsStopsTheRunAfterItsLastFrameAndTheVideoHoldsThemAll) {
  ASSERT_FALSE(plateFixture().srgb.empty());
  const std::string video = path("plate.mp4");
  {
    cv::VideoWriter writer(video, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), 30.0,
                           cv::Size(kPlateW, kPlateH));
    ASSERT_TRUE(writer.isOpened());
    cv::Mat rgb(kPlateH, kPlateW, CV_8UC3, const_cast<std::uint8_t*>(plateFixture().srgb.data()));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    for (int i = 0; i < 3; ++i) writer.write(bgr);
  }
  const CommandRun r = run(common() + "--plate " + video + " --width 80 --frames 10 --video " +
                           path("composite.mp4") + " --no-exr --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("the plate ended"), std::string::npos) << r.err;
  const auto lines = jsonLines(fs::path(path("out")) / "timing.jsonl");
  ASSERT_EQ(lines.size(), 4U);  // three pictures, then the end seen on the fourth
  EXPECT_EQ(lines[2]["plate_seq"].get<int>(), 3);
  EXPECT_TRUE(lines[2]["drawn"].get<bool>());
  // A new picture under the same lights: the render without the objects is kept.
  EXPECT_FALSE(lines[0]["without_reused"].get<bool>());
  EXPECT_TRUE(lines[1]["without_reused"].get<bool>());
  EXPECT_FALSE(lines[3]["drawn"].get<bool>());  // no new picture: nothing to redraw
  cv::VideoCapture written(path("composite.mp4"), cv::CAP_FFMPEG);
  ASSERT_TRUE(written.isOpened());
  EXPECT_EQ(int(written.get(cv::CAP_PROP_FRAME_WIDTH)), kPlateW);
  int frames = 0;
  for (cv::Mat frame; written.read(frame);) ++frames;
  EXPECT_GE(frames, 3);
}

TEST_F(VemviewPlate, PlateOfAnotherCamerasSizeIsOneSentenceNamingTheIntrinsics) {
  ASSERT_FALSE(plateFixture().srgb.empty());
  cv::Mat small(60, 80, CV_8UC3, cv::Scalar(90, 90, 90));
  ASSERT_TRUE(cv::imwrite(path("small.png"), small));
  expectRefused(common() + "--plate " + path("small.png"), "intrinsics: calibrated for 160 x 120",
                1);
}

TEST_F(VemviewPlate, MissingPlateCameraFileIsOneSentenceNamingIt) {
  expectRefused(" --headless --plate " + plate() + " --plate-camera " + path("none.toml"),
                path("none.toml"), 1);
}

TEST_F(VemviewPlate, LightProbeCameraFileGivenAsThePlateCameraIsRefusedInOneSentence) {
  const std::string probe = std::string(VEM_SOURCE_DIR) + "/config/camera-example.toml";
  expectRefused(" --headless --plate " + plate() + " --plate-camera " + probe,
                "camera-example.toml", 1);
}

TEST_F(VemviewPlate, PlateWithoutItsCameraOrWithTheReferenceRendererIsAUsageError) {
  expectRefused(" --headless --plate " + plate(), "--plate-camera", 2);
  expectRefused(" --headless --plate sim --renderer reference", "not reference", 2);
  expectRefused(" --headless --place 0,0,0,0", "--plate SOURCE", 2);
}

// The composite of the simulated plate under the sun by each renderer, against its golden
// picture (golden_compare.h's tolerances): the spheres, their sun shadows on the tiles and the box.
TEST_F(VemviewPlate, SimulatedPlateCompositeLooksAsItDidInBothRenderers) {
  for (const std::string renderer : {"embree", "gl"}) {
    const std::string out = path("out-" + renderer);
    const CommandRun r =
        run(" --headless --plate sim --width 160 --count 256 --soft-shadows "
            "--shadowed 256 --renderer " +
            renderer + " --map " + skyMap() + " --no-exr --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto picture = vem::render::loadSrgb8(fs::path(out) / "frame-000000.png");
    ASSERT_TRUE(picture.has_value()) << picture.error();
    vem::testing::compareSrgb8WithGolden(picture->rgb, picture->widthPx, picture->heightPx,
                                         "composite-sim-sky-" + renderer + ".png");
  }
}

TEST_F(VemviewPlate, SimulatedPlateCompositesWithNoCameraAndNoFile) {
  const CommandRun r = run(" --headless --plate sim --width 64 --count 16 --map " + skyMap() +
                           " --place 0.1,0,0,30 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("composite into sim"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 proxy meshes"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(fs::path(path("out")) / "frame-000000.png"));
}

}  // namespace
