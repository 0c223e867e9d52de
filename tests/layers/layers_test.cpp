// The layer rules (docs/architecture.md, "Layers"): the pure check against small made-up tables,
// the real table's shape, and the real tree against the real table.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "include_rules.h"
#include "tree_scan.h"

namespace vem::layers {
namespace {

// A small stack like the daemon's: util < frames < {stream, sinks} < vemd < tool.
constexpr std::string_view kSmallTable = R"(
# comment
daemon/util ->
daemon/frames -> daemon/util
daemon/stream -> daemon/frames
daemon/vemd/sinks -> daemon/frames
daemon/vemd -> daemon/stream daemon/vemd/sinks   # wires them
tool daemon/tools/vemtool -> daemon/vemd
)";

LayerRules smallRules() {
  auto rules = parseLayerRules(kSmallTable);
  EXPECT_TRUE(rules.has_value()) << rules.error();
  return rules.value_or(LayerRules{});
}

std::vector<Violation> check(const std::vector<IncludeEdge>& includes,
                             const LayerRules& rules = smallRules(),
                             const std::set<std::string>& detailHeaders = {}) {
  return findViolations(includes, rules, detailHeaders);
}

std::string realRoot() { return VEM_SOURCE_DIR; }

LayerRules realRules() {
  auto text = readTextFile(realRoot() + "/tests/layers/allowed_includes.txt");
  EXPECT_TRUE(text.has_value()) << text.error();
  auto rules = parseLayerRules(text.value_or(""));
  EXPECT_TRUE(rules.has_value()) << rules.error();
  return rules.value_or(LayerRules{});
}

TEST(Layers, IncludeOfALowerLayerIsAllowedDirectlyAndThroughOthers) {
  EXPECT_TRUE(check({{"daemon/stream/stream_sink.h", "daemon/frames/sink.h"},
                     {"daemon/vemd/main.cpp", "daemon/util/printable.h"},
                     {"daemon/vemd/main.cpp", "daemon/vemd/pipeline.h"}})
                  .empty());
}

TEST(Layers, StreamIncludingVemdIsReportedAsAnUpwardInclude) {
  const auto violations = check({{"daemon/stream/stream_control.h", "daemon/vemd/pipeline.h"}});
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].kind, ViolationKind::Upward);
  EXPECT_EQ(violations[0].message,
            "daemon/stream/stream_control.h includes daemon/vemd/pipeline.h, an upward include: "
            "daemon/vemd sits above daemon/stream, and a folder includes only the folders below "
            "it (tests/layers/allowed_includes.txt)");
}

TEST(Layers, StreamIncludingASinkIsReportedAsASidewaysInclude) {
  const auto violations =
      check({{"daemon/stream/recording_switch.h", "daemon/vemd/sinks/recorder_sink.h"}});
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].kind, ViolationKind::Sideways);
  EXPECT_NE(violations[0].message.find("neither of daemon/stream and daemon/vemd/sinks"),
            std::string::npos)
      << violations[0].message;
}

TEST(Layers, DetailHeaderOfAnotherLibraryIsReported) {
  const std::set<std::string> detail{"daemon/frames/frame_detail.h"};
  const auto violations =
      check({{"daemon/stream/stream_sink.cpp", "daemon/frames/frame_detail.h"},
             {"daemon/frames/sink.h", "daemon/frames/frame_detail.h"}},  // its own: fine
            smallRules(), detail);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].kind, ViolationKind::DetailHeader);
  EXPECT_EQ(violations[0].message,
            "daemon/stream/stream_sink.cpp includes daemon/frames/frame_detail.h, a detail header "
            "of daemon/frames: only daemon/frames itself may include it (use its public "
            "interface)");
}

TEST(Layers, ToolFolderIncludedByTheDaemonIsReported) {
  const auto violations =
      check({{"daemon/vemd/sinks/jsonl_light_sink.cpp", "daemon/tools/vemtool/light_json.h"}});
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].kind, ViolationKind::ToolFolder);
  EXPECT_NE(violations[0].message.find("from a tool's folder: nothing outside "
                                       "daemon/tools/vemtool may include it"),
            std::string::npos)
      << violations[0].message;
}

