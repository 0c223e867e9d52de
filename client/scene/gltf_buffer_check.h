// Checks of a glTF or GLB file's buffers that tinygltf 2.7 gets wrong or reports badly, as the
// "what" part of a sentence about the file (empty: nothing found). Sizes in bytes. Internal to
// gltf_loader.cpp.
// - binChunkProblem, before tinygltf reads a GLB: tinygltf checks the BIN chunk's length against
//   the file without the chunk's own 8-byte header, so a chunk that claims up to 8 bytes more than
//   the file holds is read past its end.
// - dataUriProblem, after tinygltf failed with "Failed to decode 'uri'" (its whole message, the
//   URI quoted in full): the first buffer whose byteLength differs from what its base64 data: URI
//   holds. Never on the way to a loaded scene, so the JSON is parsed a second time only then.
#pragma once

#include <string>

namespace vem::scene {

// `bytes`: the whole GLB file.
[[nodiscard]] std::string binChunkProblem(const std::string& bytes);

// `bytes`: the whole file, a GLB when `glb` (its JSON chunk is read), else JSON text.
[[nodiscard]] std::string dataUriProblem(const std::string& bytes, bool glb);

}  // namespace vem::scene
