// GlHandle: RAII ownership of one OpenGL object name (buffer, texture, vertex array, framebuffer,
// renderbuffer, program), move-only, deleted with its GL delete call on destruction.
//
// Conventions: a handle is created and destroyed with the owning context current (the renderer
// lives inside its GlContext's lifetime); id 0 means "no object" and is never deleted.
#pragma once

#include <utility>

#include <epoxy/gl.h>

namespace vem::gl {

template <class Traits>
class GlHandle {
 public:
  GlHandle() = default;
  [[nodiscard]] static GlHandle create() { return GlHandle(Traits::create()); }
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  [[nodiscard]] GLuint id() const { return id_; }
  [[nodiscard]] explicit operator bool() const { return id_ != 0; }

 private:
  explicit GlHandle(GLuint id) : id_(id) {}
  void reset() {
    if (id_ != 0) Traits::destroy(id_);
    id_ = 0;
  }
  GLuint id_ = 0;
};

struct BufferTraits {
  static GLuint create() { GLuint id = 0; glGenBuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct TextureTraits {
  static GLuint create() { GLuint id = 0; glGenTextures(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct VertexArrayTraits {
  static GLuint create() { GLuint id = 0; glGenVertexArrays(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct FramebufferTraits {
  static GLuint create() { GLuint id = 0; glGenFramebuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferTraits {
  static GLuint create() { GLuint id = 0; glGenRenderbuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct ProgramTraits {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint id) { glDeleteProgram(id); }
};

using GlBuffer = GlHandle<BufferTraits>;
using GlTexture = GlHandle<TextureTraits>;
using GlVertexArray = GlHandle<VertexArrayTraits>;
using GlFramebuffer = GlHandle<FramebufferTraits>;
using GlRenderbuffer = GlHandle<RenderbufferTraits>;
using GlProgramHandle = GlHandle<ProgramTraits>;

}  // namespace vem::gl
