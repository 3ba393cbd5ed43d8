// The OBJ parser's polygons (core/obj_stream.h) as triangles, split as tinyobjloader splits them:
// a triangle as it is, a quad along its shorter diagonal, a larger polygon by tinyobjloader's ear
// clipping (which may give up on a polygon it cannot clip and emit fewer triangles). Each corner
// becomes a vertex number through ObjVertices as its triangle is emitted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/block_array.h"
#include "core/obj_vertices.h"

namespace reflect {

class ObjFaceTriangulator {
 public:
  // Appends `face`'s triangles to `indices`, three vertex numbers each.
  void triangulate(const std::vector<ObjCorner>& face, const BlockArray<glm::vec3>& positions,
                   ObjVertices& vertices, BlockArray<uint32_t>& indices);
  // The ear clipper's working copy of a polygon: its bytes, and freeing them.
  size_t heldBytes() const { return remaining_.capacity() * sizeof(ObjCorner); }
  void release() { remaining_ = std::vector<ObjCorner>(); }

 private:
  void clipEars(const std::vector<ObjCorner>& face, const BlockArray<glm::vec3>& positions,
                ObjVertices& vertices, BlockArray<uint32_t>& indices);

  std::vector<ObjCorner> remaining_;  // the corners not yet cut off, kept between faces
};

}  // namespace reflect
