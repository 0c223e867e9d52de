// The layers of a composite resampled into the plate's pixels (render/layer_resampling.h).
#include "client/render/layer_resampling.h"

#include <gtest/gtest.h>

namespace vem::render {
namespace {

// A 2 x 1 render: the left pixel an object of radiance 4, the right the local floor at 2; the
// floor at 2 in both pixels of the render without the objects.
DifferentialLayers twoPixels() {
  DifferentialLayers layers;
  layers.withObjects = LinearImage::black(2, 1);
  layers.withObjects.set(0, 0, glm::vec3(4.0F), true);
  layers.withObjects.set(1, 0, glm::vec3(2.0F), true);
  layers.withoutObjects = LinearImage::black(2, 1);
  layers.withoutObjects.set(0, 0, glm::vec3(2.0F), true);
  layers.withoutObjects.set(1, 0, glm::vec3(2.0F), true);
  layers.classes = {SurfaceClass::Object, SurfaceClass::Local};
  return layers;
}

TEST(LayerResampling, LargerPlateTakesEachPixelsClassAndRadianceFromItsTaps) {
  const DifferentialLayers out = resampledLayers(twoPixels(), 4, 2, {});
  ASSERT_EQ(out.withObjects.widthPx, 4);
  ASSERT_EQ(out.classes.size(), 8U);
  EXPECT_EQ(out.classes[0], SurfaceClass::Object);
  EXPECT_EQ(out.classes[2], SurfaceClass::Local);
  EXPECT_EQ(out.classes[7], SurfaceClass::Local);
  EXPECT_FLOAT_EQ(out.withObjects.at(0, 0).x, 4.0F);  // clamped at the edge
  EXPECT_FLOAT_EQ(out.objectCover[0], 0.0F);          // all its taps are the object's
  EXPECT_FLOAT_EQ(out.withObjects.at(3, 1).x, 2.0F);
  EXPECT_FLOAT_EQ(out.withoutObjects.at(2, 1).x, 2.0F);
}

// Plate pixel 1 sits a quarter of the way from the object's render pixel to the floor's. The
// nearest class made the object's edge step at twice the render's size, and blending the taps
// across the edge put the floor's radiance into the object's (3.5 for 4).
TEST(LayerResampling, EdgePixelKeepsTheObjectsShareApartSoNeitherSideBleedsIntoTheOther) {
  const DifferentialLayers out = resampledLayers(twoPixels(), 4, 2, {});
  EXPECT_FLOAT_EQ(out.objectCover[1], 0.75F);
  EXPECT_FLOAT_EQ(out.objectRadiance.at(1, 0).x, 4.0F);
  EXPECT_EQ(out.classes[1], SurfaceClass::Local);  // the rest of the pixel: the floor
  EXPECT_FLOAT_EQ(out.withObjects.at(1, 0).x, 2.0F);
  EXPECT_FLOAT_EQ(out.withoutObjects.at(1, 0).x, 2.0F);
  // Composited: three quarters object, one quarter floor (here the plate, unshadowed).
  LinearImage plate = LinearImage::black(4, 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) plate.set(x, y, glm::vec3(1.0F), true);
  }
  AlbedoEstimate albedo;
  albedo.update(plate, out.withoutObjects, PlateColour{});
  const LinearImage composite = compositeDifferential(plate, out, albedo, PlateColour{});
  EXPECT_FLOAT_EQ(composite.at(1, 0).x, 0.75F * 4.0F + 0.25F * 1.0F);
  EXPECT_FLOAT_EQ(compositePasted(plate, out, PlateColour{}).at(1, 0).x, 3.25F);
}

TEST(LayerResampling, LensTableSendsEachPlatePixelWhereItsUndistortedRayLands) {
  // Every plate pixel looks at the render's right pixel, as a strong lens would send them there.
  const std::vector<glm::vec2> table(6, glm::vec2(1.6F, 0.5F));
  const DifferentialLayers out = resampledLayers(twoPixels(), 3, 2, table);
  for (const SurfaceClass c : out.classes) EXPECT_EQ(c, SurfaceClass::Local);
  EXPECT_FLOAT_EQ(out.withObjects.at(0, 0).x, 2.0F);
}

TEST(LayerResampling, NoDifferentialPassLeavesTheRenderWithoutTheObjectsEmpty) {
  DifferentialLayers layers = twoPixels();
  layers.withoutObjects = {};
  const DifferentialLayers out = resampledLayers(layers, 4, 2, {});
  EXPECT_EQ(out.withoutObjects.widthPx, 0);
  EXPECT_EQ(out.withObjects.widthPx, 4);
}

}  // namespace
}  // namespace vem::render
