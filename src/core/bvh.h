// Bounding volume hierarchies for the exact mode (search: exact), which traces every mirror and
// glass pixel's ray against the scene's triangles in the fragment shader
// (shaders/exact_trace.glsl). Neither Debian nor npm packages a BVH library that builds for wasm
// (outside three.js), so this one is written here, and kept small:
//  - buildBvh: a binned SAH build (16 bins per axis) over any boxes (bvh_build.cpp);
//  - MeshBvh: one per mesh, over its triangles in object space, built once when the mesh loads;
//  - SceneBvh: the top level over the placed objects (their world boxes), rebuilt every frame,
//    so an orbiting figure costs no rebuild of its mesh's tree (both in bvh_build.cpp);
//  - intersectScene: the CPU traversal (a stack, nearer child first), the same steps as the
//    shader's (bvh_traverse.cpp);
//  - BvhAtlas (bvh_atlas.cpp) / packScene (bvh_pack.cpp): the float textures the shader reads
//    (WebGL2 has no storage buffers).
// No GL here: core/ is unit-tested, and the Embree reference checks the hits (tests/reference).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh_data.h"
#include "core/scene.h"

namespace reflect {

struct BvhNode {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  uint32_t first = 0;  // interior: the left child (the right one is first + 1); leaf: first item
  uint32_t count = 0;  // items in a leaf; 0 for an interior node
};

struct Bvh {
  std::vector<BvhNode> nodes;   // the root is nodes[0] (none for no items)
  std::vector<uint32_t> order;  // the items in leaf order: a leaf holds order[first, first+count)
  int depth = 0;                // levels, the root's included
};

// The stack the traversals keep (the shader's too); the build never goes deeper.
inline constexpr int kBvhMaxDepth = 32;

// Binned SAH over `boxes` (one per item), leaves of at most `maxLeaf` items (more only where the
// depth limit or identical centroids leave no split).
Bvh buildBvh(const std::vector<Bounds>& boxes, int maxLeaf = 4);

// A mesh's tree, in object space. It keeps no copy of the vertices (a figure of the course's
// weight would hold them twice): it shares the mesh's, and keeps its triangles' corners in leaf
// order, so the mesh's index list may be reordered later (its chunks are) without it.
struct MeshBvh {
  Bvh tree;                              // tree.order: the mesh's triangle index at each slot
  std::shared_ptr<const MeshData> mesh;  // for the vertices
  std::vector<uint32_t> corners;         // 3 vertex indices a slot, leaf order
  size_t triangleCount() const { return tree.order.size(); }
  const Vertex& corner(size_t slot, int k) const {
    return mesh->vertices[corners[slot * 3 + static_cast<size_t>(k)]];
  }
};
MeshBvh buildMeshBvh(std::shared_ptr<const MeshData> mesh);

// Möller-Trumbore: t in (tMin, tMax) and the barycentrics (u at v1, v at v2), or false.
bool intersectTriangle(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& v0,
                       const glm::vec3& v1, const glm::vec3& v2, float tMin, float tMax, float* t,
                       float* u, float* v);

// A placed object: its mesh's tree and where it stands.
struct BvhInstance {
  std::shared_ptr<const MeshBvh> mesh;  // null: not traced (a mesh not loaded)
  glm::mat4 model{1.0f};
  glm::mat4 inverse{1.0f};
};

struct SceneBvh {
  Bvh top;  // over the instances with a mesh (items are instance indices)
  std::vector<BvhInstance> instances;
};
// The top level over `instances` (their meshes' boxes placed by their models).
SceneBvh buildSceneBvh(std::vector<BvhInstance> instances);

struct RayHit {
  float t = std::numeric_limits<float>::infinity();
  int instance = -1;  // -1: nothing met
  int slot = -1;      // the triangle's place in its MeshBvh (leaf order)
  int triangle = -1;  // the mesh's own triangle index
  float u = 0.0f, v = 0.0f;
};

// The nearest hit along origin + t direction (world space, t in (tMin, tMax)); instance `skip`
// is left out, and with `only` >= 0 only that instance is tested. The ray goes into each object's
// space unnormalised, so t is the same parameter everywhere.
RayHit intersectScene(const SceneBvh& scene, const glm::vec3& origin, const glm::vec3& direction,
                      float tMin = 0.0f, float tMax = std::numeric_limits<float>::infinity(),
                      int skip = -1, int only = -1);

// ---- The textures the shader reads ---------------------------------------------------------
// The shader walks both levels in one loop, and each turn of it reads the same four texels
// (kStepTexels) from one texture, the atlas, whatever it visits there: an interior node, a
// triangle or a placed object. A software rasteriser (SwiftShader, llvmpipe) runs a fragment
// shader on several pixels at once, each turn the union of what they take, so nested loops and
// fetches from several textures per turn multiply (the old walk's did). A branch none of them
// takes cost SwiftShader under a millisecond a frame when padded with eight fetches
// (docs/performance.md): it is skipped.
//
// RGBA32F texels, kBvhTextureWidth a row; indices and counts are stored as floats (exact below
// 2^24 texels).
inline constexpr int kBvhTextureWidthShift = 10;  // the shader splits a texel index with a shift
inline constexpr int kBvhTextureWidth = 1 << kBvhTextureWidthShift;
inline constexpr int kStepTexels = 4;  // what one turn of the shader's loop reads
inline constexpr int kNodeTexels = 4;  // an interior node: both children, (min, ref) (max, count)
inline constexpr int kTriangleTexels = 3;  // v0, v1 - v0, v2 - v0; v0.w = the triangle's slot
inline constexpr int kSlotTexels = 4;      // a placed object: its inverse model's rows, its root
// The most triangles of the object a top level tests before its walk (its tree a single leaf).
inline constexpr int kTestedTriangles = 4;

// Where a subtree starts in the atlas, as the shader follows it: an interior node (count 0) at
// texel `texel`; a leaf (count > 0) of `count` triangles from texel `texel`; or, in the top level,
// a placed object's slot (count kInstanceRef).
struct PackedRef {
  int texel = 0;
  int count = 0;
  bool operator==(const PackedRef&) const = default;
};
inline constexpr int kInstanceRef = -1;

// Every mesh's tree, one after another: its interior nodes, then its triangles; and the vertex
// normals, 3 texels a triangle slot, in a texture of their own. The texels are written on demand
// in any range (writeTexels), so an upload goes a block of rows at a time and never holds the
// whole atlas (the 157k-triangle figure's is 10 MB, its normals 7.5 MB).
class BvhAtlas {
 public:
  struct Root {
    PackedRef ref;
    Bounds box;
  };
  // Places `mesh`'s tree after the ones added before.
  void add(const std::string& name, std::shared_ptr<const MeshBvh> mesh);
  size_t texelCount() const { return texels_; }
  size_t normalTexelCount() const { return 3 * static_cast<size_t>(triangles_); }
  int triangles() const { return triangles_; }
  const std::map<std::string, Root>& roots() const { return roots_; }
  // Texels [first, first + count) as RGBA floats into out (4 a texel); zeros past the end.
  void writeTexels(size_t first, size_t count, float* out) const;
  void writeNormals(size_t first, size_t count, float* out) const;

