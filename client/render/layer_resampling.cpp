#include "client/render/layer_resampling.h"

#include <algorithm>
#include <cmath>

#include "util/contract.h"

namespace vem::render {
namespace {

glm::vec3 bilinear(const LinearImage& image, glm::vec2 renderPx) {
  const float fx = std::clamp(renderPx.x - 0.5F, 0.0F, float(image.widthPx - 1));
  const float fy = std::clamp(renderPx.y - 0.5F, 0.0F, float(image.heightPx - 1));
  const int x0 = int(fx);
  const int y0 = int(fy);
  const int x1 = std::min(x0 + 1, image.widthPx - 1);
  const int y1 = std::min(y0 + 1, image.heightPx - 1);
  const float tx = fx - float(x0);
  const float ty = fy - float(y0);
  const glm::vec3 top = image.at(x0, y0) * (1.0F - tx) + image.at(x1, y0) * tx;
  const glm::vec3 bottom = image.at(x0, y1) * (1.0F - tx) + image.at(x1, y1) * tx;
  return top * (1.0F - ty) + bottom * ty;
}

std::size_t nearest(int widthPx, int heightPx, glm::vec2 renderPx) {
  const int x = std::clamp(int(std::floor(renderPx.x)), 0, widthPx - 1);
  const int y = std::clamp(int(std::floor(renderPx.y)), 0, heightPx - 1);
  return std::size_t(y) * std::size_t(widthPx) + std::size_t(x);
}

}  // namespace

glm::vec2 scaledRenderPx(int x, int y, int plateWidthPx, int plateHeightPx, int widthPx,
                         int heightPx) {
  return {(float(x) + 0.5F) * float(widthPx) / float(plateWidthPx),
          (float(y) + 0.5F) * float(heightPx) / float(plateHeightPx)};
}

DifferentialLayers resampledLayers(const DifferentialLayers& rendered, int plateWidthPx,
                                   int plateHeightPx,
                                   std::span<const glm::vec2> renderPxOfPlatePx) {
  const int w = rendered.withObjects.widthPx;
  const int h = rendered.withObjects.heightPx;
  VEM_EXPECTS(plateWidthPx >= 1 && plateHeightPx >= 1 && w >= 1 && h >= 1);
  const bool withWithout = rendered.withoutObjects.widthPx != 0;
  VEM_EXPECTS(!withWithout ||
              (rendered.withoutObjects.widthPx == w && rendered.withoutObjects.heightPx == h));
  VEM_EXPECTS(rendered.classes.size() == std::size_t(w) * std::size_t(h));
  VEM_EXPECTS(renderPxOfPlatePx.empty() ||
              renderPxOfPlatePx.size() == std::size_t(plateWidthPx) * std::size_t(plateHeightPx));
  DifferentialLayers out;
  out.withObjects = LinearImage::black(plateWidthPx, plateHeightPx);
  if (withWithout) out.withoutObjects = LinearImage::black(plateWidthPx, plateHeightPx);
  out.classes.assign(out.withObjects.pixelCount(), SurfaceClass::Background);
  for (int y = 0; y < plateHeightPx; ++y) {
    for (int x = 0; x < plateWidthPx; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(plateWidthPx) + std::size_t(x);
      const glm::vec2 at = renderPxOfPlatePx.empty()
                               ? scaledRenderPx(x, y, plateWidthPx, plateHeightPx, w, h)
                               : renderPxOfPlatePx[i];
      const std::size_t n = nearest(w, h, at);
      out.classes[i] = rendered.classes[n];
      out.withObjects.set(x, y, bilinear(rendered.withObjects, at),
                          rendered.withObjects.covered[n] != 0);
      if (withWithout) {
        out.withoutObjects.set(x, y, bilinear(rendered.withoutObjects, at),
                               rendered.withoutObjects.covered[n] != 0);
      }
    }
  }
  return out;
}

}  // namespace vem::render
