// vemcalib as a user meets it (runs the built executable): the path from a simulated chart to a
// camera file, every refusal of `vemcalib photometric` (one sentence on stderr, a non-zero exit,
// the old output file byte-identical), `apply` turning a frame back into the map the camera saw,
// and an example in every command's --help.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "calib/io/camera_file.h"
#include "calib/io/patch_file.h"
#include "calib/io/plate_camera_file.h"
#include "calib/io/plate_colour_file.h"
#include "calib/io/raw_frame_file.h"
#include "core/env_map.h"
#include "mapio/map_file.h"
#include "support/command_run.h"

namespace {

namespace fs = std::filesystem;
using vem::testing::CommandRun;
using vem::testing::readTextFile;
using namespace vem::calib;

const fs::path kExampleCamera = fs::path(VEM_SOURCE_DIR) / "config/camera-example.toml";

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

CommandRun runIn(const fs::path& dir, const std::string& args) {
  return vem::testing::runCommand(vem::testing::commandLine(VEMCALIB_PATH, args), dir);
}

// One chart simulated from the example camera, shared by the tests (simulating takes a second).
class VemcalibCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    chartDir_ = fs::temp_directory_path() / ("vemcalib_cli_chart_" + std::to_string(::getpid()));
    fs::create_directories(chartDir_);
    simulateRun_ = runIn(chartDir_, "simulate patches --camera " + kExampleCamera.string() +
                                        " --out " + (chartDir_ / "sim").string() + " --frames 2");
  }
  static void TearDownTestSuite() { fs::remove_all(chartDir_); }

  void SetUp() override {
    ASSERT_EQ(simulateRun_.exitCode, 0) << simulateRun_.err;
    dir_ = fs::temp_directory_path() / ("vemcalib_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  [[nodiscard]] CommandRun run(const std::string& args) const { return runIn(dir_, args); }
  [[nodiscard]] static fs::path sim(const std::string& name) { return chartDir_ / "sim" / name; }
  [[nodiscard]] static std::string frames() {
    return sim("patches-1.png").string() + " " + sim("patches-2.png").string();
  }
  [[nodiscard]] static std::vector<PatchSpec> chart() {
    return *io::loadPatchFile(sim("patches.toml"));
  }
  [[nodiscard]] static PatchSpec patch(const std::string& name) {
    const std::vector<PatchSpec> all = chart();
    return *std::ranges::find(all, name, &PatchSpec::name);
  }

  // `vemcalib photometric` on the chart with the example camera's levels, into dir/OUT.
  [[nodiscard]] CommandRun photometric(const std::string& framesArg, const fs::path& patches,
                                       const std::string& extra = "") const {
    return run("photometric --frame " + framesArg + " --patches " + patches.string() +
               " --bits 12 --black-level 64 --saturation 4095 --out " + out().string() + extra);
  }
  [[nodiscard]] fs::path out() const { return dir_ / "camera.toml"; }

  // Puts the example camera at the output path, for refusals to leave alone.
  std::string existingOutput() const {
    fs::copy_file(kExampleCamera, out(), fs::copy_options::overwrite_existing);
    return readTextFile(out());
  }

  [[nodiscard]] fs::path patchFile(const std::vector<PatchSpec>& patches) const {
    const fs::path path = dir_ / "patches.toml";
    EXPECT_TRUE(io::savePatchFile(patches, path));
    return path;
  }

  // The first chart frame with `patchName`'s region set to `code` in every channel.
  [[nodiscard]] std::string frameWithPatchAt(const std::string& patchName,
                                             std::uint16_t code) const {
    vem::RawFrame frame = *io::loadRawFrame(sim("patches-1.png"), 12);
    const PatchSpec p = patch(patchName);
    for (int v = p.y; v < p.y + p.height; ++v)
      for (int u = p.x; u < p.x + p.width; ++u)
        for (int c = 0; c < frame.format.channels; ++c) frame.codes[frame.index(u, v, c)] = code;
    const fs::path path = dir_ / ("damaged-" + patchName + ".png");
    EXPECT_TRUE(io::saveRawFrame(frame, path));
    return path.string();
  }

  // The refusal contract: one sentence on stderr, a non-zero exit, the old output unchanged.
  void expectRefused(const CommandRun& r, const std::string& before,
                     const std::string& mentions) const {
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("vemcalib: error: ", 0), 0U) << r.err;
    EXPECT_TRUE(contains(r.err, mentions)) << r.err;
    EXPECT_EQ(readTextFile(out()), before) << "the refused run changed " << out();
  }

  fs::path dir_;
  static inline fs::path chartDir_;
  static inline CommandRun simulateRun_;
};

