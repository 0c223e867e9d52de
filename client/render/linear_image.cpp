#include "client/render/linear_image.h"

namespace vem::render {

LinearImage LinearImage::black(int widthPx, int heightPx) {
  LinearImage image;
  image.widthPx = widthPx;
  image.heightPx = heightPx;
  image.rgb.assign(image.pixelCount() * 3, 0.0F);
  image.covered.assign(image.pixelCount(), 0);
  return image;
}

glm::vec3 LinearImage::at(int x, int y) const {
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(widthPx) + std::size_t(x));
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void LinearImage::set(int x, int y, glm::vec3 value, bool isCovered) {
  const std::size_t p = std::size_t(y) * std::size_t(widthPx) + std::size_t(x);
  rgb[3 * p] = value.x;
  rgb[3 * p + 1] = value.y;
  rgb[3 * p + 2] = value.z;
  covered[p] = isCovered ? 1 : 0;
}

}  // namespace vem::render
