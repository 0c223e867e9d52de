// Smooth vertex normals for a triangle mesh, as the loaders compute them when a file has none.
//
// Each vertex gets the normalised sum of the unnormalised face normals cross(b - a, c - a) of
// the triangles using it, i.e. the face normals weighted by twice the triangle areas; faces are
// counter-clockwise seen from their front (scene/scene.h), so the normals point to the front.
// Unitless: the result is a set of unit vectors, whatever the scene's length unit.
#pragma once

#include <cstdint>
#include <expected>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace vem::scene {

// One unit normal per position, or the index of the first position used only by triangles of
// zero area (its normal is undefined). Positions no triangle uses get +Y (any unit vector would
// do: they are never drawn).
[[nodiscard]] std::expected<std::vector<glm::vec3>, std::size_t> smoothNormals(
    std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

}  // namespace vem::scene
