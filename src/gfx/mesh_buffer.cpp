#include "gfx/mesh_buffer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/mesh_closure.h"
#include "gfx/shader_program.h"

namespace reflect {

MeshBuffer::MeshBuffer(const MeshData& mesh)
    : tally_(mesh.vertices.size() * sizeof(Vertex) + mesh.indices.size() * sizeof(uint32_t)),
      vao_(genVertexArray()),
      vertices_(genBuffer()),
      indices_(genBuffer()),
      indexCount_(static_cast<GLsizei>(mesh.indices.size())),
      vertexCount_(static_cast<GLsizei>(mesh.vertices.size())),
      bounds_(mesh.bounds),
      sphereRadius_(mesh.sphereRadius),
      closedOutward_(isClosedOutward(mesh)) {
  for (const Vertex& v : mesh.vertices) {
    boundingRadius_ = std::max(boundingRadius_, glm::length(v.position - bounds_.centre()));
  }
  if (!mesh.vertices.empty() && glm::length(mesh.vertices[0].normal) > 0.0f) {
    flatPoint_ = mesh.vertices[0].position;
    flatNormal_ = glm::normalize(mesh.vertices[0].normal);
    // Planar within a millionth of the mesh's size, one normal within about 0.1 degree.
    const float tolerance = 1e-6f * std::max(boundingRadius_, 1e-20f);
    flat_ = std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [&](const Vertex& v) {
      return std::abs(glm::dot(v.position - flatPoint_, flatNormal_)) <= tolerance &&
             glm::dot(v.normal, flatNormal_) >= 0.999999f * glm::length(v.normal);
    });
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

void MeshBuffer::draw(const std::vector<IndexRange>& ranges, GLuint perVertex) const {
  if (perVertex == 0) return draw(ranges);
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, perVertex);
  glVertexAttribPointer(kAttribAmbientParallax, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(kAttribAmbientParallax);
  draw(ranges);
  // Off again: the mesh's other programs (and this one without a buffer) read its constant 0.
  glDisableVertexAttribArray(kAttribAmbientParallax);
}

void MeshBuffers::set(const std::string& name, int lod, const MeshData& mesh) {
  Levels& levels = meshes_[name];
  if (lod == 0) {
    levels.buffers.clear();
    levels.serial = nextSerial_++;
  }
  if (lod != static_cast<int>(levels.buffers.size())) return;
  levels.buffers.emplace_back(mesh);
}

const MeshBuffer* MeshBuffers::find(const std::string& name, int lod) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end() || it->second.buffers.empty()) return nullptr;
  const std::vector<MeshBuffer>& buffers = it->second.buffers;
  const size_t level = std::min(static_cast<size_t>(std::max(lod, 0)), buffers.size() - 1);
  return &buffers[level];
}

uint64_t MeshBuffers::serial(const std::string& name) const {
  auto it = meshes_.find(name);
  return it == meshes_.end() ? 0 : it->second.serial;
}

size_t MeshBuffers::levelCount() const {
  size_t count = 0;
  for (const auto& [name, levels] : meshes_) count += levels.buffers.size();
  return count;
}

}  // namespace reflect
