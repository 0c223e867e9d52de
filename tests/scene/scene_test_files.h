// Test helpers for tests/scene: a temporary directory removed at the end of the test, a watch that
// tells whether a file was opened, and the small OBJ / glTF files the loader tests write (a unit
// cube centred at the origin, a one-triangle glTF with an embedded base64 buffer or another
// buffer URI, and a GLB made of a JSON text and a BIN chunk).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
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
  // Writes `contents` to path() / name (making its folders) and returns that path.
  std::filesystem::path write(const std::string& name, const std::string& contents) const;
  // Makes path() / name (and its folders) a symbolic link to `target`; returns its path.
  std::filesystem::path link(const std::string& name, const std::filesystem::path& target) const;

 private:
  std::filesystem::path path_;
};

// Tells whether anything opened a file (inotify IN_OPEN) since the watch was made. The kernel
// queues the event before open() returns, so opened() needs no waiting.
class OpenWatch {
 public:
  explicit OpenWatch(const std::filesystem::path& file);
  ~OpenWatch();
  OpenWatch(const OpenWatch&) = delete;
  OpenWatch& operator=(const OpenWatch&) = delete;

  [[nodiscard]] bool opened() const;

 private:
  int fd_ = -1;
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
  std::optional<std::uint64_t> positionCount;  // the POSITION accessor's count; positions.size()
  // The buffer's uri: empty, the bytes as a data: URI; kNoUri, none (a GLB's BIN chunk); else this.
  std::string bufferUri;
  std::int64_t byteLength = -1;  // the buffer's byteLength; -1: bufferBytes().size()
  std::string extra;             // more top-level members, e.g. R"("images": [...])"

  double metallic = 0.0;
  double roughness = 1.0;
  std::vector<double> baseColour{0.5, 0.6, 0.7};

  [[nodiscard]] std::string json() const;
  // Positions, normals, indices, padded to 4 bytes: the buffer json() describes.
  [[nodiscard]] std::vector<unsigned char> bufferBytes() const;

  static constexpr const char* kNoUri = "-";
};

// A binary glTF: header, `json` as the JSON chunk (padded with spaces), `bin` as the BIN chunk,
// whose length field is bin.size() + binLengthChange (to break it).
[[nodiscard]] std::string glb(const std::string& json, const std::vector<unsigned char>& bin,
                              std::int64_t binLengthChange = 0);

}  // namespace vem::scene::test_files
