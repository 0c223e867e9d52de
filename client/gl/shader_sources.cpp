#include "client/gl/shader_sources.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace vem::gl {

std::string_view shaderSource(std::string_view fileName) {
  for (const EmbeddedShader& shader : embeddedShaders()) {
    if (shader.fileName == fileName) return shader.text;
  }
  std::fprintf(stderr, "vem_gl: no embedded shader named %s\n", std::string(fileName).c_str());
  std::abort();
}

}  // namespace vem::gl
