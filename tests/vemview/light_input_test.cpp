#include "client/vemview/light_input.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>

namespace vem::view {
namespace {

std::filesystem::path writeFile(const std::string& name, const std::string& text) {
  const auto folder = std::filesystem::temp_directory_path() / "vemview_light_input_test";
  std::filesystem::create_directories(folder);
  const auto path = folder / name;
  std::ofstream(path) << text;
  return path;
}

TEST(LightFileInput, ReadsEveryFrameThenHoldsTheLast) {
  const auto path = writeFile(
      "two.jsonl",
      R"({"frame":0,"count":1,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,2,3]}]})"
      "\n"
      R"({"frame":1,"count":2,"lights":[{"id":0,"dir":[1,0,0],"rgb":[1,1,1]},{"id":1,"dir":[0,0,1],"rgb":[2,2,2]}]})"
      "\n");
  auto input = openLightFileInput(path.string());
  ASSERT_TRUE(input.has_value()) << input.error();
  const auto first = (*input)->next(std::chrono::milliseconds(0));
  const auto second = (*input)->next(std::chrono::milliseconds(0));
  const auto third = (*input)->next(std::chrono::milliseconds(0));
  ASSERT_TRUE(first && second && third);
  EXPECT_EQ(first->lights->lights.size(), 1U);
  EXPECT_EQ(first->lights->lights[0].rgb, glm::vec3(1, 2, 3));
  EXPECT_EQ(second->lights->lights.size(), 2U);
  EXPECT_EQ(third->seq, second->seq);  // nothing new: the same lights, the same seq
  EXPECT_NEAR(second->lights->luminanceSr, 3.0, 1e-6);
}

TEST(LightFileInput, ClusteredFramesFromVemdAreMarkedClustered) {
  const auto path = writeFile(
      "clustered.jsonl",
      R"({"frame":0,"count":1,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1],"members":[0,1]}],"clustered_from":2})"
      "\n");
  auto input = openLightFileInput(path.string());
  ASSERT_TRUE(input.has_value()) << input.error();
  EXPECT_TRUE((*input)->facts().clustered);
}

// The status named the clusters as lights ("lights 11"): a frame says how many lights its
// clusters stand for ("clustered_from", else the members), for "lights 256 (11 clusters)".
TEST(LightFileInput, ClusteredFrameSaysHowManyLightsItsClustersStandForSoTheStatusNamesBoth) {
  const auto path = writeFile(
      "clustered_counts.jsonl",
      R"({"frame":0,"count":1,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1],"members":[0,1]}],"clustered_from":2})"
      "\n"
      R"({"frame":1,"count":2,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1],"members":[0,1,2]},{"id":1,"dir":[1,0,0],"rgb":[1,1,1],"members":[3]}]})"
      "\n"
      R"({"frame":2,"count":1,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1]}]})"
      "\n");
  auto input = openLightFileInput(path.string());
  ASSERT_TRUE(input.has_value()) << input.error();
  EXPECT_EQ((*input)->next(std::chrono::milliseconds(0))->clusteredFrom, 2U);
  EXPECT_EQ((*input)->next(std::chrono::milliseconds(0))->clusteredFrom, 4U);
  EXPECT_EQ((*input)->next(std::chrono::milliseconds(0))->clusteredFrom, 0U);
}

TEST(LightFileInput, BadLineIsRefusedNamingTheFileTheLineAndTheField) {
  const auto path =
      writeFile("bad.jsonl", R"({"frame":0,"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,1,1]}]})"
                             "\n"
                             R"({"frame":1,"lights":[{"id":0,"dir":[0,2,0],"rgb":[1,1,1]}]})"
                             "\n");
  auto input = openLightFileInput(path.string());
  ASSERT_FALSE(input.has_value());
  EXPECT_NE(input.error().find("bad.jsonl: line 2"), std::string::npos) << input.error();
  EXPECT_NE(input.error().find("unit vector"), std::string::npos) << input.error();
}

TEST(LightFileInput, NegativeOrNonNumericRgbIsRefused) {
  const auto negative =
      writeFile("negative.jsonl", R"({"lights":[{"id":0,"dir":[0,1,0],"rgb":[1,-1,1]}]})"
                                  "\n");
  auto a = openLightFileInput(negative.string());
  ASSERT_FALSE(a.has_value());
  EXPECT_NE(a.error().find("must not be negative"), std::string::npos) << a.error();
  const auto text = writeFile("text.jsonl", R"({"lights":[{"dir":[0,1,0],"rgb":"white"}]})"
                                            "\n");
  auto b = openLightFileInput(text.string());
  ASSERT_FALSE(b.has_value());
  EXPECT_NE(b.error().find("\"rgb\" must be an array of three numbers"), std::string::npos);
}

TEST(LightFileInput, MissingOrEmptyFileIsRefused) {
  auto missing = openLightFileInput("/nonexistent/lights.jsonl");
  ASSERT_FALSE(missing.has_value());
  EXPECT_NE(missing.error().find("/nonexistent/lights.jsonl"), std::string::npos);
  auto empty = openLightFileInput(writeFile("empty.jsonl", "\n\n").string());
  ASSERT_FALSE(empty.has_value());
  EXPECT_NE(empty.error().find("holds no frame"), std::string::npos);
}

TEST(MapInput, LightsAreComputedOnceAndTheFrameNeverChanges) {
  auto input = openMapInput(std::string(VEM_SHARED_DATA_DIR) + "/hdri/park.exr",
                            MapInputOptions{64, true, 16});
  ASSERT_TRUE(input.has_value()) << input.error();
  const auto a = (*input)->next(std::chrono::milliseconds(0));
  const auto b = (*input)->next(std::chrono::milliseconds(0));
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->seq, b->seq);
  EXPECT_EQ(a->lights.get(), b->lights.get());  // the same set, not recomputed
  EXPECT_EQ(a->lights->lights.size(), 64U);
  ASSERT_NE(a->cube, nullptr);
  EXPECT_EQ(a->cube->levels[0].facePx, 16);
  EXPECT_EQ((*input)->facts().layout, MapLayout::Sphere);
}

TEST(MapInput, NoCubeMapUnlessThePlanWantsOne) {
  auto input = openMapInput(std::string(VEM_SHARED_DATA_DIR) + "/hdri/park.exr",
                            MapInputOptions{16, false, 16});
  ASSERT_TRUE(input.has_value()) << input.error();
  EXPECT_EQ((*input)->next(std::chrono::milliseconds(0))->cube, nullptr);
}

}  // namespace
}  // namespace vem::view
