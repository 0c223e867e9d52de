// The JSON-lines light file: one `vemtool lights` object per frame plus seq and capture_ts_ns,
// floats that parse back bit for bit, the filtered lights when there are some, whole lines on disk
// as soon as consume() returns, and a write error reported once.
#include <nlohmann/json.hpp>

#include "core/light_clustering.h"
#include "sinks/sink_test_frames.h"
#include "vemd/sinks/jsonl_light_sink.h"
#include "vemd/sinks/light_json.h"

namespace vem::testing {
namespace {

using vemd::JsonlLightSink;

class JsonlLightSinkTest : public SinkFiles {};

void expectSameLights(const nlohmann::json& line, const LightSet& set) {
  ASSERT_EQ(line.at("count").get<std::size_t>(), set.lights.size());
  ASSERT_EQ(line.at("lights").size(), set.lights.size());
  for (std::size_t i = 0; i < set.lights.size(); ++i) {
    const nlohmann::json& l = line["lights"][i];
    EXPECT_EQ(l.at("id").get<std::uint32_t>(), set.lights[i].id);
    for (int k = 0; k < 3; ++k) {
      // Parsed as double and narrowed: the shortest form must give back the very same float.
      EXPECT_TRUE(sameBits(float(l["dir"][k].get<double>()), set.lights[i].dir[k]))
          << "light " << i << " dir[" << k << "] " << l["dir"][k];
      EXPECT_TRUE(sameBits(float(l["rgb"][k].get<double>()), set.lights[i].rgb[k]))
          << "light " << i << " rgb[" << k << "] " << l["rgb"][k];
    }
  }
}

TEST_F(JsonlLightSinkTest, LinesParseBackWithSeqTimestampAndBitExactFloats) {
  const fs::path path = dir_ / "lights.jsonl";
  auto sink = JsonlLightSink::open(path);
  ASSERT_TRUE(sink) << sink.error().message;
  for (int i = 0; i < 4; ++i) {
    TestFrame frame(i);
    ASSERT_TRUE(sink->consume(frame.processed));
  }
  ASSERT_TRUE(sink->close());
  const std::vector<std::string> lines = readLines(path);
  ASSERT_EQ(lines.size(), 4U);
  for (int i = 0; i < 4; ++i) {
    const nlohmann::json line = nlohmann::json::parse(lines[std::size_t(i)]);
    EXPECT_EQ(line.at("frame").get<std::uint64_t>(), std::uint64_t(i));
    EXPECT_EQ(line.at("seq").get<std::uint64_t>(), kFirstSeq + std::uint64_t(i));
    EXPECT_EQ(line.at("capture_ts_ns").get<std::int64_t>(), kFirstTsNs + i * kPeriodNs);
    EXPECT_FALSE(line.at("filtered").get<bool>());
    expectSameLights(line, oddLights(i));
  }
}

TEST_F(JsonlLightSinkTest, LineKeepsVemtoolsKeysInVemtoolsOrder) {
  TestFrame frame(0);
  const nlohmann::ordered_json line = vemd::lightsLineJson(frame.processed, 7);
  std::vector<std::string> keys;
  for (const auto& [key, value] : line.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"frame", "seq", "capture_ts_ns", "filtered", "count",
                                            "lights"}));
  const nlohmann::ordered_json vemtool = vemd::frameJson(frame.processed.lights, 7);
  EXPECT_EQ(line["lights"], vemtool["lights"]);
}

TEST_F(JsonlLightSinkTest, FilteredLightsArePublishedWhenPresentElseTheFramesOwn) {
  TestFrame frame(2);
  frame.processed.filtered = oddLights(9, 3);
  frame.processed.filteredSeq = kFirstSeq - 5;
  const nlohmann::json filtered =
      nlohmann::json::parse(vemd::lightsLineJson(frame.processed, 0).dump());
  EXPECT_TRUE(filtered.at("filtered").get<bool>());
  EXPECT_EQ(filtered.at("filtered_seq").get<std::uint64_t>(), kFirstSeq - 5);
  EXPECT_EQ(filtered.at("seq").get<std::uint64_t>(), kFirstSeq + 2);
  expectSameLights(filtered, oddLights(9, 3));

  frame.processed.filtered.reset();
  const nlohmann::json raw =
      nlohmann::json::parse(vemd::lightsLineJson(frame.processed, 0).dump());
  EXPECT_FALSE(raw.at("filtered").get<bool>());
  EXPECT_FALSE(raw.contains("filtered_seq"));
  expectSameLights(raw, oddLights(2));
}

