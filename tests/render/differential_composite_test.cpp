// Differential compositing (render/differential_composite.h) on hand-made layers: each test is
// named after the bug it catches.
#include "client/render/differential_composite.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace vem::render {
namespace {

constexpr int kW = 4;
constexpr int kH = 2;

LinearImage filled(glm::vec3 value, bool covered = true) {
  LinearImage image = LinearImage::black(kW, kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) image.set(x, y, value, covered);
  }
  return image;
}

// The local floor lit with irradiance / pi = 2 (white), an object's shadow halving it at pixel 1,
// an object at pixel 2, the background at pixel 3.
DifferentialLayers floorWithShadow() {
  DifferentialLayers layers;
  layers.withoutObjects = filled(glm::vec3(2.0F));
  layers.withObjects = filled(glm::vec3(2.0F));
  layers.withObjects.set(1, 0, glm::vec3(1.0F), true);
  layers.withObjects.set(2, 0, glm::vec3(5.0F, 4.0F, 3.0F), true);
  layers.classes.assign(std::size_t(kW * kH), SurfaceClass::Local);
  layers.classes[2] = SurfaceClass::Object;
  layers.classes[3] = SurfaceClass::Background;
  layers.withObjects.covered[3] = 0;
  layers.withoutObjects.covered[3] = 0;
  return layers;
}

bool finiteAndNonNegative(const LinearImage& image) {
  for (const float v : image.rgb) {
    if (!std::isfinite(v) || v < 0.0F) return false;
  }
  return true;
}

TEST(DifferentialComposite, ShadowDarkensTheRealFloorByTheShareOfLightTheObjectTakes) {
  const DifferentialLayers layers = floorWithShadow();
  const LinearImage plate = filled(glm::vec3(0.8F, 0.6F, 0.4F));  // albedo 0.4 / 0.3 / 0.2
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, PlateColour{});
  EXPECT_NEAR(albedo.at(0).x, 0.4F, 1e-6F);
  CompositeStats stats;
  const LinearImage out = compositeDifferential(plate, layers, albedo, PlateColour{}, &stats);
  EXPECT_NEAR(out.at(0, 0).x, 0.8F, 1e-6F);  // unshadowed floor: the plate itself
  EXPECT_NEAR(out.at(1, 0).x, 0.4F, 1e-6F);  // half the light: half the plate
  EXPECT_NEAR(out.at(1, 0).z, 0.2F, 1e-6F);
  EXPECT_NEAR(out.at(2, 0).y, 4.0F, 1e-6F);  // the object hides the plate
  EXPECT_NEAR(out.at(3, 0).x, 0.8F, 1e-6F);  // background: the plate
  EXPECT_EQ(stats.objectPixels, 1U);
  EXPECT_EQ(stats.localPixels, std::size_t(kW * kH - 2));
  const LinearImage pasted = compositePasted(plate, layers, PlateColour{});
  EXPECT_NEAR(pasted.at(1, 0).x, 0.8F, 1e-6F);  // no shadow without the differential pass
}

TEST(DifferentialComposite, PlateDarkerThanTheRenderedFloorClampsTheAlbedoAtZeroNeverNegative) {
  const DifferentialLayers layers = floorWithShadow();
  LinearImage plate = filled(glm::vec3(0.8F));
  plate.set(1, 0, glm::vec3(-0.5F, 0.0F, 1e-30F), true);  // a black level below zero
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, PlateColour{});
  EXPECT_EQ(albedo.at(1).x, 0.0F);
  EXPECT_GE(albedo.at(1).z, 0.0F);
  const LinearImage out = compositeDifferential(plate, layers, albedo, PlateColour{});
  EXPECT_TRUE(finiteAndNonNegative(out));
  EXPECT_EQ(out.at(1, 0).x, 0.0F);
}

TEST(DifferentialComposite, SaturatedPlateKeepsAnAlbedoOfAtMostOneAndStillTakesTheShadow) {
  const DifferentialLayers layers = floorWithShadow();
  const PlateColour colour{.gainRgb = glm::vec3(1.0F), .saturation = 1.0F};
  const LinearImage plate = filled(glm::vec3(1.0F));  // clipped everywhere
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, colour);
  EXPECT_LE(albedo.at(1).x, 1.0F);
  EXPECT_EQ(albedo.clampedLastUpdate(), std::size_t(kW * kH - 1));
  const LinearImage out = compositeDifferential(plate, layers, albedo, colour);
  EXPECT_TRUE(finiteAndNonNegative(out));
  EXPECT_LT(out.at(1, 0).x, out.at(0, 0).x);  // the shadow shows on the clipped floor
}

