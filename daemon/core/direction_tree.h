// A kd-tree (nanoflann) over unit directions, for the nearest or the within-an-angle search on the
// sphere: the chord between unit vectors grows with the angle, chord^2 = 2 - 2 cos(angle).
// The directions are borrowed: they must outlive the tree and not change under it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <nanoflann.hpp>

namespace vem {

// nanoflann's dataset adaptor over unit directions.
struct DirectionCloud {
  const std::vector<glm::dvec3>& dirs;

  [[nodiscard]] std::size_t kdtree_get_point_count() const { return dirs.size(); }
  [[nodiscard]] double kdtree_get_pt(std::size_t index, std::size_t dim) const {
    return dirs[index][glm::length_t(dim)];
  }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox& /*unused*/) const {
    return false;
  }
};

using DirectionTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, DirectionCloud>,
                                        DirectionCloud, 3, std::uint32_t>;

}  // namespace vem
