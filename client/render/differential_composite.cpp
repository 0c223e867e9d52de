#include "client/render/differential_composite.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/common.hpp>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "util/contract.h"

namespace vem::render {
namespace {

bool sameSize(const LinearImage& a, const LinearImage& b) {
  return a.widthPx == b.widthPx && a.heightPx == b.heightPx;
}

glm::vec3 rgbAt(const LinearImage& image, std::size_t pixel) {
  return {image.rgb[3 * pixel], image.rgb[3 * pixel + 1], image.rgb[3 * pixel + 2]};
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The plate in the lights' units; non-finite values count as 0.
glm::vec3 plateRadiance(const LinearImage& plate, std::size_t pixel, const PlateColour& colour,
                        bool* nonFinite) {
  const glm::vec3 value = rgbAt(plate, pixel);
  if (!finite(value)) {
    *nonFinite = true;
    return glm::vec3(0.0F);
  }
  *nonFinite = false;
  return glm::max(value, glm::vec3(0.0F)) / colour.gainRgb;
}

bool saturated(const LinearImage& plate, std::size_t pixel, const PlateColour& colour) {
  if (!(colour.saturation > 0.0F)) {
    return false;
  }
  const glm::vec3 value = rgbAt(plate, pixel);
  return value.x >= colour.saturation || value.y >= colour.saturation ||
         value.z >= colour.saturation;
}

// A composite pixel, never negative or NaN, in the plate's units.
void storeInPlateUnits(LinearImage& out, std::size_t pixel, glm::vec3 radiance,
                       const PlateColour& colour) {
  radiance = finite(radiance) ? glm::max(radiance, glm::vec3(0.0F)) : glm::vec3(0.0F);
  const glm::vec3 value = radiance * colour.gainRgb;
  out.rgb[3 * pixel] = value.x;
  out.rgb[3 * pixel + 1] = value.y;
  out.rgb[3 * pixel + 2] = value.z;
  out.covered[pixel] = 1;
}

// `rest` blended with the objects' radiance by the share of pixel i they cover, where an object's
// edge crosses it; `rest` itself elsewhere.
glm::vec3 withObjectEdge(const DifferentialLayers& layers, std::size_t i, glm::vec3 rest) {
  if (layers.objectCover.empty()) return rest;
  const float cover = layers.objectCover[i];
  if (!(cover > 0.0F && cover < 1.0F)) return rest;
  return cover * rgbAt(layers.objectRadiance, i) + (1.0F - cover) * rest;
}

void expectColour(const PlateColour& colour) {
  VEM_EXPECTS(colour.gainRgb.x > 0.0F && colour.gainRgb.y > 0.0F && colour.gainRgb.z > 0.0F);
  VEM_EXPECTS(std::isfinite(colour.gainRgb.x) && std::isfinite(colour.gainRgb.y) &&
              std::isfinite(colour.gainRgb.z));
}

void expectLayers(const LinearImage& plate, const DifferentialLayers& layers) {
  VEM_EXPECTS(sameSize(plate, layers.withObjects) && sameSize(plate, layers.withoutObjects));
  VEM_EXPECTS(layers.classes.size() == plate.pixelCount());
  VEM_EXPECTS(layers.objectCover.empty() || (layers.objectCover.size() == plate.pixelCount() &&
                                             sameSize(plate, layers.objectRadiance)));
}

// f(first, last) over ranges of pixels on TBB's threads (each pixel is its own: the result does
// not depend on the schedule).
template <class F>
void forPixelRanges(std::size_t pixelCount, const F& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixelCount, 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

}  // namespace

AlbedoEstimate::AlbedoEstimate(int windowFrames) : windowFrames_(windowFrames) {
  VEM_EXPECTS(windowFrames >= 1);
}

void AlbedoEstimate::reset() {
  frames_ = 0;
  widthPx_ = 0;
  heightPx_ = 0;
  albedo_.clear();
  seen_.clear();
  clamped_ = 0;
}

void AlbedoEstimate::update(const LinearImage& plate, const LinearImage& withoutObjects,
                            const PlateColour& colour) {
  VEM_EXPECTS(sameSize(plate, withoutObjects));
  expectColour(colour);
  if (plate.widthPx != widthPx_ || plate.heightPx != heightPx_) {
    reset();
    widthPx_ = plate.widthPx;
    heightPx_ = plate.heightPx;
    albedo_.assign(plate.pixelCount(), glm::vec3(0.0F));
    seen_.assign(plate.pixelCount(), 0);
  }
  tbb::combinable<std::size_t> clampedCount([] { return std::size_t{0}; });
  forPixelRanges(plate.pixelCount(), [&](std::size_t first, std::size_t last) {
    std::size_t& clampedHere = clampedCount.local();
    for (std::size_t i = first; i < last; ++i) {
      if (withoutObjects.covered[i] == 0) {
        continue;
      }
      const glm::vec3 white = rgbAt(withoutObjects, i);
      bool nonFinite = false;
      const glm::vec3 radiance = plateRadiance(plate, i, colour, &nonFinite);
      if (nonFinite || !finite(white)) {
        continue;
      }
      glm::vec3 estimate(0.0F);
      bool clamped = saturated(plate, i, colour);
      for (int c = 0; c < 3; ++c) {
        if (!(white[c] > 0.0F)) {
          continue;  // no light reaches it: nothing to divide by, nothing to composite either
        }
        const float raw = radiance[c] / white[c];
        clamped = clamped || raw > 1.0F;
        estimate[c] = std::clamp(raw, 0.0F, 1.0F);
      }
      clampedHere += clamped ? 1U : 0U;
      const std::uint16_t n =
          std::min<std::uint16_t>(std::uint16_t(seen_[i] + 1), std::uint16_t(windowFrames_));
      seen_[i] = n;
      albedo_[i] += (estimate - albedo_[i]) / float(n);
    }
  });
  clamped_ = clampedCount.combine(std::plus<>());
  ++frames_;
}

glm::vec3 AlbedoEstimate::at(std::size_t pixel) const {
  VEM_EXPECTS(pixel < albedo_.size());
  return albedo_[pixel];
}

LinearImage compositeDifferential(const LinearImage& plate, const DifferentialLayers& layers,
                                  const AlbedoEstimate& albedo, const PlateColour& colour,
                                  CompositeStats* stats) {
  expectLayers(plate, layers);
  expectColour(colour);
  VEM_EXPECTS(albedo.widthPx() == plate.widthPx && albedo.heightPx() == plate.heightPx);
  tbb::combinable<CompositeStats> countedParts;
  LinearImage out = LinearImage::black(plate.widthPx, plate.heightPx);
  forPixelRanges(plate.pixelCount(), [&](std::size_t first, std::size_t last) {
    CompositeStats& counted = countedParts.local();
    for (std::size_t i = first; i < last; ++i) {
      bool nonFinite = false;
      const glm::vec3 radiance = plateRadiance(plate, i, colour, &nonFinite);
      counted.nonFinitePlatePixels += nonFinite ? 1U : 0U;
      glm::vec3 value = radiance;
      if (layers.classes[i] == SurfaceClass::Object) {
        value = rgbAt(layers.withObjects, i);
        ++counted.objectPixels;
      } else if (layers.classes[i] == SurfaceClass::Local) {
        value = radiance +
                albedo.at(i) * (rgbAt(layers.withObjects, i) - rgbAt(layers.withoutObjects, i));
        ++counted.localPixels;
      }
      storeInPlateUnits(out, i, withObjectEdge(layers, i, value), colour);
    }
  });
  if (stats != nullptr) {
    *stats = countedParts.combine([](CompositeStats a, const CompositeStats& b) {
      a.objectPixels += b.objectPixels;
      a.localPixels += b.localPixels;
      a.nonFinitePlatePixels += b.nonFinitePlatePixels;
      return a;
    });
  }
  return out;
}

LinearImage compositePasted(const LinearImage& plate, const DifferentialLayers& layers,
                            const PlateColour& colour) {
  VEM_EXPECTS(sameSize(plate, layers.withObjects));
  VEM_EXPECTS(layers.classes.size() == plate.pixelCount());
  VEM_EXPECTS(layers.objectCover.empty() || (layers.objectCover.size() == plate.pixelCount() &&
                                             sameSize(plate, layers.objectRadiance)));
  expectColour(colour);
  LinearImage out = LinearImage::black(plate.widthPx, plate.heightPx);
  forPixelRanges(plate.pixelCount(), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      bool nonFinite = false;
      const glm::vec3 value = layers.classes[i] == SurfaceClass::Object
                                  ? rgbAt(layers.withObjects, i)
                                  : plateRadiance(plate, i, colour, &nonFinite);
      storeInPlateUnits(out, i, withObjectEdge(layers, i, value), colour);
    }
  });
  return out;
}

}  // namespace vem::render