TEST_F(JsonlLightSinkTest, ClusteredLineIsWhatVemtoolLightsClusterWrites) {
  TestFrame frame(1);
  frame.processed.lights = oddLights(1, 40);
  for (Light& l : frame.processed.lights.lights) l.rgb = glm::vec3(0.25F, 0.5F, 1.0F / 7.0F);
  vem::ClusteringParams params;
  params.clusterBudget = 6;
  frame.processed.clustering = clusterLights(frame.processed.lights, params);
  ASSERT_LT(frame.processed.clustering->clusters.lights.size(), 40U);
  const nlohmann::ordered_json line = vemd::lightsLineJson(frame.processed, 3);
  const nlohmann::ordered_json vemtool =
      vemd::clusteredFrameJson(frame.processed.lights, 6, MapLayout::Hemisphere, 3);
  EXPECT_EQ(line["lights"], vemtool["lights"]);
  EXPECT_EQ(line["count"], vemtool["count"]);
  EXPECT_EQ(line["clustered_from"], 40);
  EXPECT_EQ(line["radius_rad"], vemtool["radius_rad"]);
  EXPECT_DOUBLE_EQ(line["radius_rad"].get<double>(), clusterRadiusRad(params));
}

// The radius used to be fixed when vemd started, so a cluster budget changed by a client's control
// message left every later line with the old radius.
TEST_F(JsonlLightSinkTest, RadiusIsTheOneEachFrameWasClusteredWith) {
  TestFrame frame(1);
  frame.processed.lights = oddLights(1, 40);
  double lastRadius = -1.0;
  for (const int budget : {6, 40}) {
    vem::ClusteringParams params;
    params.clusterBudget = budget;
    frame.processed.clustering = clusterLights(frame.processed.lights, params);
    const nlohmann::ordered_json line = vemd::lightsLineJson(frame.processed, 0);
    EXPECT_DOUBLE_EQ(line["radius_rad"].get<double>(), clusterRadiusRad(params)) << budget;
    EXPECT_NE(line["radius_rad"].get<double>(), lastRadius);
    lastRadius = line["radius_rad"].get<double>();
  }
}

TEST_F(JsonlLightSinkTest, ClusteringOfAnotherSetIsNotAttributedToTheseLights) {
  TestFrame frame(1);
  vem::ClusteringParams params;
  params.clusterBudget = 2;
  frame.processed.clustering = clusterLights(oddLights(1, 12), params);  // 12 lights, not 5
  const nlohmann::ordered_json line = vemd::lightsLineJson(frame.processed, 0);
  EXPECT_FALSE(line.contains("clustered_from"));
  EXPECT_EQ(line["count"], 5);
}

TEST_F(JsonlLightSinkTest, EachLineIsInTheFileWhenConsumeReturns) {
  const fs::path path = dir_ / "lights.jsonl";
  auto sink = JsonlLightSink::open(path);
  ASSERT_TRUE(sink);
  for (int i = 0; i < 3; ++i) {
    TestFrame frame(i);
    ASSERT_TRUE(sink->consume(frame.processed));
    const std::vector<std::string> lines = readLines(path);  // another reader, sink still open
    ASSERT_EQ(lines.size(), std::size_t(i + 1));
    EXPECT_TRUE(nlohmann::json::accept(lines.back())) << lines.back();
  }
  EXPECT_EQ(sink->linesWritten(), 3U);
}

TEST_F(JsonlLightSinkTest, RestartAppendsToTheFileInsteadOfTruncatingIt) {
  const fs::path path = dir_ / "lights.jsonl";
  for (int run = 0; run < 2; ++run) {
    auto sink = JsonlLightSink::open(path);
    ASSERT_TRUE(sink);
    TestFrame frame(run);
    ASSERT_TRUE(sink->consume(frame.processed));
    ASSERT_TRUE(sink->close());
  }
  const std::vector<std::string> lines = readLines(path);
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_EQ(nlohmann::json::parse(lines[1]).at("seq").get<std::uint64_t>(), kFirstSeq + 1);
}

TEST_F(JsonlLightSinkTest, FolderThatDoesNotExistFailsAtOpenWithOneSentence) {
  const fs::path path = dir_ / "missing" / "lights.jsonl";
  auto sink = JsonlLightSink::open(path);
  ASSERT_FALSE(sink);
  EXPECT_EQ(sink.error().message,
            "jsonl: cannot open " + path.string() + " for appending (No such file or directory)");
}

// /dev/full accepts open() and fails every write() with ENOSPC.
TEST_F(JsonlLightSinkTest, WriteErrorIsReportedOnceThenTheSinkIsQuiet) {
  auto sink = JsonlLightSink::open("/dev/full");
  ASSERT_TRUE(sink) << sink.error().message;
  TestFrame frame(0);
  auto first = sink->consume(frame.processed);
  ASSERT_FALSE(first);
  EXPECT_EQ(first.error().message,
            "jsonl: /dev/full: cannot write line 0 (No space left on device); the 0 lines before "
            "it stay readable and no more are written");
  EXPECT_TRUE(sink->consume(frame.processed));
  EXPECT_TRUE(sink->close());
}

}  // namespace
}  // namespace vem::testing
