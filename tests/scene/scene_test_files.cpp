#include "scene_test_files.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/inotify.h>
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
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << contents;
  if (!out) {
    throw std::runtime_error("cannot write " + file.string());
  }
  return file;
}

std::filesystem::path TempDir::link(const std::string& name,
                                    const std::filesystem::path& target) const {
  const auto file = path_ / name;
  std::filesystem::create_directories(file.parent_path());
  std::filesystem::create_symlink(target, file);
  return file;
}

OpenWatch::OpenWatch(const std::filesystem::path& file) : fd_(inotify_init1(IN_NONBLOCK)) {
  if (fd_ < 0 || inotify_add_watch(fd_, file.c_str(), IN_OPEN) < 0) {
    throw std::runtime_error("cannot watch " + file.string());
  }
}

OpenWatch::~OpenWatch() { ::close(fd_); }

bool OpenWatch::opened() const {
  alignas(inotify_event) char events[4096];
  return ::read(fd_, events, sizeof events) > 0;
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

std::vector<unsigned char> GltfTriangle::bufferBytes() const {
  std::vector<unsigned char> bytes;
  appendVec3s(bytes, positions);
  appendVec3s(bytes, normals);
  for (const std::uint16_t index : indices) {
    append(bytes, index);
  }
  while (bytes.size() % 4 != 0) {
    bytes.push_back(0);
  }
  return bytes;
}

std::string GltfTriangle::json() const {
  const std::vector<unsigned char> bytes = bufferBytes();
  // With no normals, accessor 1 (unused) repeats the positions.
  const std::size_t normalOffset = normals.empty() ? 0 : 12 * positions.size();
  const std::size_t indexOffset = 12 * (positions.size() + normals.size());
  const std::size_t indexBytes = 2 * indices.size();
  const std::string uri = bufferUri.empty() ? R"(, "uri": "data:application/octet-stream;base64,)" +
                                                  base64(bytes) + "\""
                          : bufferUri == kNoUri ? std::string()
                                                : R"(, "uri": ")" + bufferUri + "\"";
  const std::string normalAttribute = normals.empty() ? "" : R"(, "NORMAL": 1)";
  const std::uint64_t count = positionCount.value_or(positions.size());
  return fmt::format(
      R"({{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
  "nodes": {nodes},
  "meshes": [{{"name": "tri", "primitives": [{{"attributes": {{"POSITION": 0{normal}}},
    "indices": 2, "mode": {mode}, "material": 0}}]}}],
  "materials": [{{"name": "paint", "pbrMetallicRoughness": {{"baseColorFactor": [{base}, 1.0],
    "metallicFactor": {metallic}, "roughnessFactor": {roughness}}}}}],
  "buffers": [{{"byteLength": {size}{uri}}}],{extra}
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
      fmt::arg("roughness", roughness),
      fmt::arg("size", byteLength < 0 ? static_cast<std::int64_t>(bytes.size()) : byteLength),
      fmt::arg("uri", uri), fmt::arg("extra", extra.empty() ? extra : "\n  " + extra + ","),
      fmt::arg("indexOffset", indexOffset), fmt::arg("indexBytes", indexBytes),
      fmt::arg("count", count), fmt::arg("normalOffset", normalOffset),
      fmt::arg("normals", normals.empty() ? positions.size() : normals.size()),
      fmt::arg("indices", indices.size()));
}

std::string glb(const std::string& json, const std::vector<unsigned char>& bin,
                std::int64_t binLengthChange) {
  std::string text = json;
  while (text.size() % 4 != 0) {
    text += ' ';
  }
  std::vector<unsigned char> out;
  const auto u32 = [&out](std::uint64_t value) { append(out, static_cast<std::uint32_t>(value)); };
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(12 + 8 + text.size() + 8 + bin.size());
  u32(text.size());
  u32(0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  u32(static_cast<std::uint64_t>(static_cast<std::int64_t>(bin.size()) + binLengthChange));
  u32(0x004E4942);  // "BIN"
  out.insert(out.end(), bin.begin(), bin.end());
  return {out.begin(), out.end()};
}

}  // namespace vem::scene::test_files
