#include "client/gl/gl_program.h"

#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "client/gl/shader_sources.h"

namespace vem::gl {
namespace {

constexpr std::string_view kVersionLine = "#version 330 core\n";

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::string log(std::size_t(std::max(length, 1)), '\0');
  if (isProgram) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::string fileList(std::initializer_list<std::string_view> files) {
  std::string out;
  int number = 0;
  for (std::string_view file : files) {
    out += (number == 0 ? "" : ", ") + std::to_string(number) + ": " + std::string(file);
    ++number;
  }
  return out;
}

// A compiled shader (deleted on scope exit: the program keeps it alive once attached).
struct ShaderObject {
  GLuint id = 0;
  ~ShaderObject() {
    if (id != 0) glDeleteShader(id);
  }
};

std::expected<void, std::string> compileInto(ShaderObject& shader, GLenum stage,
                                             std::string_view label,
                                             std::initializer_list<std::string_view> files) {
  std::vector<std::string> pieces{std::string(kVersionLine)};
  int number = 0;
  for (std::string_view file : files) {
    pieces.push_back("#line 1 " + std::to_string(number++) + "\n" +
                     std::string(shaderSource(file)) + "\n");
  }
  std::vector<const GLchar*> pointers;
  for (const std::string& piece : pieces) pointers.push_back(piece.c_str());
  shader.id = glCreateShader(stage);
  glShaderSource(shader.id, GLsizei(pointers.size()), pointers.data(), nullptr);
  glCompileShader(shader.id);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    return std::unexpected("shader program " + std::string(label) + ": the " +
                           (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                           " stage (files " + fileList(files) + ") does not compile: " +
                           infoLog(shader.id, false));
  }
  return {};
}

}  // namespace

std::expected<GlProgram, std::string> GlProgram::build(
    std::string_view label, std::initializer_list<std::string_view> vertexFiles,
    std::initializer_list<std::string_view> fragmentFiles) {
  ShaderObject vertex;
  ShaderObject fragment;
  if (auto ok = compileInto(vertex, GL_VERTEX_SHADER, label, vertexFiles); !ok) {
    return std::unexpected(ok.error());
  }
  if (auto ok = compileInto(fragment, GL_FRAGMENT_SHADER, label, fragmentFiles); !ok) {
    return std::unexpected(ok.error());
  }
  GlProgramHandle program = GlProgramHandle::create();
  glAttachShader(program.id(), vertex.id);
  glAttachShader(program.id(), fragment.id);
  glBindAttribLocation(program.id(), 0, "aPosition");
  glBindAttribLocation(program.id(), 1, "aNormal");
  glBindFragDataLocation(program.id(), 0, "fragColor");
  glLinkProgram(program.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    return std::unexpected("shader program " + std::string(label) + " does not link: " +
                           infoLog(program.id(), true));
  }
  glDetachShader(program.id(), vertex.id);
  glDetachShader(program.id(), fragment.id);
  return GlProgram(std::move(program));
}

GLint GlProgram::location(const char* name) const {
  return glGetUniformLocation(program_.id(), name);
}

void GlProgram::set(const char* name, int value) const { glUniform1i(location(name), value); }
void GlProgram::set(const char* name, float value) const { glUniform1f(location(name), value); }
void GlProgram::set(const char* name, std::span<const float> values) const {
  glUniform1fv(location(name), GLsizei(values.size()), values.data());
}
void GlProgram::set(const char* name, glm::vec2 value) const {
  glUniform2fv(location(name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, glm::ivec2 value) const {
  glUniform2iv(location(name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, glm::vec3 value) const {
  glUniform3fv(location(name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace vem::gl
