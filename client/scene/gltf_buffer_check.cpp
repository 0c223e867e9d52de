#include "client/scene/gltf_buffer_check.h"

#include <fmt/format.h>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string_view>

namespace vem::scene {
namespace {

constexpr std::string_view kBase64 = ";base64,";

std::uint32_t littleEndian32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    value |= std::uint32_t{static_cast<unsigned char>(bytes[at + k])} << (8 * k);
  }
  return value;
}

// The JSON text of a .gltf file, or the JSON chunk of a GLB file (empty when it has none).
std::string_view jsonTextOf(const std::string& bytes, bool glb) {
  constexpr std::size_t kJsonAt = 20;
  if (!glb) {
    return bytes;
  }
  if (bytes.size() < kJsonAt) {
    return {};
  }
  return std::string_view(bytes).substr(kJsonAt, littleEndian32(bytes, 12));
}

}  // namespace

std::string binChunkProblem(const std::string& bytes) {
  constexpr std::size_t kHeaderBytes = 12;      // magic, version, length
  constexpr std::size_t kChunkHeaderBytes = 8;  // length, type
  if (bytes.size() < kHeaderBytes + kChunkHeaderBytes) {
    return {};
  }
  const std::uint64_t end = std::min<std::uint64_t>(littleEndian32(bytes, 8), bytes.size());
  const std::uint64_t binChunk =
      kHeaderBytes + kChunkHeaderBytes + std::uint64_t{littleEndian32(bytes, kHeaderBytes)};
  if (binChunk + kChunkHeaderBytes > end) {
    return {};  // no BIN chunk
  }
  const std::uint64_t binBytes = littleEndian32(bytes, static_cast<std::size_t>(binChunk));
  if (binChunk + kChunkHeaderBytes + binBytes <= end) {
    return {};
  }
  return fmt::format(
      "its BIN chunk claims {} bytes from byte {}, past the end of the file's {} "
      "bytes, where the chunk was expected to fit",
      binBytes, binChunk + kChunkHeaderBytes, end);
}

std::string dataUriProblem(const std::string& bytes, bool glb) {
  const auto document =
      nlohmann::json::parse(jsonTextOf(bytes, glb), nullptr, /*allow_exceptions=*/false);
  if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) {
    return {};
  }
  const auto& buffers = document["buffers"];
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const auto& buffer = buffers[i];
    if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string() ||
        !buffer.contains("byteLength") || !buffer["byteLength"].is_number_unsigned()) {
      continue;
    }
    const auto& uri = buffer["uri"].get_ref<const std::string&>();
    const std::size_t base64At = uri.find(kBase64);
    if (!uri.starts_with("data:") || base64At == std::string::npos) {
      continue;
    }
    const std::string_view payload = std::string_view(uri).substr(base64At + kBase64.size());
    const std::size_t padding = payload.ends_with("==") ? 2 : payload.ends_with('=') ? 1 : 0;
    const std::size_t held = payload.size() / 4 * 3 - std::min(padding, payload.size() / 4 * 3);
    if (const auto claimed = buffer["byteLength"].get<std::uint64_t>(); claimed != held) {
      return fmt::format(
          "buffer {} has byteLength {}, where the {} bytes its data: URI holds "
          "were expected",
          i, claimed, held);
    }
  }
  return {};
}

}  // namespace vem::scene