TEST_F(VemcalibCli, NewUsersPathFromSimulatedChartToCameraFileRecoversTheExampleResponse) {
  // The command `simulate patches` prints is the one the user runs next.
  const std::string printed = simulateRun_.out;
  const std::size_t next = printed.find("next: vemcalib ");
  ASSERT_NE(next, std::string::npos) << printed;
  std::string command = printed.substr(next + 15, printed.find('\n', next) - next - 15);
  command.replace(command.find("--out "), std::string::npos, "--out " + out().string());
  const CommandRun fit = run(command);
  ASSERT_EQ(fit.exitCode, 0) << fit.err;
  EXPECT_EQ(fit.err, "");
  for (const char* row : {"p1 ", "p6 ", "c1 ", "c2 "})
    EXPECT_TRUE(contains(fit.out, row)) << fit.out;
  EXPECT_TRUE(contains(fit.out, "check")) << fit.out;
  EXPECT_TRUE(contains(fit.out, "rms residual")) << fit.out;

  const auto truth = io::loadCameraFile(kExampleCamera);
  const auto fitted = io::loadCameraFile(out());
  ASSERT_TRUE(fitted.has_value()) << fitted.error().message;
  const auto& want = std::get<LogResponse>(truth->photometric->response);
  const auto& got = std::get<LogResponse>(fitted->photometric->response);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(got.aCode[c], want.aCode[c], 1.0);
    EXPECT_NEAR(got.bCodePerLn[c] / want.bCodePerLn[c], 1.0, 0.005);
  }
  EXPECT_EQ(fitted->photometricQuality.fitPatches, 6);
  EXPECT_EQ(fitted->photometricQuality.checkPatches, 2);

  const CommandRun show = run("show " + out().string());
  ASSERT_EQ(show.exitCode, 0) << show.err;
  EXPECT_TRUE(contains(show.out, "log response")) << show.out;
  EXPECT_TRUE(contains(show.out, "1280 x 1024 px, RGB12")) << show.out;
  EXPECT_TRUE(contains(show.out, "geometric:    none")) << show.out;
}

TEST_F(VemcalibCli, PhotometricReplacesOnlyThePhotometricSectionOfAnExistingFile) {
  existingOutput();
  const CommandRun r =
      run("photometric --frame " + frames() + " --patches " + sim("patches.toml").string() +
          " --out " + out().string());  // bits and levels from the file
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto before = io::loadCameraFile(kExampleCamera);
  const auto after = io::loadCameraFile(out());
  ASSERT_TRUE(after.has_value()) << after.error().message;
  EXPECT_EQ(after->camera.model, before->camera.model);
  EXPECT_EQ(after->lens->kPx, before->lens->kPx);
  EXPECT_EQ(after->geometricQuality.date, before->geometricQuality.date);
  EXPECT_EQ(after->photometricQuality.fitPatches, 6);
  EXPECT_NE(after->photometricQuality.date, before->photometricQuality.date);
  EXPECT_EQ(after->photometric->blackLevelCode, 64.0);
}

TEST_F(VemcalibCli, RefusesFewerThanThreeFitPatchesWithoutTouchingTheOutput) {
  const std::string before = existingOutput();
  std::vector<PatchSpec> few;
  for (const char* name : {"p1", "p4", "c1", "c2"}) few.push_back(patch(name));
  expectRefused(photometric(frames(), patchFile(few)), before, "at least 3");
}

TEST_F(VemcalibCli, RefusesASaturatedPatchWithoutTouchingTheOutput) {
  const std::string before = existingOutput();
  expectRefused(photometric(frameWithPatchAt("p6", 4095), sim("patches.toml")), before,
                "'p6' is saturated");
}

TEST_F(VemcalibCli, RefusesAPatchUnderTheBlackLevelWithoutTouchingTheOutput) {
  const std::string before = existingOutput();
  expectRefused(photometric(frameWithPatchAt("p1", 60), sim("patches.toml")), before,
                "'p1' is under the black level");
}

