// vemd's configuration: the shipped file documents every key at its default, bad files and flags
// are refused in one sentence, flags override the file; source specs and rates.
#include "vemd/vemd_config.h"

#include <fstream>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "vemd/config_toml.h"
#include "vemd/source_factory.h"
#include "vemd/source_rate.h"
#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

using vemd::parseConfig;
using vemd::VemdConfig;

const fs::path kShippedConfig = fs::path(VEM_SOURCE_DIR) / "config" / "vemd.toml";

std::string refusal(const std::string& text) {
  auto config = parseConfig(text, "vemd.toml");
  EXPECT_FALSE(config) << "accepted:\n" << text;
  return config ? std::string() : config.error();
}

TEST(VemdConfig, ShippedFileLoadsAndEqualsTheBuiltInDefaults) {
  auto config = vemd::loadConfigFile(kShippedConfig);
  ASSERT_TRUE(config) << config.error();
  EXPECT_TRUE(*config == VemdConfig{});
}

// A key the loader knows but the file leaves out would be undocumented.
TEST(VemdConfig, ShippedFileSetsEveryKeyTheLoaderKnows) {
  const toml::table document = toml::parse_file(kShippedConfig.string());
  for (const vemd::ConfigSection& section : vemd::configSchema()) {
    const toml::table* table = section.name.empty() ? &document : document[section.name].as_table();
    ASSERT_NE(table, nullptr) << "[" << section.name << "] is missing";
    for (const std::string& key : section.keys) {
      EXPECT_TRUE(table->contains(key)) << section.name << "." << key << " is not documented";
    }
  }
}

TEST(VemdConfig, EmptyFileGivesTheBuiltInDefaults) {
  auto config = parseConfig("", "empty.toml");
  ASSERT_TRUE(config) << config.error();
  EXPECT_TRUE(*config == VemdConfig{});
}

TEST(VemdConfig, ValuesAreRead) {
  auto config = parseConfig(R"(
[source]
spec = "replay:a.vem"
rate = 29.97
loop = true
frames = 100
[processing]
lights = 256
sampler = "standard"
[filter]
preset = "equiripple5"
[clustering]
enabled = false
budget = 30
[output]
jsonl = "l.jsonl"
preview_every = 10
[stats]
every_s = 2
)",
                            "a.toml");
  ASSERT_TRUE(config) << config.error();
  EXPECT_EQ(config->source.spec, "replay:a.vem");
  EXPECT_EQ(config->source.rate, (vemd::SourceRate{vemd::SourceRate::Mode::Fixed, 29.97}));
  EXPECT_TRUE(config->source.loop);
  EXPECT_EQ(config->source.frames, 100u);
  EXPECT_EQ(config->processing.lightCount, 256u);
  EXPECT_EQ(config->processing.sampler, SamplerKind::Standard);
  EXPECT_EQ(config->processing.filter, FilterPreset::Equiripple5);
  EXPECT_FALSE(config->processing.clustering);
  EXPECT_EQ(config->processing.clusterBudget, 30);
  EXPECT_EQ(config->output.jsonl, "l.jsonl");
  EXPECT_EQ(config->output.previewEvery, 10);
  EXPECT_EQ(config->stats.everyS, 2.0);
}

TEST(VemdConfig, MisspeltKeyIsRefusedNamingItAndTheKnownKeys) {
  EXPECT_EQ(refusal("[processing]\nlight = 64\n"),
            "vemd.toml: processing.light: unknown key (expected one of: map_width, map_height, "
            "lights, sampler)");
}

TEST(VemdConfig, MisspeltSectionIsRefused) {
  EXPECT_EQ(refusal("[proccessing]\nlights = 64\n"),
            "vemd.toml: proccessing: unknown section (expected one of: version, source, camera, "
            "bracketing, "
            "processing, filter, clustering, output, stats, log, stream, mqtt)");
}

TEST(VemdConfig, OutOfRangeValueIsRefusedWithExpectedAndFound) {
  EXPECT_EQ(refusal("[processing]\nlights = 0\n"),
            "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found 0");
  EXPECT_EQ(refusal("[stats]\nevery_s = -1.5\n"),
            "vemd.toml: stats.every_s: expected a number from 0 to 86400, found -1.5");
  EXPECT_EQ(refusal("[source]\nqueue_depth = 5000\n"),
            "vemd.toml: source.queue_depth: expected a whole number from 1 to 64 (every queued "
            "frame holds a whole sensor image), found 5000");
  EXPECT_EQ(refusal("[source]\nretry_initial_ms = 500\nretry_max_ms = 100\n"),
            "vemd.toml: source.retry_max_ms: expected at least source.retry_initial_ms (500), "
            "found 100");
}

