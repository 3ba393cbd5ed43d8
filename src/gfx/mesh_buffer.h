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
  void abandon();

 private:
  VertexArrayHandle vao_;
  BufferHandle vertices_;
  BufferHandle indices_;
  GLsizei indexCount_ = 0;
  Bounds bounds_;
  float sphereRadius_ = 0.0f;
  float boundingRadius_ = 0.0f;
};

}  // namespace reflect
