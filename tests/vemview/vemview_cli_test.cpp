// vemview as a user meets it (the built executable, headless through EGL): the plan it prints for
// each kind of scene, the frames, EXRs and timing log it writes, the work it skips when nothing
// changed, and one error line for each kind of bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/render/image_files.h"
#include "vemview/vemview_process.h"

namespace {

namespace fs = std::filesystem;

using vem::testing::CommandRun;

std::vector<nlohmann::json> jsonLines(const fs::path& path) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(nlohmann::json::parse(line));
  }
  return lines;
}

// sum |a - b| / sum |b| over every value of two images of one size (0 when b is black).
double relativeDifference(const vem::render::LinearImage& a, const vem::render::LinearImage& b) {
  double differenceSum = 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < b.rgb.size(); ++i) {
    differenceSum += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
    sum += std::abs(double(b.rgb[i]));
  }
  return sum > 0.0 ? differenceSum / sum : 0.0;
}

const std::string kSmall = " --headless --width 64 --height 48 --count 16 --shadowed 8 ";

class VemviewCli : public vem::testing::VemviewProcessTest {
 protected:
  CommandRun run(const std::string& args) const { return VemviewProcessTest::run("", args); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }
  // Exit `status` (util/cli_conventions.h: 1 a failure at run time, such as a bad file; 2 a usage
  // error) with one line that names `part`.
  void expectRefused(const std::string& args, const std::string& part, int status = 1) const {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, status) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.err.starts_with("vemview: error: ")) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  }
  // Two frames of the default scene by ratio on `renderer`: the plan line says what is
  // prefiltered and that the L/H pass is gone; the unchanged cube map is prefiltered once.
  void expectRatioShadingPrefiltersOnce(const std::string& renderer) const {
    const CommandRun r = run(kSmall + "--scene default --renderer " + renderer +
                             " --shading ratio --frames 2 --orbit 5 --out " + path("out"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("shading by ratio (irradiance cube: a diffuse material, clipped "
                         "environment for the glossy lobes: "
                         "a glossy material)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("glossy L/H pass"), std::string::npos) << r.err;
    // The cube map does not change between the two frames: it is prefiltered for the first only.
    const std::vector<nlohmann::json> lines = jsonLines(fs::path(path("out")) / "timing.jsonl");
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_TRUE(lines[0].contains("prefilter_ms"));
    EXPECT_FALSE(lines[1].contains("prefilter_ms"));
  }
};

TEST_F(VemviewCli, HeadlessRunWritesPngExrAndOneTimingLinePerFrame) {
  const CommandRun r = run(kSmall + "--scene spheres --frames 2 --orbit 10 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name :
       {"frame-000000.png", "frame-000000.exr", "frame-000001.png", "frame-000001.exr"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / name)) << name;
  }
  const auto png = vem::render::loadSrgb8(dir_ / "out" / "frame-000000.png");
  ASSERT_TRUE(png.has_value()) << png.error();
  EXPECT_EQ(png->widthPx, 64);
  EXPECT_EQ(png->heightPx, 48);
  const auto exr = vem::render::loadLinearExr(dir_ / "out" / "frame-000000.exr");
  ASSERT_TRUE(exr.has_value()) << exr.error();
  EXPECT_GT(*std::ranges::max_element(exr->rgb), 0.0F);
  EXPECT_EQ(jsonLines(dir_ / "out" / "timing.jsonl").size(), 2U);
}

TEST_F(VemviewCli, StaticLightsAndCameraAreDrawnOnceAndNotRedrawn) {
  const CommandRun r = run(kSmall + "--scene spheres --frames 3 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_TRUE(lines[0]["drawn"].get<bool>());
  EXPECT_FALSE(lines[1]["drawn"].get<bool>());
  EXPECT_FALSE(lines[2]["drawn"].get<bool>());
  EXPECT_FALSE(fs::exists(dir_ / "out" / "frame-000001.png"));
  EXPECT_NE(r.err.find("2 not redrawn"), std::string::npos) << r.err;
}

TEST_F(VemviewCli, OrbitingCameraRedrawsButReusesTheShadowMaps) {
  const CommandRun r = run(kSmall + "--cluster 0 --scene spheres --frames 3 --orbit 15 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0]["shadow_maps_rendered"].get<int>(), 8);
  for (int i = 1; i < 3; ++i) {
    EXPECT_TRUE(lines[i]["drawn"].get<bool>());
    EXPECT_EQ(lines[i]["shadow_maps_rendered"].get<int>(), 0);
    EXPECT_EQ(lines[i]["shadow_maps_reused"].get<int>(), 8);
  }
}

TEST_F(VemviewCli, LambertianSceneSkipsTheGlossyPassAndTheCubeMap) {
  const CommandRun r = run(kSmall + "--scene diffuse --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("no glossy pass (no glossy material)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no cube map"), std::string::npos) << r.err;
}

TEST_F(VemviewCli, GlossySceneGetsTheLHPassAndTheCubeMap) {
  const CommandRun r = run(kSmall + "--scene default --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("glossy L/H pass"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cube map of 128 px ("), std::string::npos) << r.err;
}

// --cube-face-px reached the plan line but not the map input (which built 128 px cube maps
// whatever was asked): the background, level 0 of the cube map, is the same at 8 px and at 256.
TEST_F(VemviewCli, CubeFaceSizeReachesTheCubeMapNotOnlyThePlanLine) {
  std::vector<vem::render::LinearImage> images;
  for (const int facePx : {8, 256}) {
    const std::string out = path("out" + std::to_string(facePx));
    const CommandRun r = run(kSmall + "--scene default --background --no-png --cube-face-px " +
                             std::to_string(facePx) + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("cube map of " + std::to_string(facePx) + " px ("), std::string::npos)
        << r.err;
    auto exr = vem::render::loadLinearExr(fs::path(out) / "frame-000000.exr");
    ASSERT_TRUE(exr.has_value()) << exr.error();
    images.push_back(std::move(*exr));
  }
  EXPECT_GT(relativeDifference(images[0], images[1]), 0.01);  // an 8 px sky blurs the 256 px one
  expectRefused(kSmall + "--cube-face-px 1024", "--cube-face-px", 2);
}

TEST_F(VemviewCli, RatioShadingPrefiltersOnceAndSaysSoInThePlan) {
  for (const std::string renderer : {"gl", "embree"}) {
    SCOPED_TRACE(renderer);
    fs::remove_all(dir_ / "out");
    expectRatioShadingPrefiltersOnce(renderer);
  }
}

// --soft-shadows reaches both renderers, not only the plan line: each image differs from the hard
// shadows' one. OpenGL draws the maps beyond N along the strata (16 lights, up to 64 maps), says
// so in its status and timing, and keeps them while only the camera moves.
TEST_F(VemviewCli, SoftShadowsReachBothRenderersAndOpenGlKeepsItsStrataMapsWhileTheCameraMoves) {
  for (const std::string renderer : {"gl", "embree"}) {
    SCOPED_TRACE(renderer);
    std::vector<vem::render::LinearImage> images;
    for (const std::string soft : {"", " --soft-shadows"}) {
      const std::string out = path(renderer + (soft.empty() ? "-hard" : "-soft"));
      const CommandRun r = run(" --headless --width 64 --height 48 --scene spheres --count 16 "
                               "--shadowed 64 --renderer " +
                               renderer + " --shading ratio --frames 2 --orbit 5 --no-png" +
                               soft + " --out " + out);
      ASSERT_EQ(r.exitCode, 0) << r.err;
      auto exr = vem::render::loadLinearExr(fs::path(out) / "frame-000000.exr");
      ASSERT_TRUE(exr.has_value()) << exr.error();
      images.push_back(std::move(*exr));
      if (soft.empty()) continue;
      EXPECT_NE(r.err.find(", soft shadows (each light's stratum of the sky; OpenGL: up to 64 maps"),
                std::string::npos)
          << r.err;
      if (renderer != "gl") continue;
      EXPECT_NE(r.err.find("maps along strata draws)"), std::string::npos) << r.err;
      const std::vector<nlohmann::json> lines = jsonLines(fs::path(out) / "timing.jsonl");
      ASSERT_EQ(lines.size(), 2U);
      ASSERT_TRUE(lines[0].contains("strata_shadow_maps"));
      const int strataMaps = lines[0]["strata_shadow_maps"].get<int>();
      EXPECT_GT(strataMaps, 16);
      EXPECT_LE(lines[0]["shadow_maps_rendered"].get<int>(), 64);
      EXPECT_GE(lines[0]["shadow_maps_rendered"].get<int>(), strataMaps);
      EXPECT_TRUE(lines[0].contains("soft_shadow_strata_ms"));
      EXPECT_FALSE(lines[1].contains("soft_shadow_strata_ms"));  // the same lights: not redrawn
      EXPECT_EQ(lines[1]["shadow_maps_reused"].get<int>(),
                lines[0]["shadow_maps_rendered"].get<int>());
    }
    EXPECT_GT(relativeDifference(images[1], images[0]), 0.002);
  }
  expectRefused(kSmall + "--soft-shadows --out " + path("out"), "--shading ratio", 2);
}

TEST_F(VemviewCli, RatioShadingOnTheReferenceRendererIsAUsageError) {
  expectRefused(kSmall + "--renderer reference --shading ratio --out " + path("out"),
                "not reference", 2);
}

TEST_F(VemviewCli, LoneConvexObjectRendersWithoutShadowMaps) {
  const CommandRun r = run(kSmall + "--scene sphere --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("no shadow maps (nothing can shadow anything)"), std::string::npos) << r.err;
  const auto lines = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_EQ(lines[0]["shadow_maps_rendered"].get<int>(), 0);
}

// Maps of 4096 px: the atlas (at most GL_MAX_TEXTURE_SIZE square) holds fewer than the 32 asked
// for, and vemview warned so, then reported 32 shadowed lights in its plan, status and timing log.
// The status names the maps drawn of the maps planned: "shadow maps 16 of 16".
TEST_F(VemviewCli, ShadowedCountIsWhatTheAtlasHoldsNotWhatWasAskedFor) {
  const CommandRun r =
      run(" --headless --width 64 --height 48 --count 32 --shadowed 32 --cluster 0 "
          "--shadow-map-px 4096 --scene spheres --no-png --no-exr --out " +
          path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string warning = "shadow atlas holds ";
  const auto at = r.err.find(warning);
  if (at == std::string::npos) {
    GTEST_SKIP() << "this OpenGL fits 32 maps of 4096 px, so no atlas is too small:\n" << r.err;
  }
  const std::size_t held = std::stoul(r.err.substr(at + warning.size()));
  ASSERT_LT(held, 32U);
  const std::string n = std::to_string(held);
  const std::string plan =
      "plan: lights 32, shadow maps " + n + " at 4096 px (32 asked for; the atlas holds " + n + ")";
  EXPECT_NE(r.err.find(plan), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lights 32 | shadow maps " + n + " of " + n), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("shadow maps 32"), std::string::npos) << r.err;
  const auto timing = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(timing.size(), 1U);
  EXPECT_EQ(timing[0]["shadowed"], held);
  EXPECT_EQ(timing[0]["shadow_maps_rendered"], held);
}

TEST_F(VemviewCli, LightFileFromVemtoolIsRendered) {
  write(
      "lights.jsonl",
      R"({"frame":0,"count":2,"lights":[{"id":0,"dir":[0,1,0],"rgb":[3,3,3]},{"id":1,"dir":[0.6,0.8,0],"rgb":[1,1,1]}]})"
      "\n");
  const CommandRun r =
      run(kSmall + "--scene spheres --lights " + path("lights.jsonl") + " --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("light file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "frame-000000.png"));
}

TEST_F(VemviewCli, ClusteringCutsTheLightsAndShadowsEachCluster) {
  const CommandRun r =
      run(" --headless --width 64 --height 48 --count 256 --shadowed 64 --cluster 8 "
          "--scene spheres --out " +
          path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(lines.size(), 1U);
  const int lights = lines[0]["lights"].get<int>();
  EXPECT_GE(lights, 4);
  EXPECT_LE(lights, 24);
  EXPECT_EQ(lines[0]["shadowed"].get<int>(), lights);  // fewer clusters than maps: all shadowed
  EXPECT_NE(r.err.find("clustering Q 8"), std::string::npos) << r.err;
}

TEST_F(VemviewCli, AdaptiveCountHalvesTowardAnUnreachableTargetDownToItsFloor) {
  const CommandRun r =
      run(" --headless --width 64 --height 48 --count 256 --shadowed 8 --cluster 0 "
          "--target-ms 0.001 --orbit 1 --frames 8 --scene spheres --no-png --no-exr "
          "--out " +
          path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = jsonLines(dir_ / "out" / "timing.jsonl");
  ASSERT_EQ(lines.size(), 8U);
  EXPECT_EQ(lines[0]["lights"].get<int>(), 256);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i]["lights"].get<int>(), std::max(4, 256 >> i)) << "frame " << i;
  }
}

TEST_F(VemviewCli, BlackLightFrameRendersBlackWithoutNaN) {
  write("black.jsonl",
        R"({"lights":[{"id":0,"dir":[0,1,0],"rgb":[0,0,0]},{"id":1,"dir":[1,0,0],"rgb":[0,0,0]}]})"
        "\n");
  const CommandRun r =
      run(kSmall + "--scene spheres --lights " + path("black.jsonl") + " --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto exr = vem::render::loadLinearExr(dir_ / "out" / "frame-000000.exr");
  ASSERT_TRUE(exr.has_value()) << exr.error();
  for (float v : exr->rgb) {
    ASSERT_EQ(v, 0.0F);
  }
  const auto png = vem::render::loadSrgb8(dir_ / "out" / "frame-000000.png");
  ASSERT_TRUE(png.has_value()) << png.error();
  EXPECT_EQ(*std::ranges::max_element(png->rgb), 0);
}

TEST_F(VemviewCli, SunAtTenToTheFiveTimesTheSkyRendersFiniteNonNegativeRadiance) {
  std::string lights = R"({"lights":[{"id":0,"dir":[0.6,0.8,0],"rgb":[1e5,1e5,1e5]})";
  for (int i = 1; i < 16; ++i) {
    const double a = 0.4 * i;
    lights += ",{\"id\":" + std::to_string(i) + ",\"dir\":[" + std::to_string(0.6 * std::cos(a)) +
              "," + std::to_string(0.8) + "," + std::to_string(0.6 * std::sin(a)) +
              "],\"rgb\":[1,1,1]}";
  }
  write("sun.jsonl", lights + "]}\n");
  const CommandRun r =
      run(kSmall + "--scene spheres --lights " + path("sun.jsonl") + " --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto exr = vem::render::loadLinearExr(dir_ / "out" / "frame-000000.exr");
  ASSERT_TRUE(exr.has_value()) << exr.error();
  for (float v : exr->rgb) {
    ASSERT_TRUE(std::isfinite(v) && v >= 0.0F);
  }
  EXPECT_GT(*std::ranges::max_element(exr->rgb), 1e3F);  // the sunlit side
}

TEST_F(VemviewCli, MissingSceneFileIsOneSentenceNamingIt) {
  expectRefused(kSmall + "--scene " + path("nothere.obj"), "nothere.obj");
}

TEST_F(VemviewCli, TruncatedObjIsRefusedNamingTheFile) {
  write("cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2");
  expectRefused(kSmall + "--scene " + path("cut.obj"), "cut.obj");
}

TEST_F(VemviewCli, FaceIndexOutOfRangeIsRefusedNamingTheFile) {
  write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expectRefused(kSmall + "--scene " + path("range.obj"), "range.obj");
}

TEST_F(VemviewCli, NanVertexIsRefusedNamingTheFile) {
  write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
  expectRefused(kSmall + "--scene " + path("nan.obj"), "nan.obj");
}

TEST_F(VemviewCli, SceneMtllibOutsideItsFolderIsRefusedUnlessAllowed) {
  write("outside.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
  fs::create_directories(dir_ / "scene");
  write("scene/tri.obj", "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  const std::string args = kSmall + "--scene " + path("scene/tri.obj");
  expectRefused(args, "tri.obj: mtllib '../outside.mtl' lies outside the scene's folder");
  expectRefused(args, "(pass --scene-allow-outside to allow it).");
  const CommandRun allowed = run(args + " --scene-allow-outside --no-png --no-exr");
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
}

TEST_F(VemviewCli, FaceIndexPastTwoToTheThirtyTwoIsRefusedWithItsLine) {
  write("wrap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n");
  expectRefused(kSmall + "--scene " + path("wrap.obj"),
                "wrap.obj: line 4: face corner '4294967297' refers to vertex 4294967297");
}

// Triangulating it took 65 s; it is refused before tinyobjloader reads it.
TEST_F(VemviewCli, PolygonOfAHundredThousandVerticesIsRefusedWithItsLine) {
  constexpr int kCorners = 100000;
  std::ostringstream obj;
  for (int i = 0; i < kCorners; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / kCorners;
    obj << "v " << std::cos(angle) << ' ' << std::sin(angle) << " 0\n";
  }
  obj << 'f';
  for (int i = 1; i <= kCorners; ++i) {
    obj << ' ' << i;
  }
  obj << '\n';
  write("big.obj", obj.str());
  expectRefused(kSmall + "--scene " + path("big.obj"),
                "big.obj: line 100001: face has 100000 vertices and cannot be triangulated, where "
                "3 to 256 were expected");
}

TEST_F(VemviewCli, UnknownSceneFormatIsRefused) {
  write("scene.ply", "ply\n");
  expectRefused(kSmall + "--scene " + path("scene.ply"), "scene.ply");
}

TEST_F(VemviewCli, ReferenceRendererWithoutAMapIsRefused) {
  write("lights.jsonl", R"({"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1]}]})"
                        "\n");
  expectRefused(kSmall + "--renderer reference --lights " + path("lights.jsonl"), "--map", 2);
}

// --help showed CLI11's internals: "ENUM:value in {embree->1,gl->0,reference->2} OR {1,0,2}",
// "--no-png{false}", "INT:INT in [16 - 8192]".
TEST_F(VemviewCli, HelpShowsNoParserInternalsButTheExitStatusesAndTheExamples) {
  const CommandRun r = run("--help");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* internal : {"->", "ENUM", "{false}", " OR {", "INT:", "FLOAT:", "TEXT"}) {
    EXPECT_EQ(r.out.find(internal), std::string::npos) << internal << " in\n" << r.out;
  }
  EXPECT_NE(r.out.find("--renderer gl|embree|reference (default: gl)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--regions on|off (default: on)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--width 16..8192 (default: 640)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  --no-png "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Exit status: 0 success, 1 failure at run time, 2 usage error"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("Examples:\n  vemview --map"), std::string::npos) << r.out;
}

TEST_F(VemviewCli, BadFlagOrValueIsAUsageErrorExitTwo) {
  expectRefused("--no-such-flag", "--no-such-flag", 2);
  expectRefused("--renderer vulkan", "'vulkan' is not one of gl|embree|reference", 2);
  expectRefused("--width 5", "--width", 2);
  expectRefused("--target-ms -1", "'-1' is not a number greater than 0", 2);
}

TEST_F(VemviewCli, MissingSceneFileIsARuntimeFailureExitOne) {
  expectRefused(kSmall + "--scene " + path("nothere.obj"), "nothere.obj", 1);
}

TEST_F(VemviewCli, BadLightFileIsOneSentenceWithTheLine) {
  write("bad.jsonl", "{\"lights\": 3}\n");
  expectRefused(kSmall + "--lights " + path("bad.jsonl"), "bad.jsonl: line 1");
}

TEST_F(VemviewCli, OutPathThatIsAFileIsRefused) {
  write("file", "x");
  expectRefused(kSmall + "--scene spheres --out " + path("file"), "--out");
}

}  // namespace
