// GlProgram: a linked GLSL program built from embedded shader files (shader_sources.h). Each stage
// is "#version 330 core" followed by its files in order (shared helpers first), each preceded by
// a #line directive so the driver's log names lines per file (file number = position in the list).
//
// Compile and link failures are values: the program's label, the stage, the file list and the
// driver's info log.
#pragma once

#include <expected>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/gl/gl_handle.h"

namespace vem::gl {

class GlProgram {
 public:
  [[nodiscard]] static std::expected<GlProgram, std::string> build(
      std::string_view label, std::initializer_list<std::string_view> vertexFiles,
      std::initializer_list<std::string_view> fragmentFiles);

  void use() const { glUseProgram(program_.id()); }
  [[nodiscard]] GLuint id() const { return program_.id(); }
  // Uniform setters on the program in use (a missing uniform, location -1, is ignored as GL does).
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, std::span<const float> values) const;  // a float[] uniform
  void set(const char* name, glm::vec2 value) const;
  void set(const char* name, glm::ivec2 value) const;
  void set(const char* name, glm::vec3 value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  explicit GlProgram(GlProgramHandle program) : program_(std::move(program)) {}
  [[nodiscard]] GLint location(const char* name) const;
  GlProgramHandle program_;
};

}  // namespace vem::gl