TEST(Layers, FolderMissingFromTheTableIsReported) {
  const auto violations = check({{"daemon/newthing/a.cpp", "daemon/frames/sink.h"}});
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].kind, ViolationKind::UnknownFolder);
  EXPECT_NE(violations[0].message.find("daemon/newthing is not in the layer table"),
            std::string::npos)
      << violations[0].message;
}

TEST(Layers, KnownViolationIsNotReportedUntilItIsGone) {
  auto rules = smallRules();
  rules.known.push_back({"daemon/stream/a.cpp", "daemon/vemd/b.h", "fixed by another branch"});
  EXPECT_TRUE(check({{"daemon/stream/a.cpp", "daemon/vemd/b.h"}}, rules).empty());
  const auto stale = check({}, rules);
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_EQ(stale[0].kind, ViolationKind::StaleKnown);
  EXPECT_EQ(stale[0].message,
            "daemon/stream/a.cpp no longer includes daemon/vemd/b.h, listed as a known violation "
            "(fixed by another branch): remove its line from tests/layers/allowed_includes.txt");
}

TEST(Layers, TableLineWithoutAnArrowIsRefusedInOneSentence) {
  const auto rules = parseLayerRules("daemon/util ->\ndaemon/core daemon/util\n");
  ASSERT_FALSE(rules.has_value());
  EXPECT_EQ(rules.error(),
            "tests/layers/allowed_includes.txt: line 2: expected \"FOLDER -> FOLDER ...\" or "
            "\"tool FOLDER -> FOLDER ...\"");
}

TEST(Layers, CycleInATableIsFound) {
  auto rules = parseLayerRules("a -> b\nb -> c\nc -> a\n");
  ASSERT_TRUE(rules.has_value());
  const auto cycle = findCycle(*rules);
  ASSERT_TRUE(cycle.has_value());
  EXPECT_EQ(*cycle, (std::vector<std::string>{"a", "b", "c", "a"}));
}

TEST(Layers, QuotedIncludeResolvesBesideTheFileFirstThenFromTheRoots) {
  const std::set<std::string> files{"daemon/vemd/sinks/light_json.h", "daemon/vemd/pipeline.h",
                                    "calib/core/polar_remap.h"};
  const std::vector<std::string> roots{"", "daemon"};
  EXPECT_EQ(resolveInclude("daemon/vemd/sinks/light_json.cpp", "light_json.h", roots, files),
            "daemon/vemd/sinks/light_json.h");
  EXPECT_EQ(resolveInclude("daemon/stream/a.h", "vemd/pipeline.h", roots, files),
            "daemon/vemd/pipeline.h");
  EXPECT_EQ(resolveInclude("daemon/synth/a.h", "calib/core/polar_remap.h", roots, files),
            "calib/core/polar_remap.h");
  EXPECT_EQ(resolveInclude("daemon/stream/a.h", "vem_stream.pb.h", roots, files), std::nullopt);
}

TEST(Layers, AllowedTableHasNoCycle) {
  const auto cycle = findCycle(realRules());
  std::string shown;
  for (const std::string& folder : cycle.value_or(std::vector<std::string>{})) {
    shown += (shown.empty() ? "" : " -> ") + folder;
  }
  EXPECT_FALSE(cycle.has_value()) << "the layer table has a cycle: " << shown;
}

TEST(Layers, RealTreeHasNoForbiddenInclude) {
  const auto tree = scanSourceTree(realRoot());
  ASSERT_TRUE(tree.has_value()) << tree.error();
  ASSERT_GT(tree->includes.size(), 500u) << "the scan found too few includes under " << realRoot();
  for (const Violation& violation :
       findViolations(tree->includes, realRules(), tree->detailHeaders)) {
    ADD_FAILURE() << violation.message;
  }
}

}  // namespace
}  // namespace vem::layers
