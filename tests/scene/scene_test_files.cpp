#include "scene_test_files.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace vem::scene::test_files {
namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      group = (group << 8U) | (k < n ? bytes[i + k] : 0U);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 63U] : '=';
    }
  }
  return out;
}

template <typename T>
void append(std::vector<unsigned char>& bytes, const T& value) {
  const auto at = bytes.size();
  bytes.resize(at + sizeof(T));
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

void appendVec3s(std::vector<unsigned char>& bytes, const std::vector<glm::vec3>& values) {
  for (const glm::vec3& v : values) {
    append(bytes, v.x);
    append(bytes, v.y);
    append(bytes, v.z);
  }
}

}  // namespace

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          fmt::format("vem_scene_test_{}_{}", ::getpid(), counter++);
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path TempDir::write(const std::string& name, const std::string& contents) const {
  const auto file = path_ / name;
  std::ofstream out(file, std::ios::binary);
  out << contents;
  if (!out) {
    throw std::runtime_error("cannot write " + file.string());
  }
  return file;
}

std::string cubeObj(bool faceNormals) {
  std::string obj = "# unit cube\n";
  for (int i = 0; i < 8; ++i) {  // vertex i: x from bit 0, y from bit 1, z from bit 2
    obj += fmt::format("v {} {} {}\n", (i & 1) != 0 ? 0.5 : -0.5, (i & 2) != 0 ? 0.5 : -0.5,
                       (i & 4) != 0 ? 0.5 : -0.5);
  }
  // Counter-clockwise seen from outside (1-based), with each face's outward normal.
  const char* faces[6][2] = {{"1 3 4 2", "0 0 -1"}, {"5 6 8 7", "0 0 1"},  {"1 2 6 5", "0 -1 0"},
                             {"3 7 8 4", "0 1 0"},  {"1 5 7 3", "-1 0 0"}, {"2 4 8 6", "1 0 0"}};
  for (const auto& face : faces) {
    obj += faceNormals ? fmt::format("vn {}\n", face[1]) : "";
  }
  for (int f = 0; f < 6; ++f) {
    int a = 0, b = 0, c = 0, d = 0;
    std::sscanf(faces[f][0], "%d %d %d %d", &a, &b, &c, &d);
    obj += faceNormals ? fmt::format("f {0}//{4} {1}//{4} {2}//{4} {3}//{4}\n", a, b, c, d, f + 1)
                       : fmt::format("f {} {} {} {}\n", a, b, c, d);
  }
  return obj;
}

std::string firstHalf(const std::string& text) { return text.substr(0, text.size() / 2); }

std::string GltfTriangle::json() const {
  std::vector<unsigned char> bytes;
  appendVec3s(bytes, positions);
  // With no normals, accessor 1 (unused) repeats the positions.
  const std::size_t normalOffset = normals.empty() ? 0 : bytes.size();
  appendVec3s(bytes, normals);
  const std::size_t indexOffset = bytes.size();
  for (const std::uint16_t index : indices) {
    append(bytes, index);
  }
  const std::size_t indexBytes = bytes.size() - indexOffset;
  while (bytes.size() % 4 != 0) {
    bytes.push_back(0);
  }
  const std::string normalAttribute = normals.empty() ? "" : R"(, "NORMAL": 1)";
  const int count = positionCount < 0 ? static_cast<int>(positions.size()) : positionCount;
  return fmt::format(
      R"({{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
  "nodes": {nodes},
  "meshes": [{{"name": "tri", "primitives": [{{"attributes": {{"POSITION": 0{normal}}},
    "indices": 2, "mode": {mode}, "material": 0}}]}}],
  "materials": [{{"name": "paint", "pbrMetallicRoughness": {{"baseColorFactor": [{base}, 1.0],
    "metallicFactor": {metallic}, "roughnessFactor": {roughness}}}}}],
  "buffers": [{{"byteLength": {size}, "uri": "data:application/octet-stream;base64,{data}"}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": {indexOffset}}},
                  {{"buffer": 0, "byteOffset": {indexOffset}, "byteLength": {indexBytes}}}],
  "accessors": [
    {{"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": {count}, "type": "VEC3"}},
    {{"bufferView": 0, "byteOffset": {normalOffset}, "componentType": 5126, "count": {normals},
      "type": "VEC3"}},
    {{"bufferView": 1, "componentType": 5123, "count": {indices}, "type": "SCALAR"}}]}}
)",
      fmt::arg("nodes", nodes), fmt::arg("normal", normalAttribute), fmt::arg("mode", mode),
      fmt::arg("base", fmt::join(baseColour, ", ")), fmt::arg("metallic", metallic),
      fmt::arg("roughness", roughness), fmt::arg("size", bytes.size()),
      fmt::arg("data", base64(bytes)), fmt::arg("indexOffset", indexOffset),
      fmt::arg("indexBytes", indexBytes), fmt::arg("count", count),
      fmt::arg("normalOffset", normalOffset),
      fmt::arg("normals", normals.empty() ? positions.size() : normals.size()),
      fmt::arg("indices", indices.size()));
}

}  // namespace vem::scene::test_files