TEST_F(VemcalibCli, RefusesCodesThatDoNotIncreaseWithLuminance) {
  const std::string before = existingOutput();
  std::vector<PatchSpec> swapped = chart();
  std::swap(swapped[1].luminanceCdM2, swapped[3].luminanceCdM2);  // p2 and p4
  expectRefused(photometric(frames(), patchFile(swapped)), before, "do not increase");
}

TEST_F(VemcalibCli, RefusesAFitResidualAboveMaxResidualWhichIsSettable) {
  const std::string before = existingOutput();
  std::vector<PatchSpec> off = chart();
  off[2].luminanceCdM2 *= 1.02;  // p3 2 % off the curve
  const fs::path patches = patchFile(off);
  const CommandRun refused = photometric(frames(), patches, " --max-residual 0.5");
  expectRefused(refused, before, "--max-residual");
  EXPECT_TRUE(contains(refused.out, "p3 ")) << "the table still shows the fit";
  EXPECT_EQ(photometric(frames(), patches).exitCode, 0) << "2 % passes the default 3 %";
}

TEST_F(VemcalibCli, RefusesACheckErrorAboveMaxCheckErrorWhichIsSettable) {
  const std::string before = existingOutput();
  std::vector<PatchSpec> off = chart();
  off[6].luminanceCdM2 *= 1.04;  // c1 4 % off
  const fs::path patches = patchFile(off);
  expectRefused(photometric(frames(), patches, " --max-check-error 2"), before,
                "--max-check-error");
  EXPECT_EQ(photometric(frames(), patches).exitCode, 0) << "4 % passes the default 5 %";
}

TEST_F(VemcalibCli, RefusesAPatchRegionBeyondTheFrameNamingThePatch) {
  const std::string before = existingOutput();
  std::vector<PatchSpec> outside = chart();
  outside[4].x = 1250;
  expectRefused(photometric(frames(), patchFile(outside)), before, "patch \"p5\": region");
}

TEST_F(VemcalibCli, RefusesFramesThatDoNotFitTheOutputsCamera) {
  const std::string before = existingOutput();
  vem::RawFrame small = vem::RawFrame::blank(64, 48, {3, 12});
  ASSERT_TRUE(io::saveRawFrame(small, dir_ / "small.png"));
  std::vector<PatchSpec> tiny{{"a", 0, 0, 4, 4, 1, false}};
  expectRefused(photometric((dir_ / "small.png").string(), patchFile(tiny)), before,
                "the frames are 64 x 48 RGB12 but the camera in");
}

TEST_F(VemcalibCli, NeverOverwritesAnOutputFileThatDoesNotLoad) {
  std::ofstream(out()) << "format = \"vemcast-camera\"\nversion = 7\n";
  const std::string before = readTextFile(out());
  expectRefused(photometric(frames(), sim("patches.toml")), before, "unknown version 7");
}

TEST_F(VemcalibCli, CorruptFrameAndBadExposureGiveOneSentence) {
  const std::string before = existingOutput();
  const std::string png = readTextFile(sim("patches-1.png"));
  std::ofstream(dir_ / "cut.png", std::ios::binary) << png.substr(0, png.size() / 2);
  expectRefused(photometric((dir_ / "cut.png").string(), sim("patches.toml")), before, "cut.png");
  expectRefused(photometric(sim("patches-1.png").string() + "@-5", sim("patches.toml")), before,
                "positive number of microseconds");
}

