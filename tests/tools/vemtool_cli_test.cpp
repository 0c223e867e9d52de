// vemtool as a user meets it: the JSON it prints, and one clear error line for each kind of bad
// input.
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/env_map.h"
#include "mapio/map_file.h"
#include "support/command_run.h"

namespace {

namespace fs = std::filesystem;
using vem::testing::CommandRun;

class VemtoolCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vemtool_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CommandRun run(const std::string& args) const {
    return vem::testing::runCommand(vem::testing::commandLine(VEMTOOL_PATH, args), dir_);
  }
  fs::path dir_;
};

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

TEST_F(VemtoolCli, LightsPrintsOneJsonFrameWithNUnitLightsInIdOrder) {
  vem::EnvMap map = vem::EnvMap::filled(vem::MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  ASSERT_TRUE(vem::mapio::saveMap(map, dir_ / "grey.pfm"));
  const CommandRun r = run("lights --in " + (dir_ / "grey.pfm").string() + " --count 16");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(lineCount(r.out), 1);
  const auto frame = nlohmann::json::parse(r.out);
  EXPECT_EQ(frame["frame"], 0);
  EXPECT_EQ(frame["count"], 16);
  ASSERT_EQ(frame["lights"].size(), 16U);
  double sumRed = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    const auto& light = frame["lights"][i];
    EXPECT_EQ(light["id"], i);
    const double x = light["dir"][0], y = light["dir"][1], z = light["dir"][2];
    EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-6);
    sumRed += double(light["rgb"][0]);
  }
  EXPECT_NEAR(sumRed, 4 * std::numbers::pi, 1e-4);  // a constant map of 1 over the sphere
  EXPECT_EQ(r.out.find("\"frame\""), 1U) << "keys in the documented order";
}

TEST_F(VemtoolCli, MissingFileGivesOneErrorLineAndFails) {
  const CommandRun r = run("lights --in " + (dir_ / "nothere.exr").string() + " --count 4");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nothere.exr"), std::string::npos);
  EXPECT_EQ(r.out, "");
}

TEST_F(VemtoolCli, UnreadableOrTruncatedFilesGiveOneErrorLineAndFail) {
  std::ofstream(dir_ / "garbage.exr") << "this is not an OpenEXR file";
  std::ofstream(dir_ / "truncated.pfm") << "PF\n2 1\n-1.0\nabc";  // OpenCV prints its own line here
  std::ofstream(dir_ / "truncated.hdr") << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\nab";
  for (const char* name : {"garbage.exr", "truncated.pfm", "truncated.hdr"}) {
    const CommandRun r = run("lights --in " + (dir_ / name).string() + " --count 4");
    EXPECT_NE(r.exitCode, 0) << name;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << name;
  }
}

