// One mesh on the GPU: a vertex array with interleaved position + normal and 32-bit indices.
#pragma once

#include <vector>

#include "core/mesh_data.h"
#include "gfx/gl_handle.h"

namespace reflect {

class MeshBuffer {
 public:
  explicit MeshBuffer(const MeshData& mesh);

  void draw() const;
  // Only these index ranges (the visible chunks); empty draws everything.
  void draw(const std::vector<IndexRange>& ranges) const;
  GLsizei indexCount() const { return indexCount_; }
  size_t triangleCount() const { return static_cast<size_t>(indexCount_) / 3; }
  const Bounds& bounds() const { return bounds_; }
  float sphereRadius() const { return sphereRadius_; }
  // The farthest vertex from the bounds' centre (a glass interior map's reach).
  float boundingRadius() const { return boundingRadius_; }
  // When every vertex lies in one plane and carries that plane's normal (a ground quad): true,
  // with a point of it and the normal, in the mesh's space. Such a mesh faces one way from any
  // point, so a capture pass that keeps only surfaces facing away from the probe can skip it.
  bool flat() const { return flat_; }
  const glm::vec3& flatPoint() const { return flatPoint_; }
  const glm::vec3& flatNormal() const { return flatNormal_; }
  void abandon();

 private:
  VertexArrayHandle vao_;
  BufferHandle vertices_;
  BufferHandle indices_;
  GLsizei indexCount_ = 0;
  Bounds bounds_;
  float sphereRadius_ = 0.0f;
  float boundingRadius_ = 0.0f;
  bool flat_ = false;
  glm::vec3 flatPoint_{0.0f};
  glm::vec3 flatNormal_{0.0f};
};

}  // namespace reflect