TEST_F(VemcalibCli, ShowRefusesABadCameraFileWithTheLoadersSentenceAndExit1) {
  std::string text = readTextFile(kExampleCamera);
  text.replace(text.find("unit = \"px\" }     # k1"), 13, "unit = \"mm\" }");
  std::ofstream(dir_ / "bad.toml") << text;
  const CommandRun r = run("show " + (dir_ / "bad.toml").string());
  EXPECT_EQ(r.exitCode, 1);  // a file that cannot be used is a failure at run time, not usage
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_TRUE(contains(r.err, "bad.toml: geometric.k: expected unit \"px\", found \"mm\""))
      << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(VemcalibCli, ShowPrintsTheExampleCamerasModelFieldOfViewResidualsAndDates) {
  const CommandRun r = run("show " + kExampleCamera.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* part : {"HDRC-Example", "log response", "field of view 190 deg", "rms residual",
                           "rms reprojection", "2026-11-22T00:00:00Z"})
    EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
}

// A smooth sky whose red follows the azimuth and blue the elevation, in cd/m2: a channel swap, a
// mirrored azimuth or an upside-down map all change the answer.
glm::dvec3 testSky(const glm::dvec3& dir) {
  const double phi = std::atan2(dir.z, dir.x);
  return {200.0 * (1.5 + std::sin(phi)), 120.0, 30.0 * (1.2 + dir.y)};
}

TEST_F(VemcalibCli, ApplyTurnsASimulatedFrameBackIntoTheSkyTheCameraSaw) {
  vem::EnvMap sky = vem::EnvMap::filled(vem::MapLayout::Sphere, 256, 128, glm::vec3(0.0F));
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x)
      sky.set(x, y, glm::vec3(testSky(vem::pixelCentreDirection(sky, x, y))));
  ASSERT_TRUE(vem::mapio::saveMap(sky, dir_ / "sky.exr"));
  const std::string camera = kExampleCamera.string();
  const CommandRun simulated =
      run("simulate frame --camera " + camera + " --map " + (dir_ / "sky.exr").string() +
          " --noise 0 --out " + (dir_ / "raw.png").string());
  ASSERT_EQ(simulated.exitCode, 0) << simulated.err;
  const CommandRun applied =
      run("apply --camera " + camera + " --frame " + (dir_ / "raw.png").string() + " --out " +
          (dir_ / "map.exr").string() + " --width 64 --mask-out " + (dir_ / "mask.png").string());
  ASSERT_EQ(applied.exitCode, 0) << applied.err;
  EXPECT_TRUE(contains(applied.out, "next: vemtool lights --in")) << applied.out;
  const auto map = vem::mapio::loadMap(dir_ / "map.exr");
  ASSERT_TRUE(map.has_value()) << map.error().message;
  ASSERT_EQ(map->layout, vem::MapLayout::Hemisphere);
  ASSERT_EQ(map->height, 16);
  const auto mask = io::loadRawFrame(dir_ / "mask.png");
  ASSERT_TRUE(mask.has_value()) << mask.error().message;
  for (int y = 0; y < map->height; ++y) {
    for (int x = 0; x < map->width; ++x) {
      const glm::dvec3 want = testSky(vem::pixelCentreDirection(*map, x, y));
      const glm::vec3 got = map->at(x, y);
      EXPECT_EQ(mask->at(x, y), 255)
          << x << ", " << y << ": the 190-degree lens sees the hemisphere";
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(double(got[c]) / want[c], 1.0, 0.02)
            << "pixel " << x << ", " << y << " channel " << c;
    }
  }
}

// Issue 17: simulate frame's hint applied the truth camera to "map.exr"; the walk-through applies
// the camera fitted in the earlier steps (DIR/camera.toml) to the frame just written.
TEST_F(VemcalibCli, SimulateFrameHintAppliesTheFittedCameraToTheFrameWrittenNotTheTruth) {
  vem::EnvMap sky = vem::EnvMap::filled(vem::MapLayout::Sphere, 32, 16, glm::vec3(50.0F));
  ASSERT_TRUE(vem::mapio::saveMap(sky, dir_ / "sky.exr"));
  fs::create_directories(dir_ / "sim");
  const std::string simulate = "simulate frame --camera " + kExampleCamera.string() + " --map " +
                               (dir_ / "sky.exr").string() + " --noise 0 --out " +
                               (dir_ / "sim" / "raw.png").string();
  const CommandRun before = run(simulate);  // no camera fitted yet
  ASSERT_EQ(before.exitCode, 0) << before.err;
  EXPECT_TRUE(contains(before.out, "next: vemcalib apply --camera CAMERA --frame " +
                                       (dir_ / "sim" / "raw.png").string() + " --out " +
                                       (dir_ / "sim" / "polar.exr").string() +
                                       ", CAMERA being the camera file you fitted (e.g. " +
                                       (dir_ / "sim" / "camera.toml").string()))
      << before.out;
  EXPECT_FALSE(contains(before.out, "--camera " + kExampleCamera.string())) << before.out;
  EXPECT_FALSE(contains(before.out, "map.exr")) << before.out;

  fs::copy_file(kExampleCamera, dir_ / "sim" / "camera.toml");  // as if fitted
  const CommandRun after = run(simulate);
  ASSERT_EQ(after.exitCode, 0) << after.err;
  EXPECT_TRUE(contains(after.out, "next: vemcalib apply --camera " +
                                      (dir_ / "sim" / "camera.toml").string() + " --frame " +
                                      (dir_ / "sim" / "raw.png").string() + " --out " +
                                      (dir_ / "sim" / "polar.exr").string() + "\n"))
      << after.out;
}

