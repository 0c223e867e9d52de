// Differential rendering (Debevec 1998, "Rendering synthetic objects into real scenes"): synthetic
// objects composited into a camera's picture of the real scene (the "plate", issue 21), with the
// shadows they cast on the real surfaces.
//
// The local scene is the real surfaces the objects can shadow or be hidden by (the floor, proxy
// meshes), rendered white (diffuse albedo 1) so that a render of it is its irradiance over pi.
// Per frame, two renders from the plate camera under the same lights: `withObjects` (the local
// scene and the objects) and `withoutObjects` (the local scene alone), and the class of each
// pixel's nearest surface in `withObjects`. Then, per pixel and channel, in the lights' units:
//   object pixel:      composite = withObjects                     (the object hides the plate)
//   local pixel:       composite = plate + albedo (withObjects - withoutObjects)
//   background pixel:  composite = plate
//   a pixel an object's edge crosses (resampled layers): cover x the object's radiance + (1 -
//   cover) x the rest of the pixel as above
// with albedo the local surface's diffuse albedo estimated from the plate itself, nobody types it
// in: albedo = plate / withoutObjects, clamped to [0, 1] (a plate darker than the render gives 0,
// never a negative or NaN albedo; a saturated plate gives a lower bound, clamped at 1), averaged
// over time (AlbedoEstimate). Where the estimate is exact, the local pixel is plate times the
// ratio withObjects / withoutObjects: the object's shadow darkens the real floor by the share of
// the light it takes away.
//
// Colour: the plate is linear (decoded once, before) in its own units; plate = gainRgb * radiance
// in the lights' units (the scene camera's colour match to the light probe, calib/core's
// PlateColourMatch). The composite is computed in the lights' units and returned in the plate's.
// Non-finite plate values count as 0 (and are counted); the composite is never negative or NaN.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "client/render/linear_image.h"

namespace vem::render {

// What a pixel's nearest surface is, in the render with the objects.
enum class SurfaceClass : std::uint8_t { Background = 0, Local = 1, Object = 2 };

// The renders one composite needs, all the same size.
struct DifferentialLayers {
  LinearImage withObjects;
  LinearImage withoutObjects;
  std::vector<SurfaceClass> classes;  // per pixel, of withObjects
  // Resampled layers only (layer_resampling.h), where an object's edge crosses a pixel: the
  // share of the pixel the objects cover (0 to 1) and their radiance there. At such a pixel
  // withObjects, withoutObjects and classes hold the rest of the pixel (the local surface or the
  // background), and the composite blends the two by the share. Empty: no pixel is shared.
  std::vector<float> objectCover;
  LinearImage objectRadiance;
};

struct PlateColour {
  glm::vec3 gainRgb{1.0F};  // plate value per unit of the lights' radiance, > 0 per channel
  float saturation = 0.0F;  // the plate's clipping level in its own units; 0: none known
};

// The local surfaces' albedo per pixel, averaged over the frames seen with the same plate camera
// and local scene (reset() when either changes). Each frame's estimate enters with weight
// 1 / min(frames, windowFrames): a running mean that becomes an exponential average of
// windowFrames frames, so sensor noise averages out and a real change still comes through.
class AlbedoEstimate {
 public:
  explicit AlbedoEstimate(int windowFrames = 30);
  // Takes this frame's estimate where the local scene is seen (withoutObjects covered and bright
  // enough to divide by). Sizes must agree; a new size resets.
  void update(const LinearImage& plate, const LinearImage& withoutObjects,
              const PlateColour& colour);
  void reset();
  [[nodiscard]] bool empty() const { return frames_ == 0; }
  [[nodiscard]] int frames() const { return frames_; }
  [[nodiscard]] int widthPx() const { return widthPx_; }
  [[nodiscard]] int heightPx() const { return heightPx_; }
  // The estimate at pixel i (0 where none was ever taken).
  [[nodiscard]] glm::vec3 at(std::size_t pixel) const;
  // Pixels whose estimate was clamped in the last update (darker than 0 is impossible; brighter
  // than 1 or saturated).
  [[nodiscard]] std::size_t clampedLastUpdate() const { return clamped_; }

 private:
  int windowFrames_;
  int frames_ = 0;
  int widthPx_ = 0;
  int heightPx_ = 0;
  std::vector<glm::vec3> albedo_;
  std::vector<std::uint16_t> seen_;  // frames that contributed at each pixel (saturating)
  std::size_t clamped_ = 0;
};

struct CompositeStats {
  std::size_t objectPixels = 0;
  std::size_t localPixels = 0;
  std::size_t nonFinitePlatePixels = 0;
};

// The composite (above) in the plate's units, covered everywhere. All sizes must agree and the
// albedo must have been updated at this size.
[[nodiscard]] LinearImage compositeDifferential(const LinearImage& plate,
                                                const DifferentialLayers& layers,
                                                const AlbedoEstimate& albedo,
                                                const PlateColour& colour,
                                                CompositeStats* stats = nullptr);

// The objects pasted over the plate with no differential pass: what compositing without it looks
// like (no shadows on the real surfaces), for comparison, and the composite when nothing synthetic
// can shadow the local scene. layers.withoutObjects is not read (it may be empty).
[[nodiscard]] LinearImage compositePasted(const LinearImage& plate,
                                          const DifferentialLayers& layers,
                                          const PlateColour& colour);

}  // namespace vem::render
