#include "client/gl/gl_mesh.h"

#include <vector>

namespace vem::gl {

GlMesh::GlMesh(const scene::Mesh& mesh)
    : vertexArray_(GlVertexArray::create()),
      vertices_(GlBuffer::create()),
      indices_(GlBuffer::create()),
      indexCount_(GLsizei(mesh.indices.size())),
      material_(mesh.material) {
  std::vector<float> interleaved;
  interleaved.reserve(mesh.positions.size() * 6);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int c = 0; c < 3; ++c) interleaved.push_back(mesh.positions[i][c]);
    for (int c = 0; c < 3; ++c) interleaved.push_back(mesh.normals[i][c]);
  }
  glBindVertexArray(vertexArray_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  const auto stride = GLsizei(6 * sizeof(float));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glBindVertexArray(0);
}

void GlMesh::draw() const {
  glBindVertexArray(vertexArray_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace vem::gl