TEST_F(VemcalibCli, ApplyRefusesACameraWithoutLensAndAFrameOfAnotherSize) {
  CameraCalibration noLens = *io::loadCameraFile(kExampleCamera);
  noLens.lens.reset();
  ASSERT_TRUE(io::saveCameraFile(noLens, dir_ / "nolens.toml"));
  const CommandRun a = run("apply --camera " + (dir_ / "nolens.toml").string() + " --frame " +
                           sim("patches-1.png").string() + " --out " + (dir_ / "m.exr").string());
  EXPECT_EQ(a.exitCode, 1);
  EXPECT_EQ(lineCount(a.err), 1) << a.err;
  EXPECT_TRUE(contains(a.err, "nolens.toml: the camera has no geometric section")) << a.err;
  ASSERT_TRUE(io::saveRawFrame(vem::RawFrame::blank(64, 48, {3, 12}), dir_ / "small.png"));
  const CommandRun b = run("apply --camera " + kExampleCamera.string() + " --frame " +
                           (dir_ / "small.png").string() + " --out " + (dir_ / "m.exr").string());
  EXPECT_EQ(b.exitCode, 1);
  EXPECT_EQ(lineCount(b.err), 1) << b.err;
  EXPECT_TRUE(contains(b.err, "small.png: the frames are 64 x 48 RGB12 but the camera")) << b.err;
  EXPECT_FALSE(fs::exists(dir_ / "m.exr"));
}

TEST_F(VemcalibCli, HelpOfTheToolAndOfEveryCommandShowsAnExample) {
  for (const char* command :
       {"", "photometric", "fisheye", "response", "simulate", "apply", "show", "simulate patches",
        "simulate frame", "simulate boards", "simulate brackets", "simulate plate", "plate",
        "plate intrinsics", "plate pose", "plate probe-yaw", "plate colour"}) {
    const CommandRun r = run(std::string(command) + " --help");
    EXPECT_EQ(r.exitCode, 0) << command << ": " << r.err;
    EXPECT_TRUE(contains(r.out, "Example")) << "vemcalib " << command << " --help:\n" << r.out;
  }
}

// Issue 17: one exit convention for every tool (util/cli_conventions.h). vemcalib exited 105/106
// on a bad flag or value and 2 on an input file it could not use.
TEST_F(VemcalibCli, BadFlagAndBadValueExitTwoNotCli11sOwnCodes) {
  for (const std::string args :
       {"show --frobnicate", "fisheye --image x.png --board 9x6 --square many --out c.toml",
        "simulate frame --camera c.toml --map m.exr --noise -1 --out r.png", "frobnicate"}) {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.err.starts_with("vemcalib: error: ")) << r.err;
    EXPECT_TRUE(contains(r.err, " --help')")) << r.err;
  }
}

TEST_F(VemcalibCli, MissingInputFileIsAFailureAtRunTimeExitOneNotTwo) {
  const CommandRun r = run("show " + (dir_ / "nothere.toml").string());
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_TRUE(contains(r.err, "nothere.toml")) << r.err;
}

TEST_F(VemcalibCli, EveryHelpPageExitsZeroAndEndsWithTheExitStatusLine) {
  for (const char* command :
       {"", "photometric", "fisheye", "response", "simulate", "apply", "show", "simulate patches",
        "simulate frame", "simulate boards", "simulate brackets", "simulate plate", "plate",
        "plate intrinsics", "plate pose", "plate probe-yaw", "plate colour"}) {
    const CommandRun r = run(std::string(command) + " --help");
    EXPECT_EQ(r.exitCode, 0) << command << ": " << r.err;
    const std::string page = r.out.substr(0, r.out.find_last_not_of('\n') + 1);
    EXPECT_TRUE(page.ends_with(
        "\nExit status: 0 success, 1 failure at run time, 2 usage error (bad flag or value)."))
        << "vemcalib " << command << " --help:\n"
        << r.out;
  }
}