TEST(DifferentialComposite, NanPlatePixelsBecomeBlackAndAreCountedNotSpreadIntoTheAlbedo) {
  const DifferentialLayers layers = floorWithShadow();
  LinearImage plate = filled(glm::vec3(0.8F));
  plate.set(0, 1, glm::vec3(std::numeric_limits<float>::quiet_NaN()), true);
  plate.set(1, 1, glm::vec3(std::numeric_limits<float>::infinity()), true);
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, PlateColour{});
  EXPECT_EQ(albedo.at(std::size_t(kW)), glm::vec3(0.0F));
  CompositeStats stats;
  const LinearImage out = compositeDifferential(plate, layers, albedo, PlateColour{}, &stats);
  EXPECT_TRUE(finiteAndNonNegative(out));
  EXPECT_EQ(stats.nonFinitePlatePixels, 2U);
}

TEST(DifferentialComposite, UnlitFloorGivesNoAlbedoInsteadOfADivisionByZero) {
  DifferentialLayers layers = floorWithShadow();
  layers.withoutObjects = filled(glm::vec3(0.0F));
  layers.withObjects = filled(glm::vec3(0.0F));
  const LinearImage plate = filled(glm::vec3(0.3F));
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, PlateColour{});
  EXPECT_EQ(albedo.at(0), glm::vec3(0.0F));
  const LinearImage out = compositeDifferential(plate, layers, albedo, PlateColour{});
  EXPECT_TRUE(finiteAndNonNegative(out));
  EXPECT_NEAR(out.at(0, 0).x, 0.3F, 1e-6F);
}

TEST(DifferentialComposite, ColourMatchComposesInTheLightsUnitsAndReturnsThePlatesUnits) {
  const DifferentialLayers layers = floorWithShadow();
  // The plate camera sees the probe's radiance times (0.5, 1, 2).
  const PlateColour colour{.gainRgb = glm::vec3(0.5F, 1.0F, 2.0F)};
  const LinearImage plate = filled(glm::vec3(0.2F, 0.4F, 0.8F));  // albedo 0.2 in every channel
  AlbedoEstimate albedo;
  albedo.update(plate, layers.withoutObjects, colour);
  EXPECT_NEAR(albedo.at(0).x, 0.2F, 1e-6F);
  EXPECT_NEAR(albedo.at(0).z, 0.2F, 1e-6F);
  const LinearImage out = compositeDifferential(plate, layers, albedo, colour);
  EXPECT_NEAR(out.at(2, 0).x, 5.0F * 0.5F, 1e-6F);  // the object in the plate's units
  EXPECT_NEAR(out.at(1, 0).z, 0.4F, 1e-6F);
}

TEST(DifferentialComposite, AlbedoAveragesSensorNoiseOverTheWindowAndFollowsARealChange) {
  const DifferentialLayers layers = floorWithShadow();
  AlbedoEstimate albedo(4);
  for (int frame = 0; frame < 4; ++frame) {
    albedo.update(filled(glm::vec3(frame % 2 == 0 ? 0.9F : 0.7F)), layers.withoutObjects,
                  PlateColour{});
  }
  EXPECT_NEAR(albedo.at(0).x, 0.4F, 1e-6F);  // the mean of 0.45 and 0.35
  for (int frame = 0; frame < 40; ++frame) {
    albedo.update(filled(glm::vec3(0.2F)), layers.withoutObjects, PlateColour{});
  }
  EXPECT_NEAR(albedo.at(0).x, 0.1F, 1e-3F);  // an exponential average, not a frozen mean
  EXPECT_EQ(albedo.frames(), 44);
}

TEST(DifferentialComposite, PlateOfAnotherSizeResetsTheAlbedoInsteadOfReadingPastIt) {
  const DifferentialLayers layers = floorWithShadow();
  AlbedoEstimate albedo;
  albedo.update(filled(glm::vec3(0.8F)), layers.withoutObjects, PlateColour{});
  LinearImage bigger = LinearImage::black(2 * kW, kH);
  LinearImage biggerWithout = LinearImage::black(2 * kW, kH);
  albedo.update(bigger, biggerWithout, PlateColour{});
  EXPECT_EQ(albedo.widthPx(), 2 * kW);
  EXPECT_EQ(albedo.frames(), 1);
}

}  // namespace
}  // namespace vem::render
