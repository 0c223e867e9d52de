// TextureBuffer: a GL buffer texture (GL 3.1 core) holding an array the fragment shader reads with
// texelFetch: RGBA32F texels (lights) or R32UI texels (region lists and offsets). Re-uploaded
// whole with upload(); never empty on the GPU (an empty array uploads one zero texel).
#pragma once

#include <cstdint>
#include <span>

#include "client/gl/gl_handle.h"

namespace vem::gl {

class TextureBuffer {
 public:
  explicit TextureBuffer(GLenum internalFormat);  // GL_RGBA32F or GL_R32UI
  void upload(std::span<const float> values);          // RGBA32F: 4 floats a texel
  void upload(std::span<const std::uint32_t> values);  // R32UI: one a texel
  void bind(GLenum unit) const;

 private:
  void uploadBytes(const void* data, std::size_t bytes, std::size_t texelBytes);
  GLenum format_;
  GlBuffer buffer_;
  GlTexture texture_;
  std::size_t capacityBytes_ = 0;
};

}  // namespace vem::gl