 private:
  struct Part {
    std::shared_ptr<const MeshBvh> mesh;
    size_t base = 0;                      // its first texel
    size_t triangles = 0;                 // texel of its first triangle
    int firstSlot = 0;                    // its first triangle's slot in the normals
    std::vector<uint32_t> interiorNodes;  // the tree's interior nodes, in the atlas's order
    std::vector<int> nodeTexel;           // per tree node: its texel (interior) or -1
  };
  PackedRef refOf(const Part& part, uint32_t node) const;
  std::vector<Part> parts_;
  std::map<std::string, Root> roots_;
  size_t texels_ = 0;
  int triangles_ = 0;
};

// Per frame, for the shader:
//  - `traversal`: the texels the walk reads, to be placed in the atlas from texel `firstTexel`
//    on: a header (kStepTexels: the top level's box and root, then (box min, slot texel) and
//    (box max, 1) of the object its rays test before the walk, or zeros), each object's slot
//    (kSlotTexels; the inverse model's rows, then (root texel, root count, object index)), then
//    the top level's interior nodes. The tested object is the traced one whose tree is a single
//    leaf of at most kTestedTriangles with the largest world box (the ground), and it is not in
//    the tree: a ray towards the ground meets it in one test of its two triangles, and then
//    walks the tree with that hit's distance, where it walked the tree's root, the ground's slot
//    and each of its triangles in turn (in SwiftShader the shipped scene's frame is 0.90x the
//    walk's that did, docs/performance.md);
//  - `shading`: kInstanceTexels per object, for what the walk found (normal matrix columns,
//    colour and material, mix weights, probe centre, self epsilon, inverse model's rows).
inline constexpr int kInstanceTexels = 10;
struct PackedScene {
  std::vector<float> traversal;
  std::vector<float> shading;
  int header = 0;  // texel of the header (firstTexel)
  int instances = 0;
  bool empty = true;  // no instance has a mesh
  // A second top level over the Phong objects alone, after the first's nodes: all a ray of a
  // mirror that meets nothing but Phong surfaces and the sky (EXACT_GENERAL 0) can meet. Its own
  // mirror, never met, is not in it: every such ray starts inside that mirror's box, and the walk
  // would visit its slot to leave it.
  int phongHeader = 0;
  bool phongEmpty = true;  // no Phong object has a mesh
};
// `roots`: each object's mesh root in the atlas (count 0 and texel -1: not traced);
// `probeCentres`: where each object's probe captures from (the cube-textured material traces
// from there).
PackedScene packScene(const Scene& scene, const SceneBvh& bvh, const std::vector<PackedRef>& roots,
                      const std::vector<glm::vec3>& probeCentres, int firstTexel);

// The stack the shader's walk needs (EXACT_STACK): an entry a pushed child, at most one for each
// interior node on the path it walks, the top level's (a binary tree over `objects` leaves: at
// most objects - 1) and then its object's (at most `deepestTree` - 1, that mesh tree's levels).
// In steps of 8, so a new model seldom asks for a new program; at most both levels of
// kBvhMaxDepth. A smaller stack is cheaper: SwiftShader's WebGL2 zeroes every local array each
// pixel, and the 66 entries of the largest cost a fifth of the shipped scene's trace.
int traceStackFor(size_t objects, int deepestTree);

}  // namespace reflect
