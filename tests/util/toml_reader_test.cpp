// TomlReader (daemon/util/toml_reader.h): each test names the bug it stops. The calibration files'
// and vemd's configuration's own suites check their full sentences; these check the reader.
#include "util/toml_reader.h"

#include <gtest/gtest.h>

namespace vem::util {
namespace {

toml::table parsed(const std::string& text) {
  auto document = parseToml(text, "t.toml");
  EXPECT_TRUE(document) << document.error().message;
  return document ? std::move(*document) : toml::table{};
}

TEST(TomlReader, BrokenSyntaxNamesTheFileLineAndColumn) {
  const auto document = parseToml("a = \n", "t.toml");
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error().cause, TomlProblem::BadSyntax);
  EXPECT_TRUE(document.error().message.starts_with("t.toml: line 1, column "))
      << document.error().message;
}

TEST(TomlReader, MisspeltKeyIsRefusedNotIgnored) {
  const toml::table doc = parsed("[camera]\nexposure_us = 5\nwidht = 3\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader camera(*doc["camera"].as_table(), "camera.", status);
  camera.onlyKeys({"exposure_us", "width"});
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message,
            "t.toml: camera.widht: unknown field (expected one of: exposure_us, width)");
}

TEST(TomlReader, MisspeltSectionIsNamedASectionInConfigWording) {
  const toml::table doc = parsed("[sorce]\nrate = 1\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  const std::string_view known[] = {"source"};
  top.onlyKeys(known, UnknownKeyWords::KeyOrSection);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message, "t.toml: sorce: unknown section (expected one of: source)");
}

TEST(TomlReader, FirstFailureWinsAndLaterReadsRecordNothing) {
  const toml::table doc = parsed("a = \"x\"\nb = \"y\"\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  EXPECT_EQ(top.integer("a", 0, 9), 0);
  EXPECT_EQ(top.integer("b", 0, 9), 0);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message, "t.toml: a: expected an integer, found the string \"x\"");
}

TEST(TomlReader, MissingRequiredFieldSaysWhatWasExpected) {
  const toml::table doc = parsed("");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "lens.", status);
  (void)top.quantity("focal", "px");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->cause, TomlProblem::MissingField);
  EXPECT_EQ(status.failure->message,
            "t.toml: lens.focal: missing (expected { value = <number>, unit = \"px\" })");
}

TEST(TomlReader, QuantityInTheWrongUnitIsRefusedNotConverted) {
  const toml::table doc = parsed("f = { value = 3, unit = \"mm\" }\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  (void)top.quantity("f", "px");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->cause, TomlProblem::WrongUnit);
  EXPECT_EQ(status.failure->message, "t.toml: f: expected unit \"px\", found \"mm\"");
}

TEST(TomlReader, AngleInRadiansIsConvertedForADegreeField) {
  const toml::table doc = parsed("yaw = { value = 3.141592653589793, unit = \"rad\" }\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  EXPECT_NEAR(top.angleDeg("yaw"), 180.0, 1e-12);
  EXPECT_TRUE(status.ok());
}

TEST(TomlReader, NonFiniteNumberIsRefused) {
  const toml::table doc = parsed("x = inf\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  (void)top.number("x");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message, "t.toml: x: expected a finite number, found inf");
}

TEST(TomlReader, AbsentOptionalFieldKeepsItsDefaultAndOutOfRangeOneIsRefused) {
  const toml::table doc = parsed("depth = 99\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "source.", status);
  int frames = 7;
  top.optionalWholeNumber("frames", 0, 10, frames);
  EXPECT_EQ(frames, 7);
  int depth = 4;
  top.optionalWholeNumber("depth", 1, 64, depth, "memory grows with it");
  EXPECT_EQ(depth, 4);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message,
            "t.toml: source.depth: expected a whole number from 1 to 64 (memory grows with it), "
            "found 99");
}

TEST(TomlReader, ChoiceListsTheNamesItTakes) {
  const toml::table doc = parsed("sampler = \"fast\"\n");
  TomlStatus status{"t.toml", std::nullopt};
  TomlReader top(doc, "", status);
  std::size_t index = 0;
  top.optionalChoice("sampler", {"havran", "standard", "other"}, index);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.failure->message,
            "t.toml: sampler: expected \"havran\", \"standard\" or \"other\", found the string "
            "\"fast\"");
}

}  // namespace
}  // namespace vem::util
