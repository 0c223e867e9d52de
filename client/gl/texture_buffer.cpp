#include "client/gl/texture_buffer.h"

#include <array>

namespace vem::gl {

TextureBuffer::TextureBuffer(GLenum internalFormat)
    : format_(internalFormat), buffer_(GlBuffer::create()), texture_(GlTexture::create()) {}

void TextureBuffer::upload(std::span<const float> values) {
  uploadBytes(values.data(), values.size_bytes(), 4 * sizeof(float));
}

void TextureBuffer::upload(std::span<const std::uint32_t> values) {
  uploadBytes(values.data(), values.size_bytes(), sizeof(std::uint32_t));
}

void TextureBuffer::uploadBytes(const void* data, std::size_t bytes, std::size_t texelBytes) {
  static constexpr std::array<std::uint32_t, 4> kZeroTexel{};
  if (bytes == 0) {
    data = kZeroTexel.data();
    bytes = texelBytes;
  }
  glBindBuffer(GL_TEXTURE_BUFFER, buffer_.id());
  if (bytes > capacityBytes_) {
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_STREAM_DRAW);
    capacityBytes_ = bytes;
    glBindTexture(GL_TEXTURE_BUFFER, texture_.id());
    glTexBuffer(GL_TEXTURE_BUFFER, format_, buffer_.id());
  } else {
    glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(bytes), data);
  }
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void TextureBuffer::bind(GLenum unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, texture_.id());
}

}  // namespace vem::gl