// Issue 17: help pages showed the parser's internals ("INT:INT in [1 - 65536]", "TEXT:FILE",
// "FLOAT:POSITIVE", enum maps "{a->0} OR {0}", "{false}").
TEST_F(VemcalibCli, NoHelpPageShowsTheParsersInternals) {
  const std::regex typeAndValidator{R"(\b(TEXT|INT|UINT|FLOAT|BOOLEAN):)"};
  for (const char* command :
       {"", "photometric", "fisheye", "response", "simulate", "apply", "show", "simulate patches",
        "simulate frame", "simulate boards", "simulate brackets", "simulate plate", "plate",
        "plate intrinsics", "plate pose", "plate probe-yaw", "plate colour"}) {
    const CommandRun r = run(std::string(command) + " --help");
    ASSERT_EQ(r.exitCode, 0) << command << ": " << r.err;
    for (const char* internal : {"->", "ENUM", "{false}", " OR {", " in [", "POSITIVE"})
      EXPECT_EQ(r.out.find(internal), std::string::npos)
          << "vemcalib " << command << " --help shows " << internal << ":\n"
          << r.out;
    EXPECT_FALSE(std::regex_search(r.out, typeAndValidator)) << "vemcalib " << command << ":\n"
                                                             << r.out;
  }
}

// Issue 17: `vemcalib show --compare TRUTH.toml`, each fitted value beside the truth and how far
// apart they are in pixels, degrees and per cent of luminance.
class VemcalibCompare : public VemcalibCli {
 protected:
  // The number before `unit` on the table line that starts with `name` (NaN when none).
  static double differenceOn(const std::string& out, const std::string& name,
                             const std::string& unit) {
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
      const std::size_t at = line.find("  " + name);
      if (at != 0) continue;
      const std::size_t end = line.rfind(unit);
      const std::size_t begin = line.rfind(' ', end - 1);
      return std::stod(line.substr(begin + 1, end - begin - 1));
    }
    return std::nan("");
  }
  CommandRun compare(const CameraCalibration& fitted) const {
    EXPECT_TRUE(io::saveCameraFile(fitted, dir_ / "fitted.toml"));
    return run("show " + (dir_ / "fitted.toml").string() + " --compare " + kExampleCamera.string());
  }
};

