// The OBJ parser's vertices (core/obj_stream.h): a vertex is a (position, normal) pair, numbered in
// the order of first use, as tinyobjloader's callers number them. While the file is read a vertex
// is a 12-byte key found again through a chain per position; at the end the keys become the mesh's
// vertices, with the file's normals or, where a vertex has no usable one, the area-weighted normal
// of its position's triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/block_array.h"
#include "core/mesh_data.h"

namespace reflect {

// One face corner, resolved as tinyobjloader resolves it: 0-based position; normal 0-based, or
// -1 for none (absent, or a negative index before the first normal). A positive normal index may
// be past the normals read so far: the file may define it further down.
struct ObjCorner {
  uint32_t position = 0;
  int32_t normal = -1;
};

class ObjVertices {
 public:
  // A position was read: its chain starts empty.
  void addPosition();
  // The vertex of a corner: the one made for the same (position, normal) before, or a new one.
  uint32_t vertexOf(const ObjCorner& corner);

  // Whether a vertex names a normal past the file's last, `normalCount` (a forward reference the
  // file never defined).
  bool anyNormalPast(size_t normalCount) const;
  // Where a positive normal index turned out past the file's last normal, those vertices name no
  // normal: several of them at one position are one vertex, as they would have been had the
  // file's normal count been known when they were read. Renumbers the vertices (still in the
  // order of first use) and rewrites `indices`. The chains are not kept up to date: call it after
  // releaseChains().
  void mergeUndefinedNormals(size_t normalCount, BlockArray<uint32_t>& indices);

  // Frees what finding vertices again needs (the chains and the overflow map).
  void releaseChains();
  // The mesh's vertices, made from `positions` and `normals` (both emptied). Frees the keys too:
  // see obj_vertices.cpp for why the order of what is freed matters.
  std::vector<Vertex> makeVertices(BlockArray<glm::vec3>& positions, BlockArray<glm::vec3>& normals,
                                   const BlockArray<uint32_t>& indices);

  size_t size() const { return keys_.size(); }
  // The bytes held: the keys, the chains and the overflow map.
  size_t heldBytes() const;

 private:
  // A vertex while the file is read: its position and normal (ObjCorner's numbers) and the next
  // vertex of the same position (the chain vertexOf walks). 12 bytes where the Vertex it becomes
  // is 24: makeVertices() makes the vertices, once, in the mesh's own array.
  struct Key {
    uint32_t position = 0;
    int32_t normal = -1;
    uint32_t nextSamePosition = 0;
  };

  BlockArray<Key> keys_;
  BlockArray<uint32_t> firstOfPosition_;             // per position: its chain's first vertex
  std::unordered_map<uint64_t, uint32_t> overflow_;  // (position, normal) past a chain's limit
};

}  // namespace reflect
