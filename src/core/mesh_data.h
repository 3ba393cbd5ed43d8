// CPU-side triangle mesh: what the renderer uploads and what the OBJ loader produces.
// Only position and normal per vertex: the scene's shaders need nothing else.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace reflect {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  glm::vec3 centre() const { return (min + max) * 0.5f; }
};

struct IndexRange {
  uint32_t first = 0;  // first index (not triangle)
  uint32_t count = 0;  // indices
};

// Nearby triangles stored contiguously, with their bounds (see mesh_chunks.h).
struct MeshChunk {
  IndexRange range;
  Bounds bounds;
};

struct MeshData {
  std::string name;  // for messages: the file it came from
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangles, counter-clockwise
  Bounds bounds;
  std::vector<MeshChunk> chunks;  // empty until chunkMesh
  // When every vertex lies on one sphere about bounds.centre(): its radius (glass then leaves the
  // object analytically through its far side); 0 for any other shape.
  float sphereRadius = 0.0f;

  size_t triangleCount() const { return indices.size() / 3; }
};

Bounds computeBounds(const std::vector<Vertex>& vertices);

// The radius of the sphere about bounds.centre() that every vertex lies on, within 0.5%, with its
// normal pointing away from the centre; 0 when they do not (or the mesh is empty).
float sphereRadiusOf(const MeshData& mesh);

}  // namespace reflect