TEST_F(VemcalibCompare, AFileComparedWithItselfDiffersByNothing) {
  const CommandRun r =
      run("show " + kExampleCamera.string() + " --compare " + kExampleCamera.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(differenceOn(r.out, "luminance, max", " %"), 0.0) << r.out;
  EXPECT_EQ(differenceOn(r.out, "luminance, rms", " %"), 0.0) << r.out;
  EXPECT_EQ(differenceOn(r.out, "projection, max", " px"), 0.0) << r.out;
  EXPECT_EQ(differenceOn(r.out, "direction, max", " deg"), 0.0) << r.out;
  EXPECT_EQ(differenceOn(r.out, "principal point x", " px"), 0.0) << r.out;
}

TEST_F(VemcalibCompare, APrincipalPointShiftedBy2PxShows2PxAndAboutAThirdOfADegree) {
  CameraCalibration fitted = *io::loadCameraFile(kExampleCamera);
  fitted.lens->principalPointPx.x += 2.0;
  const CommandRun r = compare(fitted);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NEAR(differenceOn(r.out, "principal point x", " px"), 2.0, 1e-9) << r.out;
  EXPECT_NEAR(differenceOn(r.out, "projection, max", " px"), 2.0, 1e-3) << r.out;
  EXPECT_NEAR(differenceOn(r.out, "projection, rms", " px"), 2.0, 1e-3) << r.out;
  // 2 px over r'(0) = k1 = 310 px per radian near the axis: 0.37 deg; more where r' is smaller.
  EXPECT_GT(differenceOn(r.out, "direction, max", " deg"), 0.3) << r.out;
  EXPECT_LT(differenceOn(r.out, "direction, max", " deg"), 1.0) << r.out;
  EXPECT_EQ(differenceOn(r.out, "luminance, max", " %"), 0.0) << r.out;
}

TEST_F(VemcalibCompare, AResponseReading10PercentMoreLuminanceShows10Percent) {
  CameraCalibration fitted = *io::loadCameraFile(kExampleCamera);
  auto& log = std::get<LogResponse>(fitted.photometric->response);
  for (int c = 0; c < 3; ++c) log.aCode[c] -= log.bCodePerLn[c] * std::log(1.1);  // L' = 1.1 L
  const CommandRun r = compare(fitted);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NEAR(differenceOn(r.out, "luminance, max", " %"), 10.0, 0.01) << r.out;
  EXPECT_NEAR(differenceOn(r.out, "luminance, rms", " %"), 10.0, 0.01) << r.out;
  EXPECT_EQ(differenceOn(r.out, "projection, max", " px"), 0.0) << r.out;
}

TEST_F(VemcalibCompare, AMissingOrBrokenTruthFileIsOneSentenceNamingItAndExit1) {
  std::ofstream(dir_ / "broken.toml") << "this is [not a camera file\n";
  for (const std::string truth : {"nothere.toml", "broken.toml"}) {
    const CommandRun r =
        run("show " + kExampleCamera.string() + " --compare " + (dir_ / truth).string());
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_TRUE(r.err.starts_with("vemcalib: error: --compare: ")) << r.err;
    EXPECT_TRUE(contains(r.err, truth)) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

// Issue 21: the plate camera's calibration as a user meets it: the simulated walk-through of
// docs/calibration.md ("Plate camera") gives the truth back, each step merges its own section, and
// a refused step leaves the plate-camera file byte for byte as it was.
class VemcalibPlate : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("vemcalib_cli_plate_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    simulate_ = runIn(dir_, "simulate plate --camera " + kExamplePlate.string() +
                                " --board 9x6 --square 60 --floor-square 100 --views 10 --out " +
                                (dir_ / "sim").string());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  void SetUp() override { ASSERT_EQ(simulate_.exitCode, 0) << simulate_.err; }

  [[nodiscard]] static CommandRun run(const std::string& args) { return runIn(dir_, args); }
  // A file in the simulation's folder, as an absolute path (commands run in the test's folder).
  [[nodiscard]] static std::string sim(const std::string& name) {
    return (dir_ / "sim" / name).string();
  }
  // The command simulate plate printed after "next: vemcalib " whose arguments start with `start`.
  [[nodiscard]] static std::string next(const std::string& start) {
    std::istringstream lines(simulate_.out);
    for (std::string line; std::getline(lines, line);)
      if (line.starts_with("next: vemcalib " + start)) return line.substr(15);
    ADD_FAILURE() << "no next: vemcalib " << start << " in\n" << simulate_.out;
    return "";
  }
  // The whole calibration into sim/NAME, every step succeeding.
  static void calibrate(const std::string& name) {
    for (const char* step : {"plate intrinsics", "plate pose", "plate probe-yaw", "plate colour"}) {
      std::string args = next(step);
      args.replace(args.find(sim("plate.toml")), sim("plate.toml").size(), sim(name));
      const CommandRun r = run(args);
      ASSERT_EQ(r.exitCode, 0) << args << ": " << r.err;
      EXPECT_TRUE(contains(r.out, "wrote " + sim(name))) << r.out;
    }
  }

  static inline const fs::path kExamplePlate =
      fs::path(VEM_SOURCE_DIR) / "config/plate-camera-example.toml";
  static inline fs::path dir_;
  static inline CommandRun simulate_;
};

TEST_F(VemcalibPlate, TheSimulatedWalkThroughGivesTheTruthBack) {
  calibrate("plate.toml");
  const auto fitted = io::loadPlateCameraFile(sim("plate.toml"));
  ASSERT_TRUE(fitted.has_value()) << fitted.error().message;
  const auto truth = io::loadPlateCameraFile(kExamplePlate);
  ASSERT_TRUE(truth.has_value());
  EXPECT_LT(fitted->intrinsicsQuality.rmsReprojectionPx, 0.5);
  EXPECT_NEAR(fitted->intrinsics.fxPx, truth->intrinsics.fxPx, 0.005 * truth->intrinsics.fxPx);
  EXPECT_NEAR(fitted->intrinsics.cxPx, truth->intrinsics.cxPx, 3.0);
  ASSERT_TRUE(fitted->pose.has_value());
  EXPECT_LT(glm::length(fitted->pose->positionWorldM - truth->pose->positionWorldM), 0.01);
  EXPECT_NEAR(fitted->probeYawRad, truth->probeYawRad, 0.3 * std::numbers::pi / 180.0);
  ASSERT_TRUE(fitted->colour.has_value());
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(fitted->colour->gainRgb[c], truth->colour->gainRgb[c],
                0.005 * truth->colour->gainRgb[c]);
  const CommandRun shown = run("show " + sim("plate.toml") + " --compare " + kExamplePlate.string());
  EXPECT_EQ(shown.exitCode, 0) << shown.err;
  EXPECT_TRUE(contains(shown.out, "world points, rms")) << shown.out;
}

TEST_F(VemcalibPlate, ARefusedStepLeavesThePlateFileByteForByte) {
  calibrate("kept.toml");
  const std::string before = readTextFile(sim("kept.toml"));
  std::string intrinsics = next("plate intrinsics");
  intrinsics.replace(intrinsics.find(sim("plate.toml")), sim("plate.toml").size(), sim("kept.toml"));
  // An RMS limit no fit meets.
  CommandRun r = run(intrinsics + " --max-rms 0.001");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "above the limit of 0.001 px")) << r.err;
  EXPECT_TRUE(contains(r.err, "(nothing was written)")) << r.err;
  EXPECT_EQ(lineCount(r.err.substr(r.err.find("vemcalib: error:"))), 1) << r.err;
  // A floor board's RMS limit no pose meets.
  r = run("plate pose --image " + sim("plate-floor.png") +
          " --board 9x6 --square 100 --max-rms 0.001 --out " + sim("kept.toml"));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "plate-floor.png: the floor board's RMS reprojection error is"))
      << r.err;
  // A saturated colour patch.
  auto patches = io::loadColourPatchFile(sim("plate-colour.toml"));
  ASSERT_TRUE(patches.has_value());
  patches->back().plateLinear[1] = 1.0;
  ASSERT_TRUE(io::saveColourPatchFile(*patches, sim("saturated.toml")).has_value());
  r = run("plate colour --patches " + sim("saturated.toml") + " --out " + sim("kept.toml"));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "patch 'g6' is saturated in G")) << r.err;
  // A marker whose elevations disagree: another marker.
  r = run("plate probe-yaw --pixel 1024,86.4 --probe-direction 10,40 --out " + sim("kept.toml"));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "--max-elevation-difference")) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_EQ(readTextFile(sim("kept.toml")), before);
}