// Catches the issue-16 map: 16384 x 16384 took 60 s and 3.2 GB to start, past the unit's
// TimeoutStartSec. The sentence gives the range and why it is there.
TEST(VemdConfig, MapBeyondTheStartUpLimitIsRefusedWithTheRangeAndWhy) {
  EXPECT_EQ(refusal("[processing]\nmap_width = 16384\n"),
            "vemd.toml: processing.map_width: expected a whole number from 4 to 4096 (start-up "
            "time and memory grow with map_width x map_height), found 16384");
  EXPECT_EQ(refusal("[processing]\nmap_height = 4096\n"),
            "vemd.toml: processing.map_height: expected a whole number from 4 to 2048 (start-up "
            "time and memory grow with map_width x map_height), found 4096");
  auto largest = parseConfig("[processing]\nmap_width = 4096\nmap_height = 2048\n", "vemd.toml");
  ASSERT_TRUE(largest) << largest.error();
  EXPECT_EQ(largest->processing.mapWidth, 4096);
}

// Catches a preview image far larger than the map: preview_scale 16 on a 4096-wide map made a
// 65536-pixel-wide image (3 GB) on the processing thread. Checked only while the preview is on,
// so the shipped preview_scale = 2 stands beside the largest map.
TEST(VemdConfig, PreviewBeyondItsSizeLimitForTheMapIsRefused) {
  EXPECT_EQ(refusal("[processing]\nmap_width = 4096\nmap_height = 1024\n"
                    "[output]\npreview_every = 10\npreview_scale = 16\n"),
            "vemd.toml: output.preview_scale: expected a whole number from 1 to 1 while "
            "output.preview_every is on (the preview is the 4096 x 1024 map times preview_scale, "
            "at most 4096 pixels on a side), found 16");
  EXPECT_NE(refusal("[output]\npreview_every = 1\npreview_scale = 5\n"), "");  // 1024 x 5
  auto largest = parseConfig("[output]\npreview_every = 1\npreview_scale = 4\n", "vemd.toml");
  ASSERT_TRUE(largest) << largest.error();
  EXPECT_EQ(largest->output.previewScale, 4);
  auto off =
      parseConfig("[processing]\nmap_width = 4096\n[output]\npreview_scale = 2\n", "vemd.toml");
  ASSERT_TRUE(off) << off.error();
}

TEST(VemdConfig, WrongTypeIsRefused) {
  EXPECT_EQ(refusal("[processing]\nlights = \"many\"\n"),
            "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found the "
            "string \"many\"");
  EXPECT_EQ(refusal("[processing]\nlights = 64.5\n"),
            "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found the "
            "number 64.5");
  EXPECT_EQ(refusal("[source]\nloop = \"yes\"\n"),
            "vemd.toml: source.loop: expected true or false, found the string \"yes\"");
  EXPECT_EQ(refusal("source = 3\n"),
            "vemd.toml: source: expected a table ([source]), found the "
            "integer 3");
}

TEST(VemdConfig, UnknownChoiceIsRefusedListingTheChoices) {
  EXPECT_EQ(refusal("[filter]\npreset = \"paper\"\n"),
            "vemd.toml: filter.preset: expected \"none\", \"paper9\", \"equiripple5\" or "
            "\"minphase9\", found the string \"paper\"");
  EXPECT_EQ(refusal("[source]\nrate = 0\n"),
            "vemd.toml: source.rate: expected \"recorded\", \"max\" or a number of frames per "
            "second above 0 and at most 10000, found the integer 0");
  EXPECT_EQ(refusal("[source]\nrate = \"fast\"\n"),
            "vemd.toml: source.rate: expected \"recorded\", \"max\" or a number of frames per "
            "second above 0 and at most 10000, found the string \"fast\"");
}

TEST(VemdConfig, UnknownVersionIsRefused) {
  EXPECT_EQ(refusal("version = 2\n"),
            "vemd.toml: version: expected a whole number from 1 to 1, found 2");
}

