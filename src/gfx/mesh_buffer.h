// One mesh on the GPU: a vertex array with interleaved position + normal and 32-bit indices; and
// the set of every mesh's levels that all of a demo's renderers draw from (one GPU copy each).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh_data.h"
#include "gfx/gl_handle.h"

namespace reflect {

// Mesh buffers alive right now and the bytes they hold (vertices and indices as uploaded), for
// tests that check a mesh is on the GPU once, whichever renderers draw it.
inline long gLiveMeshBuffers = 0;
inline size_t gLiveMeshBufferBytes = 0;

// Counts one buffer's bytes in the totals above while it lives; a move hands the count over.
class MeshBufferTally {
 public:
  explicit MeshBufferTally(size_t bytes) : bytes_(bytes), live_(true) {
    ++gLiveMeshBuffers;
    gLiveMeshBufferBytes += bytes_;
  }
  ~MeshBufferTally() { release(); }
  MeshBufferTally(const MeshBufferTally&) = delete;
  MeshBufferTally& operator=(const MeshBufferTally&) = delete;
  MeshBufferTally(MeshBufferTally&& other) noexcept
      : bytes_(other.bytes_), live_(std::exchange(other.live_, false)) {}
  MeshBufferTally& operator=(MeshBufferTally&& other) noexcept {
    if (this != &other) {
      release();
      bytes_ = other.bytes_;
      live_ = std::exchange(other.live_, false);
    }
    return *this;
  }
  void release() {
    if (!live_) return;
    --gLiveMeshBuffers;
    gLiveMeshBufferBytes -= bytes_;
    live_ = false;
  }

 private:
  size_t bytes_ = 0;
  bool live_ = false;
};

class MeshBuffer {
 public:
  explicit MeshBuffer(const MeshData& mesh);

  void draw() const;
  // Only these index ranges (the visible chunks); empty draws everything.
  void draw(const std::vector<IndexRange>& ranges) const;
  // ... with `perVertex` (vec3s, one a vertex) as attribute kAttribAmbientParallax for this draw.
  void draw(const std::vector<IndexRange>& ranges, GLuint perVertex) const;
  GLsizei vertexCount() const { return vertexCount_; }
  GLuint vertexArray() const { return vao_.id(); }
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
  // A closed, outward-wound solid (core/mesh_closure.h): its back faces never show from outside.
  bool closedOutward() const { return closedOutward_; }

 private:
  MeshBufferTally tally_;
  VertexArrayHandle vao_;
  BufferHandle vertices_;
  BufferHandle indices_;
  GLsizei indexCount_ = 0;
  GLsizei vertexCount_ = 0;
  Bounds bounds_;
  float sphereRadius_ = 0.0f;
  float boundingRadius_ = 0.0f;
  bool flat_ = false;
  glm::vec3 flatPoint_{0.0f};
  glm::vec3 flatNormal_{0.0f};
  bool closedOutward_ = false;
};

// Every mesh's levels of detail on the GPU, by the name the scene knows the mesh by. One owner
// uploads; every renderer of the same context draws from it (SceneRenderer::setMeshes).
class MeshBuffers {
 public:
  // Uploads (or replaces) level `lod` of mesh `name` (0 = full detail; setting level 0 drops the
  // coarser levels, which belonged to the old mesh). Levels arrive in order, 0 first; one out of
  // order is ignored.
  void set(const std::string& name, int lod, const MeshData& mesh);
  // Level `lod` of mesh `name`, or its coarsest when it has fewer levels; null without the mesh.
  const MeshBuffer* find(const std::string& name, int lod) const;
  // Changes whenever level 0 of mesh `name` is replaced (0: no such mesh), so that what a
  // renderer derived from the old mesh (a glass interior map) can be told stale.
  uint64_t serial(const std::string& name) const;
  // Levels held, over every mesh.
  size_t levelCount() const;

 private:
  struct Levels {
    std::vector<MeshBuffer> buffers;
    uint64_t serial = 0;
  };
  std::map<std::string, Levels> meshes_;
  uint64_t nextSerial_ = 1;
};

}  // namespace reflect
