#include "gfx/mesh_buffer.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "gfx/shader_program.h"

namespace reflect {

MeshBuffer::MeshBuffer(const MeshData& mesh)
    : vao_(genVertexArray()),
      vertices_(genBuffer()),
      indices_(genBuffer()),
      indexCount_(static_cast<GLsizei>(mesh.indices.size())),
      bounds_(mesh.bounds),
      sphereRadius_(mesh.sphereRadius) {
  for (const Vertex& v : mesh.vertices) {
    boundingRadius_ = std::max(boundingRadius_, glm::length(v.position - bounds_.centre()));
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(kAttribPosition);
  glVertexAttribPointer(kAttribPosition, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(kAttribNormal);
  glVertexAttribPointer(kAttribNormal, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, normal)));
  glBindVertexArray(0);
  checkGlError(("upload mesh " + mesh.name).c_str());
}

void MeshBuffer::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void MeshBuffer::draw(const std::vector<IndexRange>& ranges) const {
  if (ranges.empty()) return draw();
  glBindVertexArray(vao_.id());
  for (const IndexRange& r : ranges) {
    glDrawElements(
        GL_TRIANGLES, static_cast<GLsizei>(r.count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(static_cast<uintptr_t>(r.first) * sizeof(uint32_t)));
  }
}

void MeshBuffer::abandon() {
  vao_.abandon();
  vertices_.abandon();
  indices_.abandon();
}

}  // namespace reflect
