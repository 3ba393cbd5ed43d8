#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh_chunks.h"
#include "core/mesh_lod.h"
#include "core/obj_loader.h"

namespace reflect {
namespace {

// A strip of n separate triangles along x.
MeshData strip(int n) {
  MeshData mesh;
  for (int i = 0; i < n; ++i) {
    const float x = static_cast<float>(i);
    for (glm::vec3 p : {glm::vec3(x, 0, 0), glm::vec3(x + 0.5f, 0, 0), glm::vec3(x, 1, 0)}) {
      mesh.indices.push_back(static_cast<uint32_t>(mesh.vertices.size()));
      mesh.vertices.push_back({p, {0, 0, 1}});
    }
  }
  std::reverse(mesh.indices.begin(), mesh.indices.end());  // scrambled order to start with
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

TEST(MeshChunks, CoverEveryTriangleOnceInBoundedContiguousPieces) {
  MeshData mesh = strip(1000);
  std::vector<uint32_t> before = mesh.indices;
  chunkMesh(mesh, 100);
  ASSERT_GE(mesh.chunks.size(), 10u);
  uint32_t next = 0;
  for (const MeshChunk& c : mesh.chunks) {
    EXPECT_EQ(c.range.first, next);
    EXPECT_LE(c.range.count, 300u);
    EXPECT_GT(c.range.count, 0u);
    next += c.range.count;
    for (uint32_t i = c.range.first; i < c.range.first + c.range.count; ++i) {
      const glm::vec3 p = mesh.vertices[mesh.indices[i]].position;
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, c.bounds.min)) &&
                  glm::all(glm::lessThanEqual(p, c.bounds.max)));
    }
  }
  EXPECT_EQ(next, mesh.indices.size());
  // The same triangles, only reordered (each triangle's corners kept together and in order).
  std::vector<uint32_t> after = mesh.indices;
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  EXPECT_EQ(before, after);
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    EXPECT_EQ(mesh.indices[t] / 3, mesh.indices[t + 1] / 3);
  }
  // Spatial: a chunk of 100 triangles of this strip spans about 100 units of x, not 1000.
  for (const MeshChunk& c : mesh.chunks) EXPECT_LT(c.bounds.max.x - c.bounds.min.x, 130.0f);
}

TEST(MeshChunks, SmallMeshIsOneChunkAndRangesMerge) {
  MeshData mesh = strip(5);
  chunkMesh(mesh);
  ASSERT_EQ(mesh.chunks.size(), 1u);
  EXPECT_EQ(mesh.chunks[0].range.count, 15u);
  std::vector<IndexRange> ranges;
  appendRange(ranges, {0, 3});
  appendRange(ranges, {3, 6});
  appendRange(ranges, {12, 3});
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].count, 9u);
  EXPECT_EQ(ranges[1].first, 12u);
}

// The chunk order is canonical (a total order for the splits, the mesh's order within a chunk) and
// the simplifier deterministic (core/mesh_simplify.h), and the page's worker runs this same C++
// compiled to wasm: these are the page's numbers too. tests/web/files.spec.mjs expects the same
// three numbers from window.demo.lodLevels('mario.obj'); a change here changes both.
TEST(MeshChunks, ShippedMarioLevelsAreThePagesLevels) {
  Result<LoadedMesh> loaded = loadObjFile(std::string(MODEL_DIR) + "/mario.obj");
  ASSERT_TRUE(loaded) << loaded.error();
  const BuiltLevels built = buildLevels(loaded.value().mesh, true, true);
  std::vector<size_t> triangles{built.base.indices.size() / 3};
  for (const LevelIndices& level : built.coarser) triangles.push_back(level.indices.size() / 3);
  EXPECT_EQ(triangles, (std::vector<size_t>{7258, 1814, 528}));
}

TEST(MeshChunks, TiedCentresSplitByTriangleNumber) {
  // Eight triangles with one centre: the splits and the chunks keep them in the mesh's order.
  const std::vector<Vertex> vertices{
      {{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
  std::vector<uint32_t> indices;
  for (int t = 0; t < 8; ++t) {
    const uint32_t first = static_cast<uint32_t>(t % 3);  // each a rotation of the same corners
    for (uint32_t k = 0; k < 3; ++k) indices.push_back((first + k) % 3);
  }
  const std::vector<uint32_t> before = indices;
  EXPECT_EQ(chunkOrder(vertices, indices, 2), (std::vector<uint32_t>{2, 2, 2, 2}));
  EXPECT_EQ(indices, before);
}

}  // namespace
}  // namespace reflect