TEST_F(VemcalibPlate, StepsThatNeedAnEarlierOneSayWhichToRunFirst) {
  const CommandRun r = run("plate pose --image " + sim("plate-floor.png") +
                           " --board 9x6 --square 100 --out " + sim("none.toml"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(contains(r.err, "none.toml: no such file (the pose needs the plate camera's "
                              "intrinsics: run vemcalib plate intrinsics first)"))
      << r.err;
  EXPECT_FALSE(fs::exists(sim("none.toml")));
}

TEST_F(VemcalibPlate, ALightProbeCameraFileGivenAsThePlateFileIsNamedAsSuch) {
  const fs::path copy = dir_ / "probe-camera.toml";
  fs::copy_file(kExampleCamera, copy, fs::copy_options::overwrite_existing);
  const std::string before = readTextFile(copy);
  const CommandRun r =
      run("plate colour --patches " + sim("plate-colour.toml") + " --out " + copy.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(contains(r.err, "(a light-probe camera file, not a plate camera file)")) << r.err;
  EXPECT_EQ(readTextFile(copy), before);
}

TEST_F(VemcalibPlate, ShowPrintsAPlateCameraFile) {
  const CommandRun r = run("show " + kExamplePlate.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "vemcast plate camera file")) << r.out;
  EXPECT_TRUE(contains(r.out, "probe yaw:    35 deg")) << r.out;
}

}  // namespace
