// Image error metrics: how far a rendered frame is from a reference of the same size, over the
// pixels both cover (render/linear_image.h), in linear radiance.
//
// - relativeRms: sqrt(sum |a - r|^2 / sum |r|^2) over covered pixels and the three channels: the
//   error of the whole picture relative to its energy (0 is exact). Robust to dark pixels.
// - meanAbsoluteRelative: mean over covered pixels of |Y(a) - Y(r)| / mean Y(r) (Rec. 709 Y).
// - maxPixelRelative: the largest |Y(a) - Y(r)| / mean Y(r) over covered pixels.
// - fractionAbove(t): the fraction of covered pixels whose |Y(a) - Y(r)| / mean Y(r) exceeds t
//   (for tolerances that allow a few edge pixels to differ, e.g. shadow-map edges).
// - coverageMismatch: pixels covered in one image and not in the other.
#pragma once

#include <cstddef>
#include <vector>

#include "client/render/linear_image.h"

namespace vem::render {

struct ImageError {
  double relativeRms = 0.0;
  double meanAbsoluteRelative = 0.0;
  double maxPixelRelative = 0.0;
  std::size_t comparedPixels = 0;
  std::size_t coverageMismatch = 0;
  [[nodiscard]] double fractionAbove(double threshold) const;

  std::vector<float> pixelRelative;  // per compared pixel, |dY| / mean Y(r)
};

// Same size required (a contract: aborts otherwise).
[[nodiscard]] ImageError compareImages(const LinearImage& rendered, const LinearImage& reference);

}  // namespace vem::render
