// `vemtool synth`, `export` and `import` as a user meets them (the built executable): a synthetic
// recording that info describes, a frame exported to a map that `lights` reads and that points at
// the scene's sun, raw codes exported bit for bit, shared HDRIs imported, and one error line with
// nothing left at --out for each kind of bad input.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "core/color.h"
#include "mapio/map_file.h"
#include "recording/recording_reader.h"
#include "support/command_run.h"
#include "synth/default_camera.h"
#include "synth/sky_scene.h"

namespace {

namespace fs = std::filesystem;
using vem::testing::CommandRun;
using vem::testing::readTextFile;

const std::string kHdri = std::string(VEM_SHARED_DATA_DIR) + "/hdri/";

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

class VemtoolSynthCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const fs::path root = fs::temp_directory_path() /
                          ("vemtool_synth_cli_" + std::to_string(::getpid()) + "_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    logs_ = root / "logs";
    dir_ = root / "work";
    fs::create_directories(logs_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_.parent_path()); }

  CommandRun run(const std::string& args) const {
    return vem::testing::runCommand(vem::testing::commandLine(VEMTOOL_PATH, args), logs_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The names in the work folder (temporary files included: they start with a dot).
  std::vector<std::string> workFiles() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
    std::ranges::sort(names);
    return names;
  }
  // A failed command: a non-zero exit, one error line, and the work folder as it was.
  void expectRefused(const std::string& args, const std::string& errorPart) const {
    const std::vector<std::string> before = workFiles();
    const CommandRun r = run(args);
    EXPECT_NE(r.exitCode, 0) << args;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_TRUE(r.err.starts_with("vemtool: error: ")) << r.err;
    EXPECT_NE(r.err.find(errorPart), std::string::npos) << r.err;
    EXPECT_EQ(workFiles(), before) << args;
  }

  fs::path logs_;
  fs::path dir_;
};

TEST_F(VemtoolSynthCli, SynthRecordsNFramesAtTheRateThatInfoReports) {
  const CommandRun r = run("synth --scene sky --frames 3 --rate 30 --out " + path("sky.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + path("sky.vem") + ": 3 frames of scene sky at 30 Hz"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(workFiles(), std::vector<std::string>{"sky.vem"});  // no temporary left

  const CommandRun i = run("info " + path("sky.vem") + " --format json");
  ASSERT_EQ(i.exitCode, 0) << i.err;
  const auto j = nlohmann::json::parse(i.out);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["first_seq"], 0);
  EXPECT_EQ(j["last_seq"], 2);
  EXPECT_EQ(j["first_ts_ns"], 0);
  EXPECT_EQ(j["last_ts_ns"], 66'666'667);  // 2 x 1e9 / 30, rounded
  EXPECT_EQ(j["nominal_rate_hz"], 30.0);
  EXPECT_NEAR(double(j["mean_rate_hz"]), 30.0, 1e-3);
  EXPECT_EQ(j["camera"]["model"], "HDRC-Example");
  EXPECT_EQ(j["sensor"]["pixel_format"], "RGB12");
  EXPECT_EQ(j["writer"]["name"], "vemtool synth");
  EXPECT_EQ(j["index"], "valid");

  // The header holds the camera the frames were rendered through: the built-in example.
  auto reader = vem::recording::RecordingReader::open(path("sky.vem"));
  ASSERT_TRUE(reader);
  const auto stored = vem::calib::io::parseCameraFile(reader->header().calibrationToml, "header");
  const auto example =
      vem::calib::io::parseCameraFile(std::string(vem::synth::exampleCameraToml()), "example");
  ASSERT_TRUE(stored && example);
  EXPECT_EQ(vem::calib::io::formatCameraFile(*stored), vem::calib::io::formatCameraFile(*example));
}

TEST_F(VemtoolSynthCli, SynthCreatesTheFolderOfItsOutput) {
  const CommandRun r =
      run("synth --scene sky --frames 1 --rate 30 --out " + path("runs/a/sky.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "runs" / "a" / "sky.vem"));
}

TEST_F(VemtoolSynthCli, ExportedFrameIsAMapWhoseStrongestLightIsTheSun) {
  ASSERT_EQ(run("synth --scene sky --frames 3 --rate 30 --out " + path("sky.vem")).exitCode, 0);
  const CommandRun e = run("export " + path("sky.vem") + " --frame 2 --out " + path("sky-2.exr"));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_NE(e.out.find("1024 x 256 hemisphere map"), std::string::npos) << e.out;
  const auto map = vem::mapio::loadMap(path("sky-2.exr"));
  ASSERT_TRUE(map);
  EXPECT_EQ(map->width, 1024);
  EXPECT_EQ(map->height, 256);

  const CommandRun l = run("lights --in " + path("sky-2.exr") + " --count 1024 --cluster 256");
  ASSERT_EQ(l.exitCode, 0) << l.err;
  const auto lights = nlohmann::json::parse(l.out)["lights"];
  const auto strongest = std::ranges::max_element(lights, {}, [](const nlohmann::json& light) {
    return vem::luminance(double(light["rgb"][0]), double(light["rgb"][1]),
                          double(light["rgb"][2]));
  });
  const glm::dvec3 dir((*strongest)["dir"][0], (*strongest)["dir"][1], (*strongest)["dir"][2]);
  const glm::dvec3 sun = vem::synth::sunDirection(vem::synth::SunArc{}, 2.0 / 30.0);
  EXPECT_LT(std::acos(std::min(1.0, glm::dot(glm::normalize(dir), sun))) * 180.0 / std::numbers::pi,
            1.0);
}

// Issue 17: `vemtool synth --scene clouds --frames 300 --out runs/clouds.vem` failed with
// "--rate is required"; without --rate the recording runs at the scene's natural rate.
TEST_F(VemtoolSynthCli, SynthWithoutRateRecordsAtTheScenesNaturalRate) {
  const CommandRun r = run("synth --scene clouds --frames 2 --out " + path("clouds.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("2 frames of scene clouds at 30 Hz"), std::string::npos) << r.out;
  const CommandRun i = run("info " + path("clouds.vem") + " --format json");
  ASSERT_EQ(i.exitCode, 0) << i.err;
  const auto j = nlohmann::json::parse(i.out);
  EXPECT_EQ(j["nominal_rate_hz"], 30.0);
  EXPECT_EQ(j["last_ts_ns"], 33'333'333);  // 1e9 / 30, rounded
  const CommandRun help = run("synth --help");
  EXPECT_NE(help.out.find("default: the scene's natural rate, 30 Hz"), std::string::npos)
      << help.out;
}

TEST_F(VemtoolSynthCli, ExportRawWritesTheRecordedCodesBitForBit) {
  ASSERT_EQ(
      run("synth --scene fluorescent --frames 2 --rate 30 --noise 2 --out " + path("room.vem"))
          .exitCode,
      0);
  const CommandRun e =
      run("export " + path("room.vem") + " --frame 1 --raw --out " + path("room-1.png"));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  const auto png = vem::calib::io::loadRawFrame(path("room-1.png"), 12);
  ASSERT_TRUE(png) << png.error().message;
  auto reader = vem::recording::RecordingReader::open(path("room.vem"));
  ASSERT_TRUE(reader);
  ASSERT_TRUE(*reader->seek(1));
  const auto recorded = reader->next();
  ASSERT_TRUE(recorded && *recorded);
  EXPECT_EQ((*recorded)->seq, 1u);
  EXPECT_EQ(png->codes, (*recorded)->frame.codes);
}

TEST_F(VemtoolSynthCli, ImportRecordsEachSharedHdriAsAFrame) {
  const CommandRun r = run("import --in " + kHdri + "park.exr " + kHdri +
                           "sky.exr --rate 10 --out " + path("two.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("2 frames from 2 files at 10 Hz"), std::string::npos) << r.out;
  const CommandRun i = run("info " + path("two.vem") + " --format json");
  const auto j = nlohmann::json::parse(i.out);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["last_ts_ns"], 100'000'000);
  EXPECT_EQ(j["writer"]["name"], "vemtool import");
  // Each frame shows its own map: sky.exr's sun is far brighter than anything in park.exr's sky.
  ASSERT_EQ(run("export " + path("two.vem") + " --frame 0 --out " + path("0.exr")).exitCode, 0);
  ASSERT_EQ(run("export " + path("two.vem") + " --frame 1 --out " + path("1.exr")).exitCode, 0);
  const auto first = vem::mapio::loadMap(path("0.exr"));
  const auto second = vem::mapio::loadMap(path("1.exr"));
  ASSERT_TRUE(first && second);
  EXPECT_NE(first->rgb, second->rgb);
}

TEST_F(VemtoolSynthCli, ImportExpandsAQuotedPatternInSortedOrder) {
  const CommandRun r =
      run("import --in '" + kHdri + "su*.exr' --rate 30 --out " + path("suns.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("2 frames from 2 files"), std::string::npos) << r.out;  // sunrise, sunset
}

TEST_F(VemtoolSynthCli, ImportTreatsVideoCodesOverTwoFiftyFiveAsLinearRadiance) {
  // Three frames of one colour (B, G, R = 20, 100, 200), Motion JPEG (OpenCV's own encoder).
  cv::VideoWriter video(path("pano.avi"), cv::CAP_OPENCV_MJPEG,
                        cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(128, 64));
  ASSERT_TRUE(video.isOpened());
  for (int k = 0; k < 3; ++k) video.write(cv::Mat(64, 128, CV_8UC3, cv::Scalar(20, 100, 200)));
  video.release();
  const CommandRun r =
      run("import --in " + path("pano.avi") + " --rate 10 --scale 100 --out " + path("pano.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("3 frames from 1 files at 10 Hz"), std::string::npos) << r.out;
  ASSERT_EQ(run("export " + path("pano.vem") + " --frame 2 --out " + path("2.exr")).exitCode, 0);
  const auto map = vem::mapio::loadMap(path("2.exr"));
  ASSERT_TRUE(map);
  const glm::vec3 zenith = map->at(0, 0);  // R, G, B = (200, 100, 20) / 255 x 100 cd/m2
  EXPECT_NEAR(zenith.r, 78.4, 4.0);
  EXPECT_NEAR(zenith.g, 39.2, 2.0);
  EXPECT_NEAR(zenith.b, 7.8, 1.0);
}

TEST_F(VemtoolSynthCli, UnknownSceneIsRefusedAndWritesNothing) {
  expectRefused("synth --scene skies --frames 2 --rate 30 --out " + path("x.vem"),
                "unknown scene 'skies' (expected one of sky, clouds, hdri:FILE, fluorescent, "
                "exposure-jump)");
  expectRefused(
      "synth --scene hdri:" + path("none.exr") + " --frames 2 --rate 30 --out " + path("x.vem"),
      "none.exr");
}

TEST_F(VemtoolSynthCli, ExistingOutputIsKeptUnlessOverwriteIsGiven) {
  std::ofstream(path("keep.vem")) << "precious";
  expectRefused("synth --scene sky --frames 1 --rate 30 --out " + path("keep.vem"),
                "a file is already there");
  EXPECT_EQ(readTextFile(path("keep.vem")), "precious");
  const CommandRun r =
      run("synth --scene sky --frames 1 --rate 30 --overwrite --out " + path("keep.vem"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(readTextFile(path("keep.vem")), "precious");
}

TEST_F(VemtoolSynthCli, CameraWithoutALensIsRefused) {
  auto camera =
      vem::calib::io::parseCameraFile(std::string(vem::synth::exampleCameraToml()), "example");
  ASSERT_TRUE(camera);
  camera->lens.reset();
  ASSERT_TRUE(vem::calib::io::saveCameraFile(*camera, path("nolens.toml")));
  expectRefused("synth --scene sky --frames 1 --rate 30 --camera " + path("nolens.toml") +
                    " --out " + path("x.vem"),
                "the camera has no geometric section");
}

TEST_F(VemtoolSynthCli, ExportOfAMissingFrameNamesTheFramesThereAre) {
  ASSERT_EQ(run("synth --scene sky --frames 3 --rate 30 --out " + path("sky.vem")).exitCode, 0);
  expectRefused("export " + path("sky.vem") + " --frame 7 --out " + path("x.exr"),
                "no frame with sequence number 7 (its 3 frames run from 0 to 2)");
  expectRefused("export " + path("missing.vem") + " --frame 0 --out " + path("x.exr"),
                "missing.vem: no such file");
}

TEST_F(VemtoolSynthCli, ImportFailingMidwayLeavesNoPartialRecording) {
  // A polar (hemisphere) map is not equirectangular: the second input fails after the first frame.
  ASSERT_EQ(run("synth --scene sky --frames 1 --rate 30 --out " + path("sky.vem")).exitCode, 0);
  ASSERT_EQ(run("export " + path("sky.vem") + " --frame 0 --out " + path("polar.exr")).exitCode, 0);
  expectRefused("import --in " + kHdri + "park.exr " + path("polar.exr") + " --rate 30 --out " +
                    path("x.vem"),
                "not equirectangular (expected width = 2 x height)");
  expectRefused("import --in " + path("nothing.exr") + " --rate 30 --out " + path("x.vem"),
                "nothing.exr: no such file");
  expectRefused("import --in '" + path("nothing-*.exr") + "' --rate 30 --out " + path("x.vem"),
                "no file matches the pattern");
}

TEST_F(VemtoolSynthCli, EveryCommandHasHelpWithAnExample) {
  for (const char* command : {"synth", "export", "import"}) {
    const CommandRun r = run(std::string(command) + " --help");
    EXPECT_EQ(r.exitCode, 0) << command;
    EXPECT_NE(r.out.find("Example:"), std::string::npos) << command;
  }
  EXPECT_NE(run("import --help").out.find("TREATED AS LINEAR"), std::string::npos);
}

}  // namespace
