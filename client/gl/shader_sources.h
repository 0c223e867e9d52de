// Shader sources: the GLSL files of client/gl/shaders/, embedded in the library at build time
// (client/gl/CMakeLists.txt generates the table), looked up by file name.
#pragma once

#include <span>
#include <string_view>

namespace vem::gl {

struct EmbeddedShader {
  std::string_view fileName;  // e.g. "lighting.frag.glsl"
  std::string_view text;
};

// Every embedded shader (defined in the generated embedded_shaders.cpp).
[[nodiscard]] std::span<const EmbeddedShader> embeddedShaders();
// The text of shaders/<fileName>; aborts when no such file was embedded (a bug, not input).
[[nodiscard]] std::string_view shaderSource(std::string_view fileName);

}  // namespace vem::gl
