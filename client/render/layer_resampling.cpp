#include "client/render/layer_resampling.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/contract.h"

namespace vem::render {
namespace {

// The four taps of a bilinear read at a render position: pixel offsets (times 3) and weights.
struct Taps {
  std::size_t offset[4];
  float weight[4];
};

Taps tapsAt(int widthPx, int heightPx, glm::vec2 renderPx) {
  const float fx = std::clamp(renderPx.x - 0.5F, 0.0F, float(widthPx - 1));
  const float fy = std::clamp(renderPx.y - 0.5F, 0.0F, float(heightPx - 1));
  const int x0 = int(fx);
  const int y0 = int(fy);
  const int x1 = std::min(x0 + 1, widthPx - 1);
  const int y1 = std::min(y0 + 1, heightPx - 1);
  const float tx = fx - float(x0);
  const float ty = fy - float(y0);
  const auto at = [widthPx](int x, int y) {
    return 3 * (std::size_t(y) * std::size_t(widthPx) + std::size_t(x));
  };
  return Taps{{at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)},
              {(1.0F - tx) * (1.0F - ty), tx * (1.0F - ty), (1.0F - tx) * ty, tx * ty}};
}

void readInto(const LinearImage& from, const Taps& taps, float* out) {
  const float* rgb = from.rgb.data();
  for (int c = 0; c < 3; ++c) {
    out[c] = rgb[taps.offset[0] + std::size_t(c)] * taps.weight[0] +
             rgb[taps.offset[1] + std::size_t(c)] * taps.weight[1] +
             rgb[taps.offset[2] + std::size_t(c)] * taps.weight[2] +
             rgb[taps.offset[3] + std::size_t(c)] * taps.weight[3];
  }
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
  out.objectCover.assign(out.withObjects.pixelCount(), 0.0F);
  out.objectRadiance = LinearImage::black(plateWidthPx, plateHeightPx);
  // Rows in parallel on TBB's threads; each pixel is written once, so the result does not depend
  // on the schedule.
  tbb::parallel_for(
      tbb::blocked_range<int>(0, plateHeightPx), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
          for (int x = 0; x < plateWidthPx; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(plateWidthPx) + std::size_t(x);
            const glm::vec2 at = renderPxOfPlatePx.empty()
                                     ? scaledRenderPx(x, y, plateWidthPx, plateHeightPx, w, h)
                                     : renderPxOfPlatePx[i];
            const std::size_t n = nearest(w, h, at);
            Taps taps = tapsAt(w, h, at);
            // Where an object's edge crosses the pixel: the objects' share and radiance apart,
            // and the rest of the pixel from the other taps alone.
            Taps objectTaps = taps;
            float cover = 0.0F;
            std::size_t rest = n;
            for (int k = 0; k < 4; ++k) {
              const std::size_t tap = taps.offset[k] / 3;
              const bool object = rendered.classes[tap] == SurfaceClass::Object;
              cover += object ? taps.weight[k] : 0.0F;
              objectTaps.weight[k] = object ? taps.weight[k] : 0.0F;
            }
            if (cover > 1e-4F && cover < 1.0F - 1e-4F) {
              float restWeight = 0.0F;
              for (int k = 0; k < 4; ++k) {
                const std::size_t tap = taps.offset[k] / 3;
                const bool object = rendered.classes[tap] == SurfaceClass::Object;
                objectTaps.weight[k] /= cover;
                taps.weight[k] = object ? 0.0F : taps.weight[k] / (1.0F - cover);
                if (!object && taps.weight[k] > restWeight) {
                  restWeight = taps.weight[k];
                  rest = tap;  // the other taps' heaviest names the rest of the pixel
                }
              }
              readInto(rendered.withObjects, objectTaps, &out.objectRadiance.rgb[3 * i]);
              out.objectCover[i] = cover;
            }
            out.classes[i] = rendered.classes[rest];
            readInto(rendered.withObjects, taps, &out.withObjects.rgb[3 * i]);
            out.withObjects.covered[i] = rendered.withObjects.covered[rest];
            if (withWithout) {
              readInto(rendered.withoutObjects, taps, &out.withoutObjects.rgb[3 * i]);
              out.withoutObjects.covered[i] = rendered.withoutObjects.covered[rest];
            }
          }
        }
      });
  return out;
}

}  // namespace vem::render
