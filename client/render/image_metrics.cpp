#include "client/render/image_metrics.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"
#include "util/contract.h"

namespace vem::render {

double ImageError::fractionAbove(double threshold) const {
  if (pixelRelative.empty()) {
    return 0.0;
  }
  const auto above =
      std::ranges::count_if(pixelRelative, [&](float e) { return double(e) > threshold; });
  return double(above) / double(pixelRelative.size());
}

ImageError compareImages(const LinearImage& rendered, const LinearImage& reference) {
  VEM_EXPECTS(rendered.widthPx == reference.widthPx && rendered.heightPx == reference.heightPx);
  ImageError error;
  double sumDiff2 = 0.0;
  double sumRef2 = 0.0;
  double sumRefY = 0.0;
  std::vector<double> dy;
  for (std::size_t p = 0; p < reference.pixelCount(); ++p) {
    if ((rendered.covered[p] != 0) != (reference.covered[p] != 0)) {
      ++error.coverageMismatch;
    }
    if (rendered.covered[p] == 0 || reference.covered[p] == 0) {
      continue;
    }
    glm::dvec3 a(rendered.rgb[3 * p], rendered.rgb[3 * p + 1], rendered.rgb[3 * p + 2]);
    glm::dvec3 r(reference.rgb[3 * p], reference.rgb[3 * p + 1], reference.rgb[3 * p + 2]);
    for (int c = 0; c < 3; ++c) {
      sumDiff2 += (a[c] - r[c]) * (a[c] - r[c]);
      sumRef2 += r[c] * r[c];
    }
    sumRefY += luminance(r);
    dy.push_back(std::abs(luminance(a) - luminance(r)));
  }
  error.comparedPixels = dy.size();
  if (dy.empty() || sumRefY <= 0.0) {
    return error;
  }
  const double meanY = sumRefY / double(dy.size());
  error.relativeRms = std::sqrt(sumDiff2 / std::max(sumRef2, 1e-300));
  double sumRel = 0.0;
  for (double d : dy) {
    const double rel = d / meanY;
    sumRel += rel;
    error.maxPixelRelative = std::max(error.maxPixelRelative, rel);
    error.pixelRelative.push_back(float(rel));
  }
  error.meanAbsoluteRelative = sumRel / double(dy.size());
  return error;
}

}  // namespace vem::render