TEST(VemdConfig, BrokenTomlNamesTheLine) {
  EXPECT_NE(refusal("[source\n").find("vemd.toml: line 1, column"), std::string::npos);
}

TEST(VemdConfig, MissingFileIsRefused) {
  auto config = vemd::loadConfigFile("/nonexistent/vemd.toml");
  ASSERT_FALSE(config);
  EXPECT_EQ(config.error(), "/nonexistent/vemd.toml: no such file");
}

using VemdConfigFiles = VemdFiles;

// Catches --preview-every turning on a preview the file's map and scale make too large.
TEST_F(VemdConfigFiles, PreviewFlagBeyondTheSizeLimitIsRefused) {
  const fs::path path = dir_ / "large-map.toml";
  std::ofstream(path) << "[processing]\nmap_width = 4096\nmap_height = 2048\n";
  auto parsed = vemd::parseCommandLine({"vemd", "--config", path.string(), "--preview-every", "1"});
  ASSERT_FALSE(parsed);
  EXPECT_EQ(parsed.error().exitCode, 2);
  EXPECT_EQ(parsed.error().err,
            "--preview-every: the preview would be 8192 x 4096 pixels (the 4096 x 2048 map times "
            "output.preview_scale = 2), where at most 4096 on a side was expected; set "
            "output.preview_scale to 1\n");
}

TEST_F(VemdConfigFiles, FlagsOverrideTheFile) {
  const fs::path file = dir_ / "vemd.toml";
  std::ofstream(file) << "[source]\nspec = \"replay:file.vem\"\nframes = 5\n"
                         "[processing]\nlights = 32\n[stats]\nevery_s = 9\n";
  auto config = vemd::parseCommandLine({"vemd",
                                        "--config",
                                        file.string(),
                                        "--frames",
                                        "7",
                                        "--lights",
                                        "128",
                                        "--rate",
                                        "max",
                                        "--loop",
                                        "--cluster",
                                        "0",
                                        "--out",
                                        "o",
                                        "--record",
                                        "r.vem",
                                        "--jsonl",
                                        "l",
                                        "--preview-every",
                                        "3",
                                        "--stats-every",
                                        "0.5"});
  ASSERT_TRUE(config) << config.error().err;
  EXPECT_EQ(config->source.spec, "replay:file.vem");  // from the file: no flag given
  EXPECT_EQ(config->source.frames, 7u);
  EXPECT_EQ(config->processing.lightCount, 128u);
  EXPECT_EQ(config->source.rate.mode, vemd::SourceRate::Mode::Max);
  EXPECT_TRUE(config->source.loop);
  EXPECT_FALSE(config->processing.clustering);
  EXPECT_EQ(config->output.dir, "o");
  EXPECT_EQ(config->output.record, "r.vem");
  EXPECT_EQ(config->output.jsonl, "l");
  EXPECT_EQ(config->output.previewEvery, 3);
  EXPECT_EQ(config->stats.everyS, 0.5);
}

TEST(VemdCommandLine, ClusterFlagSetsTheBudgetAndTurnsClusteringOn) {
  auto config = vemd::parseCommandLine({"vemd", "--cluster", "30"});
  ASSERT_TRUE(config);
  EXPECT_TRUE(config->processing.clustering);
  EXPECT_EQ(config->processing.clusterBudget, 30);
}

TEST(VemdCommandLine, NoFlagsGiveTheDefaults) {
  auto config = vemd::parseCommandLine({"vemd"});
  ASSERT_TRUE(config);
  EXPECT_TRUE(*config == VemdConfig{});
}

TEST(VemdCommandLine, OutOfRangeFlagIsRefusedWithExpectedAndFound) {
  auto config = vemd::parseCommandLine({"vemd", "--lights", "0"});
  ASSERT_FALSE(config);
  EXPECT_NE(config.error().exitCode, 0);
  EXPECT_NE(config.error().err.find("--lights: expected a whole number from 1 to 65536, found 0"),
            std::string::npos)
      << config.error().err;
  auto rate = vemd::parseCommandLine({"vemd", "--rate", "fast"});
  ASSERT_FALSE(rate);
  EXPECT_NE(rate.error().err.find("--rate: expected \"recorded\", \"max\" or a number"),
            std::string::npos)
      << rate.error().err;
}

