// LinearImage: a rendered frame before tone mapping, as both renderers return it.
//
// Conventions: widthPx x heightPx pixels, row-major, row 0 at the top (scene/orbit_camera.h);
// rgb holds linear radiance in the environment map's units (three floats per pixel). covered[i] is
// 1 where a surface of the scene covers pixel i's centre and 0 where the background (the cube map,
// or black) shows: error figures are taken over covered pixels only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace vem::render {

struct LinearImage {
  int widthPx = 0;
  int heightPx = 0;
  std::vector<float> rgb;             // widthPx * heightPx * 3
  std::vector<std::uint8_t> covered;  // widthPx * heightPx

  [[nodiscard]] static LinearImage black(int widthPx, int heightPx);
  [[nodiscard]] std::size_t pixelCount() const {
    return std::size_t(widthPx) * std::size_t(heightPx);
  }
  [[nodiscard]] glm::vec3 at(int x, int y) const;
  void set(int x, int y, glm::vec3 value, bool isCovered);
};

}  // namespace vem::render
