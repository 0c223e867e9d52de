#include "vemview/golden_compare.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "client/render/image_files.h"

namespace vem::testing {

void compareSrgb8WithGolden(const std::vector<std::uint8_t>& rendered, int widthPx, int heightPx,
                            const std::string& name) {
  const auto path = std::filesystem::path(VEM_SOURCE_DIR) / "tests" / "vemview" / "golden" / name;
  if (std::getenv("VEM_UPDATE_GOLDEN") != nullptr) {
    ASSERT_TRUE(render::saveSrgbPng(rendered, widthPx, heightPx, path).has_value());
    std::printf("updated %s\n", path.c_str());
    return;
  }
  const auto golden = render::loadSrgb8(path);
  ASSERT_TRUE(golden.has_value()) << golden.error() << " (VEM_UPDATE_GOLDEN=1 makes it)";
  ASSERT_EQ(golden->widthPx, widthPx);
  ASSERT_EQ(golden->heightPx, heightPx);
  double sum = 0.0;
  std::size_t outliers = 0;
  for (std::size_t i = 0; i < rendered.size(); ++i) {
    const int d = std::abs(int(rendered[i]) - int(golden->rgb[i]));
    sum += d;
    outliers += d > kGoldenOutlierLevels ? 1 : 0;
  }
  const double mean = sum / double(rendered.size());
  const double fraction = double(outliers) / double(rendered.size());
  std::printf("%s: mean |difference| %.3f levels, %.4f %% beyond %d levels\n", name.c_str(), mean,
              100.0 * fraction, kGoldenOutlierLevels);
  EXPECT_LT(mean, kGoldenMeanTolerance) << name;
  EXPECT_LT(fraction, kGoldenOutlierFraction) << name;
  if (::testing::Test::HasFailure()) {
    const auto failed = std::filesystem::temp_directory_path() / ("failed-" + name);
    (void)render::saveSrgbPng(rendered, widthPx, heightPx, failed);
    std::printf("the rendered picture is in %s\n", failed.c_str());
  }
}

}  // namespace vem::testing