TEST(VemdCommandLine, BadConfigFileIsRefusedWithItsSentence) {
  auto config = vemd::parseCommandLine({"vemd", "--config", "/nonexistent/v.toml"});
  ASSERT_FALSE(config);
  EXPECT_EQ(config.error().exitCode, 2);
  EXPECT_EQ(config.error().err, "/nonexistent/v.toml: no such file\n");
}

TEST(VemdCommandLine, HelpExitsZeroWithTheFlagsOnStdout) {
  auto config = vemd::parseCommandLine({"vemd", "--help"});
  ASSERT_FALSE(config);
  EXPECT_EQ(config.error().exitCode, 0);
  EXPECT_NE(config.error().out.find("--source"), std::string::npos);
}

TEST(SourceRate, ParsesRecordedMaxAndHertzAndRefusesTheRest) {
  using vemd::parseSourceRate;
  using Mode = vemd::SourceRate::Mode;
  EXPECT_EQ(parseSourceRate("recorded")->mode, Mode::Recorded);
  EXPECT_EQ(parseSourceRate("max")->mode, Mode::Max);
  EXPECT_EQ(parseSourceRate("30")->hz, 30.0);
  for (const char* bad : {"0", "-5", "nan", "inf", "30fps", "", "10001"}) {
    EXPECT_FALSE(parseSourceRate(bad)) << bad;
  }
}

TEST(SourceSpec, NamesWhatWasExpected) {
  EXPECT_EQ(vemd::parseSourceSpec("camera:0").error(),
            "source \"camera:0\": unknown kind \"camera\" (expected replay:FILE.vem, "
            "synthetic:SCENE, aravis:ID, v4l2:DEVICE or libcamera:ID)");
  EXPECT_EQ(vemd::parseSourceSpec("v4l2:").error(),
            "source \"v4l2:\": expected a device path or name after \"v4l2:\"");
  EXPECT_EQ(vemd::parseSourceSpec("aravis:127.0.0.1")->kind, vemd::SourceSpec::Kind::Aravis);
  EXPECT_EQ(vemd::parseSourceSpec("libcamera:0")->kind, vemd::SourceSpec::Kind::Libcamera);
  EXPECT_EQ(vemd::parseSourceSpec("replay:").error(),
            "source \"replay:\": expected a file after \"replay:\"");
  EXPECT_EQ(vemd::parseSourceSpec("").error(),
            "no source given: expected --source (or source.spec in the configuration) "
            "replay:FILE.vem, synthetic:SCENE, aravis:ID, v4l2:DEVICE or libcamera:ID");
  auto spec = vemd::parseSourceSpec("replay:a:b.vem");
  ASSERT_TRUE(spec);
  EXPECT_EQ(spec->argument, "a:b.vem");
}

TEST_F(VemdConfigFiles, ReplayOfAMissingFileIsRefusedWithTheReadersSentence) {
  vemd::SourceConfig source;
  source.spec = "replay:" + (dir_ / "none.vem").string();
  auto made = vemd::makeSource(source);
  ASSERT_FALSE(made);
  EXPECT_EQ(made.error(), (dir_ / "none.vem").string() + ": no such file");
}

TEST(VemdConfig, CameraAndBracketingSectionsAreReadAndRangeChecked) {
  auto config = parseConfig(
      "[camera]\npixel_format = \"Mono12\"\nexposure_us = 250.0\ngain = 2.0\nbuffers = 6\n"
      "[bracketing]\ncount = 3\nstops = 2.5\nbase_exposure_us = 100.0\n",
      "vemd.toml");
  ASSERT_TRUE(config) << config.error();
  EXPECT_EQ(config->camera.pixelFormat, "Mono12");
  EXPECT_EQ(config->camera.exposureUs, 250.0);
  EXPECT_EQ(config->camera.gain, 2.0);
  EXPECT_EQ(config->camera.buffers, 6);
  EXPECT_EQ(config->bracketing.count, 3);
  EXPECT_EQ(config->bracketing.stops, 2.5);
  EXPECT_EQ(config->bracketing.baseExposureUs, 100.0);
  EXPECT_EQ(refusal("[camera]\npixel_format = \"Y16\"\n"),
            "vemd.toml: camera.pixel_format: expected \"\", \"Mono8\", \"Mono10\", \"Mono12\", "
            "\"Mono16\", \"RGB8\" ... \"RGB16\", found the string \"Y16\"");
  EXPECT_EQ(refusal("[bracketing]\ncount = 1\n"),
            "vemd.toml: bracketing.count: expected 0 (off) or 2 to 9, found 1");
  EXPECT_EQ(refusal("[camera]\nbuffers = 1\n"),
            "vemd.toml: camera.buffers: expected a whole number from 2 to 64, found 1");
}

