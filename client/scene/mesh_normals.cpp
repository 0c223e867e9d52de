#include "client/scene/mesh_normals.h"

#include <glm/geometric.hpp>

#include "util/contract.h"

namespace vem::scene {

std::expected<std::vector<glm::vec3>, std::size_t> smoothNormals(
    std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
  VEM_EXPECTS(indices.size() % 3 == 0);
  // Accumulate in double: a vertex shared by thousands of tiny triangles keeps its precision.
  std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0));
  std::vector<bool> used(positions.size(), false);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    const glm::dvec3 a(positions[indices[i]]);
    const glm::dvec3 b(positions[indices[i + 1]]);
    const glm::dvec3 c(positions[indices[i + 2]]);
    const glm::dvec3 areaWeighted = glm::cross(b - a, c - a);
    for (std::size_t k = 0; k < 3; ++k) {
      sums[indices[i + k]] += areaWeighted;
      used[indices[i + k]] = true;
    }
  }
  std::vector<glm::vec3> normals(positions.size());
  for (std::size_t v = 0; v < sums.size(); ++v) {
    const double length = glm::length(sums[v]);
    if (!used[v]) {
      normals[v] = glm::vec3(0.0F, 1.0F, 0.0F);
      continue;
    }
    if (!(length > 0.0)) {
      return std::unexpected(v);
    }
    normals[v] = glm::vec3(sums[v] / length);
  }
  return normals;
}

}  // namespace vem::scene
