// The tools' shared command-line conventions (daemon/util/cli_conventions.h).
#include "util/cli_conventions.h"

#include <map>
#include <sstream>

#include <gtest/gtest.h>

namespace vem::cli {
namespace {

enum class Renderer { kGl, kEmbree, kReference };

struct Parsed {
  int status = -1;
  std::string out;
  std::string err;
};

// A small tool with a subcommand, an enum choice, a negatable flag and a default.
Parsed run(std::vector<std::string> args) {
  CLI::App app{"demo: a tool"};
  Renderer renderer = Renderer::kGl;
  bool png = true;
  int count = 256;
  CLI::App* draw = app.add_subcommand("draw", "draws");
  const std::map<std::string, Renderer> names{
      {"gl", Renderer::kGl}, {"embree", Renderer::kEmbree}, {"reference", Renderer::kReference}};
  draw->add_option("--renderer", renderer, "which renderer")
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case))
      ->capture_default_str();
  draw->add_flag("--png,!--no-png", png, "write PNG files");
  draw->add_option("--count", count, "lights")->capture_default_str();
  applyConventions(app, "demo");
  args.insert(args.begin(), "demo");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  Parsed parsed;
  std::ostringstream out, err;
  try {
    app.parse(int(argv.size()), argv.data());
    parsed.status = kExitSuccess;
  } catch (const CLI::ParseError& e) {
    parsed.status = exitStatusFor(app, e, out, err);
  }
  parsed.out = out.str();
  parsed.err = err.str();
  return parsed;
}

TEST(CliConventions, HelpShowsChoicesAsPlainWordsNotTheParsersMap) {
  const Parsed p = run({"draw", "--help"});
  EXPECT_EQ(p.status, kExitSuccess);
  EXPECT_NE(p.out.find("embree|gl|reference (default: gl)"), std::string::npos) << p.out;
  EXPECT_EQ(p.out.find("->"), std::string::npos) << p.out;
  EXPECT_EQ(p.out.find("ENUM"), std::string::npos) << p.out;
  EXPECT_EQ(p.out.find(" OR "), std::string::npos) << p.out;
}

TEST(CliConventions, NegatableFlagIsShownWithoutItsValueInBraces) {
  const Parsed p = run({"draw", "--help"});
  EXPECT_NE(p.out.find("--no-png"), std::string::npos) << p.out;
  EXPECT_EQ(p.out.find("{false}"), std::string::npos) << p.out;
}

TEST(CliConventions, DefaultsAreSpelledOut) {
  const Parsed p = run({"draw", "--help"});
  EXPECT_NE(p.out.find("(default: 256)"), std::string::npos) << p.out;
}

bool endsWithTheExitStatuses(std::string help) {
  while (!help.empty() && help.back() == '\n') help.pop_back();
  return help.ends_with(kExitStatusHelp);
}

TEST(CliConventions, EveryHelpPageEndsWithTheExitStatuses) {
  EXPECT_TRUE(endsWithTheExitStatuses(run({"--help"}).out)) << run({"--help"}).out;
  EXPECT_TRUE(endsWithTheExitStatuses(run({"draw", "--help"}).out)) << run({"draw", "--help"}).out;
}

TEST(CliConventions, TheExitStatusesComeAfterTheToolsOwnExamplesAndOnlyOnce) {
  CLI::App app{"demo"};
  app.footer("Examples:\n  demo draw");
  app.add_subcommand("draw", "draws");
  applyConventions(app, "demo");
  applyConventions(app, "demo");
  const std::string help = app.help();
  EXPECT_LT(help.find("Examples:"), help.find(kExitStatusHelp)) << help;
  EXPECT_EQ(help.find(kExitStatusHelp), help.rfind(kExitStatusHelp)) << help;
  EXPECT_TRUE(endsWithTheExitStatuses(help)) << help;
}

TEST(CliConventions, UnknownFlagIsAUsageErrorExitTwoNotCli11sCode) {
  const Parsed p = run({"draw", "--frobnicate"});
  EXPECT_EQ(p.status, kExitUsage);
  EXPECT_NE(p.err.find("demo: error: "), std::string::npos) << p.err;
  EXPECT_NE(p.err.find("(see 'demo draw --help')"), std::string::npos) << p.err;
}

TEST(CliConventions, BadChoiceIsAUsageErrorExitTwo) {
  EXPECT_EQ(run({"draw", "--renderer", "vulkan"}).status, kExitUsage);
  EXPECT_EQ(run({"draw", "--count", "many"}).status, kExitUsage);
  EXPECT_EQ(run({}).status, kExitSuccess);
}

TEST(CliConventions, PlainTypeNameLeavesNamesWithoutChoicesAlone) {
  EXPECT_EQ(plainTypeName("INT"), "INT");
  EXPECT_EQ(plainTypeName("ENUM:value in {gl->0,embree->1} OR {0,1}"), "gl|embree");
  EXPECT_EQ(plainTypeName("TEXT:{sphere,hemisphere}"), "sphere|hemisphere");
}

}  // namespace
}  // namespace vem::cli