TEST(VemdCommandLine, CameraFileAndListDevicesFlagsAreRead) {
  auto config = vemd::parseCommandLine({"vemd", "--camera", "cam.toml", "--list-devices"});
  ASSERT_TRUE(config);
  EXPECT_EQ(config->source.camera, "cam.toml");
  EXPECT_TRUE(config->listDevices);
}

// --print-config: the configuration in force as TOML, exit 0; a flag overrides the file's value,
// and the text parses back to the very configuration vemd would run with.
TEST_F(VemdConfigFiles, PrintConfigShowsTheFlagOverTheFileAndParsesBackToTheSameConfig) {
  const fs::path file = dir_ / "vemd.toml";
  std::ofstream(file) << "[source]\nspec = \"synthetic:clouds\"\nrate = 29.97\nseed = 7\n"
                         "[processing]\nlights = 512\nsampler = \"standard\"\n"
                         "[filter]\npreset = \"none\"\n[clustering]\ncorrection_factor = 1.9\n"
                         "[output]\njsonl = \"l.jsonl\"\n[stats]\nevery_s = 2.5\n"
                         "[log]\nformat = \"json\"\n[stream]\nlisten = \"[::1]:0\"\n";
  const std::vector<std::string> flags{
      "vemd",   "--config", file.string(), "--lights", "64", "--quiet", "--allow-missing-outputs",
      "--rate", "max"};
  auto running = vemd::parseCommandLine(flags);
  ASSERT_TRUE(running) << running.error().err;
  std::vector<std::string> printing = flags;
  printing.push_back("--print-config");
  auto printed = vemd::parseCommandLine(printing);
  ASSERT_FALSE(printed);
  EXPECT_EQ(printed.error().exitCode, 0);
  EXPECT_EQ(printed.error().err, "");
  const std::string& text = printed.error().out;
  EXPECT_NE(text.find("lights = 64\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("lights = 512"), std::string::npos) << text;
  EXPECT_NE(text.find("level = 'warn'\n"), std::string::npos) << text;
  auto back = parseConfig(text, "printed");
  ASSERT_TRUE(back) << back.error() << "\n" << text;
  EXPECT_EQ(*back, *running) << text;
  EXPECT_EQ(back->processing.lightCount, 64u);
  EXPECT_EQ(back->source.spec, "synthetic:clouds");
}

TEST(VemdConfig, PrintedDefaultsParseBackToTheDefaultsAndTheTokenIsNotShown) {
  vemd::VemdConfig defaults;
  auto back = parseConfig(vemd::formatConfigToml(defaults), "printed");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(*back, defaults);
  vemd::VemdConfig secret;
  secret.stream.token = "0123456789abcdef0123";
  const std::string text = vemd::formatConfigToml(secret);
  EXPECT_EQ(text.find("0123456789abcdef0123"), std::string::npos) << text;
  EXPECT_NE(text.find("# stream.token is set and not shown"), std::string::npos) << text;
}

TEST(VemdSources, LiveCameraWithoutACameraFileIsRefusedBeforeOpeningIt) {
  vemd::SourceConfig source;
  source.spec = "v4l2:/dev/video-that-is-not-there";
  auto made = vemd::makeSource(source);
  ASSERT_FALSE(made);
  EXPECT_EQ(made.error(),
            "source \"v4l2:/dev/video-that-is-not-there\": a live camera needs its camera file "
            "(--camera FILE or source.camera; docs/calibration.md makes one)");
}

TEST_F(VemdConfigFiles, BracketingAReplayIsRefused) {
  vemd::SourceConfig source;
  source.spec = "replay:" + (dir_ / "none.vem").string();
  vemd::BracketingConfig bracketing;
  bracketing.count = 3;
  auto made = vemd::makeSource(source, {}, bracketing);
  ASSERT_FALSE(made);
  EXPECT_NE(made.error().find("bracketing needs a camera with exposure control"), std::string::npos)
      << made.error();
}

}  // namespace
}  // namespace vem::testing
