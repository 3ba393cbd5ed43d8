#include "core/mesh_simplify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace reflect {
namespace {

// A closed UV sphere of radius 1 (poles shared), `rings` x `segments` quads.
MeshData sphere(int rings, int segments) {
  MeshData mesh;
  mesh.vertices.push_back({{0, 1, 0}, {0, 1, 0}});
  for (int i = 1; i < rings; ++i) {
    const float theta = 3.14159265f * static_cast<float>(i) / static_cast<float>(rings);
    for (int j = 0; j < segments; ++j) {
      const float phi = 6.2831853f * static_cast<float>(j) / static_cast<float>(segments);
      const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back({p, p});
    }
  }
  mesh.vertices.push_back({{0, -1, 0}, {0, -1, 0}});
  const auto ring = [&](int i, int j) {
    return static_cast<uint32_t>(1 + (i - 1) * segments + (j % segments));
  };
  const uint32_t south = static_cast<uint32_t>(mesh.vertices.size() - 1);
  for (int j = 0; j < segments; ++j) {
    for (uint32_t v : {0u, ring(1, j + 1), ring(1, j)}) mesh.indices.push_back(v);
    for (uint32_t v : {south, ring(rings - 1, j), ring(rings - 1, j + 1)}) {
      mesh.indices.push_back(v);
    }
    for (int i = 1; i + 1 < rings; ++i) {
      for (uint32_t v : {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j),
                         ring(i + 1, j + 1), ring(i + 1, j)}) {
        mesh.indices.push_back(v);
      }
    }
  }
  return mesh;
}

// An open n x n grid of quads in the plane y = 0, facing up.
MeshData grid(int n) {
  MeshData mesh;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      mesh.vertices.push_back({{static_cast<float>(i), 0, static_cast<float>(j)}, {0, 1, 0}});
    }
  }
  const auto at = [&](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (uint32_t v :
           {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)}) {
        mesh.indices.push_back(v);
      }
    }
  }
  return mesh;
}

glm::vec3 normalOf(const MeshData& mesh, const std::vector<uint32_t>& indices, size_t t) {
  const glm::vec3 a = mesh.vertices[indices[t]].position,
                  b = mesh.vertices[indices[t + 1]].position,
                  c = mesh.vertices[indices[t + 2]].position;
  return glm::cross(b - a, c - a);
}

TEST(MeshSimplify, ReachesTheTargetOnASphereWithoutTurningATriangleInside) {
  const MeshData mesh = sphere(24, 48);
  const std::vector<uint32_t> out = simplifyMesh(mesh.vertices, mesh.indices, 300 * 3, 0.05f);
  EXPECT_LE(out.size(), 300u * 3);
  EXPECT_GT(out.size(), 200u * 3);
  for (size_t t = 0; t < out.size(); t += 3) {
    const glm::vec3 n = normalOf(mesh, out, t);
    const glm::vec3 centre = (mesh.vertices[out[t]].position + mesh.vertices[out[t + 1]].position +
                              mesh.vertices[out[t + 2]].position) /
                             3.0f;
    EXPECT_GT(glm::dot(n, centre), 0.0f) << "triangle " << t / 3 << " faces inwards";
  }
  // Closed and manifold still: every edge has exactly two triangles, one each way.
  std::multiset<std::pair<uint32_t, uint32_t>> edges;
  for (size_t t = 0; t < out.size(); t += 3) {
    for (size_t k = 0; k < 3; ++k) edges.insert({out[t + k], out[t + (k + 1) % 3]});
  }
  for (const auto& [a, b] : edges) {
    EXPECT_EQ(edges.count({a, b}), 1u);
    EXPECT_EQ(edges.count({b, a}), 1u);
  }
}

TEST(MeshSimplify, StopsAtTheTargetErrorAndKeepsBorders) {
  // A plane loses every inner vertex at no error; its border vertices never move.
  const MeshData flat = grid(16);
  const std::vector<uint32_t> out = simplifyMesh(flat.vertices, flat.indices, 0, 0.0f);
  EXPECT_LT(out.size(), flat.indices.size() / 4);
  std::set<uint32_t> used(out.begin(), out.end());
  for (int k = 0; k <= 16; ++k) {
    for (uint32_t v : {static_cast<uint32_t>(k), static_cast<uint32_t>(16 * 17 + k),
                       static_cast<uint32_t>(k * 17), static_cast<uint32_t>(k * 17 + 16)}) {
      EXPECT_TRUE(used.count(v)) << "border vertex " << v << " moved";
    }
  }
  for (size_t t = 0; t < out.size(); t += 3) EXPECT_GT(normalOf(flat, out, t).y, 0.0f);
  // A sphere at a tiny error keeps nearly all of itself; at a large one it reaches the target.
  const MeshData round = sphere(12, 24);
  EXPECT_GT(simplifyMesh(round.vertices, round.indices, 0, 1e-4f).size(),
            round.indices.size() * 9 / 10);
  EXPECT_LE(simplifyMesh(round.vertices, round.indices, 90, 1.0f).size(), 90u);
}

TEST(MeshSimplify, SeamsAreOneVertexAndTheResultIsRepeatable) {
  // The sphere with every triangle's corners its own vertices (a seam everywhere): it still
  // simplifies, and each corner keeps a vertex with its own normal where it can.
  const MeshData smooth = sphere(16, 32);
  MeshData split;
  for (uint32_t index : smooth.indices) {
    split.indices.push_back(static_cast<uint32_t>(split.vertices.size()));
    split.vertices.push_back(smooth.vertices[index]);
  }
  const std::vector<uint32_t> once = simplifyMesh(split.vertices, split.indices, 300, 0.05f);
  EXPECT_LE(once.size(), 300u);
  EXPECT_GT(once.size(), 150u);
  EXPECT_EQ(once, simplifyMesh(split.vertices, split.indices, 300, 0.05f));
  // Degenerate triangles and indices out of range are dropped.
  std::vector<uint32_t> bad = smooth.indices;
  bad.insert(bad.end(), {0, 0, 1, 0, 1, 999999});
  EXPECT_EQ(simplifyMesh(smooth.vertices, bad, bad.size(), 0.0f).size(), smooth.indices.size());
}

}  // namespace
}  // namespace reflect
