// Patch lists (calib/io/patch_file.h): a chart survives a save and a load, and each bad patch is
// refused in one sentence naming the file, the patch and the field.
#include "calib/io/patch_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vem::calib::io {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("vem_patch_file_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

std::vector<PatchSpec> chart() {
  return {{"p1", 10, 20, 30, 40, 1.0, false},
          {"p2", 100, 20, 30, 40, 6.309573444801933, false},
          {"grey \"card\"", 0, 0, 1, 1, 1e4, false},
          {"c1", 200, 300, 64, 64, 0.1 + 0.2, true}};
}

std::string writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string refusalOf(const TempDir& dir, const std::string& text, CalibFileError cause) {
  const std::string path = writeText(dir / "patches.toml", text);
  const auto loaded = loadPatchFile(path);
  EXPECT_FALSE(loaded.has_value()) << text;
  if (loaded) return "";
  EXPECT_EQ(loaded.error().cause, cause) << loaded.error().message;
  EXPECT_EQ(loaded.error().message.rfind(path + ": ", 0), 0U) << loaded.error().message;
  return loaded.error().message;
}

constexpr const char* kGoodPatch = R"([[patch]]
name = "p1"
region = { value = [10, 20, 30, 40], unit = "px" }
luminance = { value = 12.5, unit = "cd/m2" }
)";

std::string withPatch(const std::string& body) {
  return std::string(kGoodPatch) + "\n[[patch]]\nname = \"p2\"\n" + body;
}

TEST(PatchFile, SaveThenLoadKeepsEveryPatchExactlyAndInOrder) {
  const TempDir dir;
  ASSERT_TRUE(savePatchFile(chart(), dir / "patches.toml"));
  const auto back = loadPatchFile(dir / "patches.toml");
  ASSERT_TRUE(back.has_value()) << back.error().message;
  const std::vector<PatchSpec> original = chart();
  ASSERT_EQ(back->size(), original.size());
  for (std::size_t i = 0; i < back->size(); ++i) {
    const PatchSpec& a = original[i];
    const PatchSpec& b = (*back)[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(std::tie(a.x, a.y, a.width, a.height), std::tie(b.x, b.y, b.width, b.height));
    EXPECT_EQ(a.luminanceCdM2, b.luminanceCdM2);
    EXPECT_EQ(a.check, b.check);
  }
}

TEST(PatchFile, CheckIsOptionalAndDefaultsToAFitPatch) {
  const TempDir dir;
  const auto loaded = loadPatchFile(writeText(dir / "patches.toml", kGoodPatch));
  ASSERT_TRUE(loaded.has_value()) << loaded.error().message;
  EXPECT_FALSE(loaded->front().check);
  EXPECT_EQ(loaded->front().luminanceCdM2, 12.5);
}

TEST(PatchFile, WrongUnitNamesThePatchAndTheField) {
  const TempDir dir;
  const std::string message =
      refusalOf(dir,
                withPatch("region = { value = [1, 2, 3, 4], unit = \"mm\" }\nluminance = { value = "
                          "1, unit = \"cd/m2\" }\n"),
                CalibFileError::WrongUnit);
  EXPECT_NE(message.find("patch \"p2\": region: expected unit \"px\", found \"mm\""),
            std::string::npos)
      << message;
  const std::string nits = refusalOf(dir,
                                     withPatch("region = { value = [1, 2, 3, 4], unit = \"px\" "
                                               "}\nluminance = { value = 1, unit = \"nit\" }\n"),
                                     CalibFileError::WrongUnit);
  EXPECT_NE(nits.find("patch \"p2\": luminance: expected unit \"cd/m2\""), std::string::npos)
      << nits;
}

TEST(PatchFile, MissingFieldNamesThePatch) {
  const TempDir dir;
  const std::string message =
      refusalOf(dir, withPatch("region = { value = [1, 2, 3, 4], unit = \"px\" }\n"),
                CalibFileError::MissingField);
  EXPECT_NE(message.find("patch \"p2\": luminance: missing"), std::string::npos) << message;
  const std::string unnamed =
      refusalOf(dir, "[[patch]]\nregion = { value = [1, 2, 3, 4], unit = \"px\" }\n",
                CalibFileError::MissingField);
  EXPECT_NE(unnamed.find("patch 1: name: missing"), std::string::npos) << unnamed;
}

TEST(PatchFile, WrongTypesAndBadValuesAreRefused) {
  const TempDir dir;
  const std::string region = "region = { value = [1, 2, 3, 4], unit = \"px\" }\n";
  const std::string luminance = "luminance = { value = 5, unit = \"cd/m2\" }\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"region = { value = [1, 2, 3.5, 4], unit = \"px\" }\n" + luminance,
       "region: expected whole numbers"},
      {"region = { value = [1, 2, 3], unit = \"px\" }\n" + luminance, "region: expected 4 values"},
      {"region = { value = [1, 2, 0, 4], unit = \"px\" }\n" + luminance,
       "region: expected a width and height"},
      {"region = { value = [-1, 2, 3, 4], unit = \"px\" }\n" + luminance,
       "region: expected x and y"},
      {region + "luminance = { value = -5, unit = \"cd/m2\" }\n",
       "luminance: expected a luminance above 0"},
      {region + "luminance = { value = \"5\", unit = \"cd/m2\" }\n",
       "luminance: expected a number"},
      {region + luminance + "check = \"yes\"\n", "check: expected true or false"},
      {region + luminance + "chek = true\n", "chek: unknown field"},
  };
  for (const auto& [body, expected] : cases) {
    SCOPED_TRACE(body);
    const std::string message = refusalOf(dir, withPatch(body), CalibFileError::BadValue);
    EXPECT_NE(message.find("patch \"p2\": " + expected), std::string::npos) << message;
  }
}

TEST(PatchFile, DuplicateNamesAreRefused) {
  const TempDir dir;
  const std::string message =
      refusalOf(dir, std::string(kGoodPatch) + "\n" + kGoodPatch, CalibFileError::BadValue);
  EXPECT_NE(message.find("patch \"p1\": name: the name is used by an earlier patch"),
            std::string::npos)
      << message;
}

TEST(PatchFile, FileWithoutPatchesIsRefused) {
  const TempDir dir;
  const std::string message = refusalOf(dir, "# nothing here\n", CalibFileError::MissingField);
  EXPECT_NE(message.find("patch: missing"), std::string::npos) << message;
}

TEST(PatchFile, SavingAnInvalidPatchWritesNothing) {
  const TempDir dir;
  ASSERT_TRUE(savePatchFile(chart(), dir / "patches.toml"));
  std::ifstream in(dir / "patches.toml");
  const std::string before{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<PatchSpec> bad = chart();
  bad[1].luminanceCdM2 = 0.0;
  const auto saved = savePatchFile(bad, dir / "patches.toml");
  ASSERT_FALSE(saved);
  EXPECT_NE(saved.error().message.find("patch \"p2\": luminance"), std::string::npos)
      << saved.error().message;
  std::ifstream after(dir / "patches.toml");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(after), std::istreambuf_iterator<char>()),
            before);
}

}  // namespace
}  // namespace vem::calib::io
