#include "client/scene/gltf_accessor.h"

#include <fmt/format.h>
#include <tiny_gltf.h>
#include <cstring>

namespace vem::scene {
namespace {

// An accessor's checked location: `count` elements of `elementBytes`, `stride` apart.
struct AccessorBytes {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int componentType = 0;
};

template <typename T>
bool outside(int index, const std::vector<T>& items) {
  return index < 0 || static_cast<std::size_t>(index) >= items.size();
}

std::string checkView(const tinygltf::Model& model, int viewIndex) {
  if (outside(viewIndex, model.bufferViews)) {
    return fmt::format("buffer view {} does not exist ({} buffer views)", viewIndex,
                       model.bufferViews.size());
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
  if (outside(view.buffer, model.buffers)) {
    return fmt::format("buffer view {} refers to buffer {}, which does not exist", viewIndex,
                       view.buffer);
  }
  const std::size_t bufferBytes = model.buffers[static_cast<std::size_t>(view.buffer)].data.size();
  if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset) {
    return fmt::format("buffer view {} ends at byte {}, past the end of buffer {} ({} bytes)",
                       viewIndex, view.byteOffset + view.byteLength, view.buffer, bufferBytes);
  }
  return {};
}

std::expected<AccessorBytes, std::string> locate(const tinygltf::Model& model, int index,
                                                 int expectedType) {
  if (outside(index, model.accessors)) {
    return std::unexpected(
        fmt::format("accessor {} does not exist ({} accessors)", index, model.accessors.size()));
  }
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) {
    return std::unexpected(fmt::format("accessor {} is sparse, which is not supported", index));
  }
  if (a.type != expectedType) {
    return std::unexpected(
        fmt::format("accessor {} has {} components per element, where {} were "
                    "expected",
                    index, tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)),
                    tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(expectedType))));
  }
  if (auto problem = checkView(model, a.bufferView); !problem.empty()) {
    return std::unexpected(fmt::format("accessor {}: {}", index, problem));
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const int elementBytes =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType)) *
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  const int stride = a.ByteStride(view);
  if (elementBytes <= 0 || stride < elementBytes) {
    return std::unexpected(
        fmt::format("accessor {} has component type {} and byte stride {}, "
                    "which do not describe its elements",
                    index, a.componentType, stride));
  }
  const auto bytes = static_cast<std::size_t>(elementBytes);
  const auto step = static_cast<std::size_t>(stride);
  const bool fits =
      a.count == 0 || (a.byteOffset <= view.byteLength && bytes <= view.byteLength - a.byteOffset &&
                       (a.count - 1) <= (view.byteLength - a.byteOffset - bytes) / step);
  if (!fits) {
    return std::unexpected(
        fmt::format("accessor {} ({} elements of {} bytes from byte {}) runs "
                    "past the end of buffer view {} ({} bytes)",
                    index, a.count, bytes, a.byteOffset, a.bufferView, view.byteLength));
  }
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  return AccessorBytes{data.data() + view.byteOffset + a.byteOffset, step, a.count,
                       a.componentType};
}

template <typename T>
T load(const unsigned char* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));  // glTF data need not be aligned for T
  return value;
}

std::int64_t indexAt(const unsigned char* at, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return load<std::int8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return load<std::int16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_INT: return load<std::int32_t>(at);
    default: return load<std::uint32_t>(at);
  }
}

bool integerType(int componentType) {
  return componentType >= TINYGLTF_COMPONENT_TYPE_BYTE &&
         componentType <= TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

}  // namespace

std::expected<std::vector<glm::vec3>, std::string> readVec3Accessor(const tinygltf::Model& model,
                                                                    int accessor) {
  const auto located = locate(model, accessor, TINYGLTF_TYPE_VEC3);
  if (!located) {
    return std::unexpected(located.error());
  }
  if (located->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    return std::unexpected(
        fmt::format("accessor {} has component type {}, where 5126 (float) was "
                    "expected",
                    accessor, located->componentType));
  }
  std::vector<glm::vec3> out(located->count);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const unsigned char* at = located->first + i * located->stride;
    out[i] = {load<float>(at), load<float>(at + 4), load<float>(at + 8)};
  }
  return out;
}

std::expected<std::vector<std::uint32_t>, std::string> readIndexAccessor(
    const tinygltf::Model& model, int accessor) {
  const auto located = locate(model, accessor, TINYGLTF_TYPE_SCALAR);
  if (!located) {
    return std::unexpected(located.error());
  }
  if (!integerType(located->componentType)) {
    return std::unexpected(
        fmt::format("index accessor {} has component type {}, where an integer "
                    "type (5120 to 5125) was expected",
                    accessor, located->componentType));
  }
  std::vector<std::uint32_t> out(located->count);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::int64_t value =
        indexAt(located->first + i * located->stride, located->componentType);
    if (value < 0) {
      return std::unexpected(
          fmt::format("index {} of accessor {} is negative ({})", i, accessor, value));
    }
    out[i] = static_cast<std::uint32_t>(value);
  }
  return out;
}

}  // namespace vem::scene
