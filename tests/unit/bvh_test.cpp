// core/bvh.h: the binned SAH build's structure, and the traversal against testing every triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/bvh.h"
#include "core/obj_loader.h"

namespace reflect {
namespace {

MeshData randomTriangles(int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> at(-1.0f, 1.0f), small(-0.1f, 0.1f);
  MeshData m;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c(at(rng), at(rng), at(rng));
    for (int k = 0; k < 3; ++k) {
      m.vertices.push_back({c + glm::vec3(small(rng), small(rng), small(rng)), {0, 1, 0}});
      m.indices.push_back(static_cast<uint32_t>(m.vertices.size() - 1));
    }
  }
  m.bounds = computeBounds(m.vertices);
  return m;
}

// Every item in exactly one leaf, every child inside its parent, the depth within the stack.
void expectWellFormed(const Bvh& bvh, size_t items) {
  std::vector<int> seen(items, 0);
  for (const BvhNode& n : bvh.nodes) {
    if (n.count > 0) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i) ++seen[bvh.order[i]];
      continue;
    }
    for (uint32_t c : {n.first, n.first + 1}) {
      ASSERT_LT(c, bvh.nodes.size());
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(bvh.nodes[c].min, n.min)));
      EXPECT_TRUE(glm::all(glm::lessThanEqual(bvh.nodes[c].max, n.max)));
    }
  }
  for (int s : seen) EXPECT_EQ(s, 1);
  EXPECT_LE(bvh.depth, kBvhMaxDepth);
}

TEST(Bvh, EveryTriangleInOneLeaf) {
  const MeshData mesh = randomTriangles(5000, 1);
  const MeshBvh bvh = buildMeshBvh(mesh);
  expectWellFormed(bvh.tree, mesh.triangleCount());
  EXPECT_EQ(bvh.positions.size(), mesh.triangleCount() * 3);
  EXPECT_LT(bvh.tree.depth, 30);
}

TEST(Bvh, IdenticalBoxesStillSplit) {
  std::vector<Bounds> boxes(100, Bounds{glm::vec3(0), glm::vec3(1)});
  const Bvh bvh = buildBvh(boxes, 1);
  expectWellFormed(bvh, boxes.size());
  for (const BvhNode& n : bvh.nodes) EXPECT_LE(n.count, 1u);
}

TEST(Bvh, EmptyAndSingle) {
  EXPECT_TRUE(buildBvh({}).nodes.empty());
  const Bvh one = buildBvh({Bounds{glm::vec3(0), glm::vec3(1)}});
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_EQ(one.nodes[0].count, 1u);
}

TEST(Bvh, TraversalFindsTheNearestTriangleAsBruteForce) {
  const MeshData mesh = randomTriangles(3000, 2);
  std::vector<BvhInstance> instances(2);
  instances[0].mesh = std::make_shared<const MeshBvh>(buildMeshBvh(mesh));
  instances[1].mesh = instances[0].mesh;
  instances[1].model = glm::mat4(glm::mat3(2.0f));  // scaled, and rotated below
  instances[1].model = glm::mat4(glm::vec4(0, 0, -2, 0), glm::vec4(0, 2, 0, 0),
                                 glm::vec4(2, 0, 0, 0), glm::vec4(3, 0, 0, 1));
  for (BvhInstance& i : instances) i.inverse = glm::inverse(i.model);
  const SceneBvh scene = buildSceneBvh(instances);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> at(-4.0f, 4.0f);
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    const glm::vec3 o(at(rng), at(rng), 6.0f);
    const glm::vec3 d = glm::normalize(glm::vec3(at(rng), at(rng), -6.0f) - o);
    const RayHit got = intersectScene(scene, o, d);
    // Brute force in world space.
    float bestT = std::numeric_limits<float>::infinity();
    int bestInstance = -1, bestTriangle = -1;
    for (int i = 0; i < 2; ++i) {
      for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
          p[k] = glm::vec3(
              instances[static_cast<size_t>(i)].model *
              glm::vec4(mesh.vertices[mesh.indices[t * 3 + static_cast<size_t>(k)]].position,
                        1.0f));
        }
        float th, u, v;
        if (intersectTriangle(o, d, p[0], p[1], p[2], 0.0f, bestT, &th, &u, &v)) {
          bestT = th;
          bestInstance = i;
          bestTriangle = static_cast<int>(t);
        }
      }
    }
    EXPECT_EQ(got.instance, bestInstance);
    EXPECT_EQ(got.triangle, bestTriangle);
    if (bestInstance >= 0) {
      ++hits;
      EXPECT_NEAR(got.t, bestT, 1e-4f * bestT);
    }
  }
  EXPECT_GT(hits, 200);
}

TEST(Bvh, SkipAndOnly) {
  MeshData quad;
  quad.vertices = {{{-1, -1, 0}, {0, 0, 1}},
                   {{1, -1, 0}, {0, 0, 1}},
                   {{1, 1, 0}, {0, 0, 1}},
                   {{-1, 1, 0}, {0, 0, 1}}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  std::vector<BvhInstance> instances(2);
  instances[0].mesh = std::make_shared<const MeshBvh>(buildMeshBvh(quad));
  instances[1].mesh = instances[0].mesh;
  instances[1].model = glm::mat4(1.0f);
  instances[1].model[3] = glm::vec4(0, 0, -1, 1);
  for (BvhInstance& i : instances) i.inverse = glm::inverse(i.model);
  const SceneBvh scene = buildSceneBvh(instances);
  const glm::vec3 o(0.2f, 0.1f, 5.0f), d(0, 0, -1);
  EXPECT_EQ(intersectScene(scene, o, d).instance, 0);
  EXPECT_FLOAT_EQ(intersectScene(scene, o, d).t, 5.0f);
  EXPECT_EQ(intersectScene(scene, o, d, 0.0f, 1e30f, 0).instance, 1);
  EXPECT_FLOAT_EQ(intersectScene(scene, o, d, 0.0f, 1e30f, 0).t, 6.0f);
  EXPECT_EQ(intersectScene(scene, o, d, 0.0f, 1e30f, -1, 1).instance, 1);
  EXPECT_EQ(intersectScene(scene, o, -d).instance, -1);
}

TEST(Bvh, AtlasMakesIndicesAbsolute) {
  const MeshData a = randomTriangles(50, 4), b = randomTriangles(70, 5);
  const MeshBvh ta = buildMeshBvh(a), tb = buildMeshBvh(b);
  BvhAtlas atlas;
  atlas.add("a", ta);
  atlas.add("b", tb);
  EXPECT_EQ(atlas.roots["a"], 0u);
  EXPECT_EQ(atlas.roots["b"], ta.tree.nodes.size());
  EXPECT_EQ(atlas.positions.size(), (50u + 70u) * 3u * 4u);
  // b's root: an interior node whose children follow in b's part of the atlas.
  const size_t root = atlas.roots["b"] * 8;
  EXPECT_EQ(atlas.nodes[root + 7], 0.0f);
  EXPECT_EQ(atlas.nodes[root + 3], static_cast<float>(ta.tree.nodes.size() + 1));
}

}  // namespace
}  // namespace reflect