TEST_F(VemtoolCli, ZeroAbsurdOrMissingCountAndUnknownOptionsAreRefusedInOneLine) {
  vem::EnvMap map = vem::EnvMap::filled(vem::MapLayout::Sphere, 8, 4, glm::vec3(1.0F));
  ASSERT_TRUE(vem::mapio::saveMap(map, dir_ / "small.pfm"));
  const std::string in = " --in " + (dir_ / "small.pfm").string();
  const std::vector<std::string> cases{"lights" + in + " --count 0",
                                       "lights" + in + " --count 70000",
                                       "lights" + in + " --count many",
                                       "lights" + in + " --bogus",
                                       "lights" + in + " --sampler fancy",
                                       "lights --count 4",
                                       "frobnicate"};
  for (const std::string& args : cases) {
    const CommandRun r = run(args);
    EXPECT_NE(r.exitCode, 0) << args;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
}

TEST_F(VemtoolCli, NanInfAndNegativePixelsAreCountedInOneWarning) {
  vem::EnvMap map = vem::EnvMap::filled(vem::MapLayout::Sphere, 8, 4, glm::vec3(1.0F));
  map.set(1, 1, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  map.set(2, 1, glm::vec3(std::numeric_limits<float>::infinity(), 1, 1));
  map.set(3, 2, glm::vec3(1, -2, 1));
  ASSERT_TRUE(vem::mapio::saveMap(map, dir_ / "bad.pfm"));
  const CommandRun r = run("lights --in " + (dir_ / "bad.pfm").string() + " --count 8");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("3 pixels"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["count"], 8);
}

TEST_F(VemtoolCli, ClusterAddsMembersThatCoverEveryLightOnce) {
  vem::EnvMap map = vem::EnvMap::filled(vem::MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  ASSERT_TRUE(vem::mapio::saveMap(map, dir_ / "grey.pfm"));
  const CommandRun r =
      run("lights --in " + (dir_ / "grey.pfm").string() + " --count 64 --cluster 8");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto frame = nlohmann::json::parse(r.out);
  EXPECT_EQ(frame["clustered_from"], 64);
  std::vector<int> seen(64, 0);
  for (const auto& cluster : frame["lights"])
    for (const auto& id : cluster["members"]) ++seen[std::size_t(id.get<int>())];
  for (int count : seen) EXPECT_EQ(count, 1);
  EXPECT_LT(frame["count"].get<int>(), 64);
}

// Issue 17: one exit convention for every tool (util/cli_conventions.h): vemtool exited 105 on
// an unknown flag and 106 on a bad value, CLI11's own codes.
TEST_F(VemtoolCli, BadFlagAndBadValueExitTwoNotCli11s105Or106) {
  vem::EnvMap map = vem::EnvMap::filled(vem::MapLayout::Sphere, 8, 4, glm::vec3(1.0F));
  ASSERT_TRUE(vem::mapio::saveMap(map, dir_ / "small.pfm"));
  const std::string in = " --in " + (dir_ / "small.pfm").string();
  for (const std::string& args : std::vector<std::string>{
           "lights" + in + " --count 4 --bogus", "lights" + in + " --count many",
           "lights" + in + " --count 4 --sampler fancy", "info x.vem --format yaml",
           "synth --scene sky --frames 0 --out x.vem", "frobnicate"}) {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.err.starts_with("vemtool: error: ")) << r.err;
  }
}

TEST_F(VemtoolCli, MissingInputFileIsAFailureAtRunTimeExitOne) {
  for (const std::string& args : std::vector<std::string>{
           "info " + (dir_ / "nothere.vem").string(),
           "export " + (dir_ / "nothere.vem").string() + " --frame 0 --out x.exr",
           "recover " + (dir_ / "nothere.vem").string()}) {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, 1) << args << ": " << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("nothere.vem"), std::string::npos) << r.err;
  }
}

TEST_F(VemtoolCli, EveryHelpPageExitsZeroAndEndsWithTheExitStatusLine) {
  for (const char* command :
       {"", "lights", "filters", "info", "recover", "synth", "export", "import", "subscribe",
        "cameras"}) {
    const CommandRun r = run(std::string(command) + " --help");
    EXPECT_EQ(r.exitCode, 0) << command << ": " << r.err;
    const std::string page = r.out.substr(0, r.out.find_last_not_of('\n') + 1);
    EXPECT_TRUE(page.ends_with(
        "\nExit status: 0 success, 1 failure at run time, 2 usage error (bad flag or value)."))
        << "vemtool " << command << " --help:\n"
        << r.out;
  }
}

// Issue 17: help pages showed the parser's internals ("INT:INT in [1 - 65536]", "TEXT:FILE",
// "FLOAT:POSITIVE", enum maps "{a->0} OR {0}", "{false}").
TEST_F(VemtoolCli, NoHelpPageShowsTheParsersInternals) {
  const std::regex typeAndValidator{R"(\b(TEXT|INT|UINT|FLOAT|BOOLEAN):)"};
  for (const char* command :
       {"", "lights", "filters", "info", "recover", "synth", "export", "import", "subscribe",
        "cameras"}) {
    const CommandRun r = run(std::string(command) + " --help");
    ASSERT_EQ(r.exitCode, 0) << command << ": " << r.err;
    for (const char* internal : {"->", "ENUM", "{false}", " OR {", " in [", "POSITIVE"})
      EXPECT_EQ(r.out.find(internal), std::string::npos)
          << "vemtool " << command << " --help shows " << internal << ":\n"
          << r.out;
    EXPECT_FALSE(std::regex_search(r.out, typeAndValidator)) << "vemtool " << command << ":\n"
                                                             << r.out;
  }
}

}  // namespace
