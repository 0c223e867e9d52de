// Test helpers for tests/scene: a temporary directory removed at the end of the test, and the
// small OBJ / glTF files the loader tests write into it (a unit cube centred at the origin, a
// one-triangle glTF with an embedded base64 buffer).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace vem::scene::test_files {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // Writes `contents` to path() / name and returns that path.
  std::filesystem::path write(const std::string& name, const std::string& contents) const;

 private:
  std::filesystem::path path_;
};

// A cube from -0.5 to 0.5: 8 vertices, 6 counter-clockwise quads; with `faceNormals`, 6 `vn`
// lines and faces written v//vn.
[[nodiscard]] std::string cubeObj(bool faceNormals);

// The first half of `text` (a truncated file).
[[nodiscard]] std::string firstHalf(const std::string& text);

// One glTF triangle: positions (0,0,0), (1,0,0), (0,1,0) (or `positions`), normal +Z, uint16
// indices 0 1 2, one material; everything adjustable to break it.
struct GltfTriangle {
  std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<glm::vec3> normals{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};  // empty: no NORMAL
  std::vector<std::uint16_t> indices{0, 1, 2};
  std::string nodes = R"([{"mesh": 0}])";  // JSON array; node 0 is the scene's root
  int mode = 4;
  int positionCount = -1;  // the POSITION accessor's count; -1: positions.size()
  double metallic = 0.0;
  double roughness = 1.0;
  std::vector<double> baseColour{0.5, 0.6, 0.7};

  [[nodiscard]] std::string json() const;
};

}  // namespace vem::scene::test_files
