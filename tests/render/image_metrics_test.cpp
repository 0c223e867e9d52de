#include "client/render/image_metrics.h"

#include <gtest/gtest.h>

namespace vem::render {
namespace {

LinearImage ramp(float scale) {
  LinearImage image = LinearImage::black(16, 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      image.set(x, y, scale * glm::vec3(float(x + 1), float(y + 1), 1.0F), true);
    }
  }
  return image;
}

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
  const ImageError e = compareImages(ramp(1.0F), ramp(1.0F));
  EXPECT_EQ(e.relativeRms, 0.0);
  EXPECT_EQ(e.maxPixelRelative, 0.0);
  EXPECT_EQ(e.comparedPixels, 128U);
}

TEST(ImageMetrics, TenPercentBrighterIsTenPercentRelativeRms) {
  const ImageError e = compareImages(ramp(1.1F), ramp(1.0F));
  EXPECT_NEAR(e.relativeRms, 0.1, 1e-6);
  EXPECT_NEAR(e.meanAbsoluteRelative, 0.1, 1e-6);
}

TEST(ImageMetrics, BackgroundPixelsDoNotCountButMismatchedCoverageIsReported) {
  LinearImage a = ramp(1.0F);
  LinearImage r = ramp(1.0F);
  a.set(0, 0, glm::vec3(1e6F), false);
  r.set(0, 0, glm::vec3(0.0F), false);
  a.set(1, 0, glm::vec3(1e6F), false);  // covered in the reference only
  const ImageError e = compareImages(a, r);
  EXPECT_EQ(e.relativeRms, 0.0);
  EXPECT_EQ(e.coverageMismatch, 1U);
  EXPECT_EQ(e.comparedPixels, 126U);
}

TEST(ImageMetrics, OneBadPixelShowsInTheFractionAboveATolerance) {
  LinearImage a = ramp(1.0F);
  a.set(3, 3, glm::vec3(100.0F), true);
  const ImageError e = compareImages(a, ramp(1.0F));
  EXPECT_NEAR(e.fractionAbove(0.5), 1.0 / 128.0, 1e-9);
}

}  // namespace
}  // namespace vem::render
