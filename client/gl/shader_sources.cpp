#include "client/gl/shader_sources.h"

#include "util/contract.h"

namespace vem::gl {

std::string_view shaderSource(std::string_view fileName) {
  for (const EmbeddedShader& shader : embeddedShaders()) {
    if (shader.fileName == fileName) return shader.text;
  }
  VEM_UNREACHABLE("shaderSource: every name asked for is one of shaders/*.glsl");
}

}  // namespace vem::gl
