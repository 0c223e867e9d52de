// Reading glTF 2.0 accessors (tinygltf's Model) into plain arrays, every index and byte range
// checked first: the accessor, its buffer view and buffer must exist, and the accessor's last
// element must end inside its buffer view, and the view inside its buffer. Internal to
// gltf_loader.cpp (tinygltf is a private dependency of vem_scene). Errors are the "what" part of
// a sentence ("accessor 3 ... past the end of buffer view 1 (96 bytes)"), without the file.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace tinygltf {
class Model;
}

namespace vem::scene {

// A VEC3 FLOAT accessor (POSITION, NORMAL) as vectors, in the file's units.
[[nodiscard]] std::expected<std::vector<glm::vec3>, std::string> readVec3Accessor(
    const tinygltf::Model& model, int accessor);

// A SCALAR accessor of any integer component type (signed or unsigned, 8, 16 or 32 bits) as
// unsigned 32-bit indices; negative values are refused.
[[nodiscard]] std::expected<std::vector<std::uint32_t>, std::string> readIndexAccessor(
    const tinygltf::Model& model, int accessor);

}  // namespace vem::scene
