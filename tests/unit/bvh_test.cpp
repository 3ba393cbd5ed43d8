// core/bvh.h: the binned SAH build's structure, and the traversal against testing every triangle.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

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

std::shared_ptr<const MeshData> shared(const MeshData& mesh) {
  return std::make_shared<const MeshData>(mesh);
}

// Every texel of an atlas, as the upload writes them.
std::vector<float> allTexels(const BvhAtlas& atlas) {
  std::vector<float> texels(atlas.texelCount() * 4);
  atlas.writeTexels(0, atlas.texelCount(), texels.data());
  return texels;
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
  const MeshBvh bvh = buildMeshBvh(shared(mesh));
  expectWellFormed(bvh.tree, mesh.triangleCount());
  EXPECT_EQ(bvh.corners.size(), mesh.triangleCount() * 3);
  // Each slot's corners are its triangle's, in the mesh's own order.
  for (size_t s = 0; s < bvh.triangleCount(); s += 97) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(bvh.corners[s * 3 + static_cast<size_t>(k)],
                mesh.indices[static_cast<size_t>(bvh.tree.order[s]) * 3 + static_cast<size_t>(k)]);
    }
  }
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
  instances[0].mesh = std::make_shared<const MeshBvh>(buildMeshBvh(shared(mesh)));
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
  instances[0].mesh = std::make_shared<const MeshBvh>(buildMeshBvh(shared(quad)));
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

// The shader's walk (shaders/exact_trace.glsl's exactTrace), step for step, over the packed
// texels: one loop over both levels, four texels read a turn.
struct PackedWalk {
  const std::vector<float>& texels;  // the atlas with the frame's texels in place
  mutable size_t deepest = 0;        // the most entries its stack held, over every walk
  glm::vec4 at(int texel) const {
    const size_t i = static_cast<size_t>(texel) * 4;
    if (i + 4 > texels.size()) return glm::vec4(0.0f);  // the shader reads zeros past the end
    return {texels[i], texels[i + 1], texels[i + 2], texels[i + 3]};
  }
  static float entry(const glm::vec4& lo, const glm::vec4& hi, const glm::vec3& o,
                     const glm::vec3& inv, float tMin, float tMax) {
    const glm::vec3 t0 = (glm::vec3(lo) - o) * inv, t1 = (glm::vec3(hi) - o) * inv;
    const glm::vec3 a = glm::min(t0, t1), b = glm::max(t0, t1);
    const float enter = std::max(std::max(a.x, a.y), std::max(a.z, tMin));
    const float leave = std::min(std::min(b.x, b.y), std::min(b.z, tMax));
    return enter <= leave ? enter : INFINITY;
  }
  static glm::vec3 inverse(const glm::vec3& d) {
    glm::vec3 r;
    for (int i = 0; i < 3; ++i)
      r[i] = 1.0f / (std::abs(d[i]) < 1e-20f ? std::copysign(1e-20f, d[i]) : d[i]);
    return r;
  }
  RayHit trace(int header, const glm::vec3& origin, const glm::vec3& direction, int skip = -1,
               int only = -1, int* steps = nullptr) const {
    RayHit best;
    const glm::vec3 worldInv = inverse(direction);
    const glm::vec4 h0 = at(header), h1 = at(header + 1), h2 = at(header + 2), h3 = at(header + 3);
    // The object tested before the walk: its triangles in its space.
    if (h3.w > 0.5f && entry(h2, h3, origin, worldInv, 0.0f, best.t) != INFINITY) {
      const int slot = static_cast<int>(h2.w);
      const glm::vec4 r0 = at(slot), r1 = at(slot + 1), r2 = at(slot + 2), r3 = at(slot + 3);
      const int object = static_cast<int>(r3.z);
      if (object != skip && (only < 0 || object == only)) {
        const glm::vec4 p(origin, 1.0f);
        const glm::vec3 o(glm::dot(r0, p), glm::dot(r1, p), glm::dot(r2, p));
        const glm::vec3 d(glm::dot(glm::vec3(r0), direction), glm::dot(glm::vec3(r1), direction),
                          glm::dot(glm::vec3(r2), direction));
        for (int k = 0, tri = static_cast<int>(r3.x); k < static_cast<int>(r3.y);
             ++k, tri += kTriangleTexels) {
          if (steps) ++*steps;
          const glm::vec3 v0(at(tri));
          float t, u, v;
          if (intersectTriangle(o, d, v0, v0 + glm::vec3(at(tri + 1)), v0 + glm::vec3(at(tri + 2)),
                                0.0f, best.t, &t, &u, &v)) {
            best.t = t;
            best.instance = object;
            best.slot = static_cast<int>(at(tri).w);
          }
        }
      }
    }
    if (h0.w < 0.0f || entry(h0, h1, origin, worldInv, 0.0f, best.t) == INFINITY) return best;
    int ref = static_cast<int>(h0.w), count = static_cast<int>(h1.w);
    glm::vec3 o = origin, d = direction, inv = worldInv;
    int instance = -1, base = -1;
    std::vector<std::array<float, 3>> stack;  // ref, count, entry
    for (int step = 0; step < 4096; ++step) {
      if (steps) ++*steps;
      const glm::vec4 a = at(ref), b = at(ref + 1), c = at(ref + 2), e = at(ref + 3);
      bool done = false;
      if (count == 0) {
        const float tl = entry(a, b, o, inv, 0.0f, best.t), tr = entry(c, e, o, inv, 0.0f, best.t);
        const bool leftFirst = tl <= tr;
        if (std::max(tl, tr) != INFINITY) {
          stack.push_back(leftFirst ? std::array<float, 3>{c.w, e.w, tr}
                                    : std::array<float, 3>{a.w, b.w, tl});
          deepest = std::max(deepest, stack.size());
        }
        ref = static_cast<int>(leftFirst ? a.w : c.w);
        count = static_cast<int>(leftFirst ? b.w : e.w);
        done = std::min(tl, tr) == INFINITY;
      } else if (count > 0) {
        float t, u, v;
        const glm::vec3 v0(a);
        if (intersectTriangle(o, d, v0, v0 + glm::vec3(b), v0 + glm::vec3(c), 0.0f, best.t, &t, &u,
                              &v)) {
          best.t = t;
          best.instance = instance;
          best.slot = static_cast<int>(a.w);
        }
        ref += kTriangleTexels;
        done = --count == 0;
      } else {
        const int object = static_cast<int>(e.z);
        if (object == skip || (only >= 0 && object != only) || e.x < 0.0f) {
          done = true;
        } else {
          const glm::vec4 p(origin, 1.0f);
          o = {glm::dot(a, p), glm::dot(b, p), glm::dot(c, p)};
          d = {glm::dot(glm::vec3(a), direction), glm::dot(glm::vec3(b), direction),
               glm::dot(glm::vec3(c), direction)};
          inv = inverse(d);
          instance = object;
          base = static_cast<int>(stack.size());
          ref = static_cast<int>(e.x);
          count = static_cast<int>(e.y);
        }
      }
      if (!done) continue;
      while (!stack.empty() && stack.back()[2] > best.t) stack.pop_back();
      if (stack.empty()) break;
      ref = static_cast<int>(stack.back()[0]);
      count = static_cast<int>(stack.back()[1]);
      stack.pop_back();
      if (static_cast<int>(stack.size()) < base) {
        o = origin;
        d = direction;
        inv = worldInv;
        instance = -1;
        base = -1;
      }
    }
    return best;
  }
};

TEST(Bvh, ThePackedWalkFindsWhatTheTraversalFinds) {
  const MeshData a = randomTriangles(300, 4), b = randomTriangles(3, 5);
  const auto ta = std::make_shared<const MeshBvh>(buildMeshBvh(shared(a)));
  const auto tb = std::make_shared<const MeshBvh>(buildMeshBvh(shared(b)));
  BvhAtlas atlas;
  atlas.add("a", ta);
  atlas.add("b", tb);
  EXPECT_EQ(atlas.triangles(), 303);
  EXPECT_EQ(atlas.normalTexelCount(), 303u * 3u);
  EXPECT_EQ(atlas.roots().at("a").ref.count, 0);  // an interior node
  EXPECT_EQ(atlas.roots().at("b").ref.count, 3);  // three triangles: the root is a leaf
  // Written in any pieces, the texels are the same.
  const std::vector<float> whole = allTexels(atlas);
  std::vector<float> pieces(whole.size());
  for (size_t first = 0; first < atlas.texelCount(); first += 37) {
    const size_t count = std::min<size_t>(37, atlas.texelCount() - first);
    atlas.writeTexels(first, count, pieces.data() + 4 * first);
  }
  EXPECT_EQ(pieces, whole);

  // Five objects, two of them on mesh b, one untraced (no mesh), placed and turned.
  Scene scene;
  std::vector<BvhInstance> instances(5);
  std::vector<PackedRef> roots(5, PackedRef{-1, 0});
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> at(-3.0f, 3.0f);
  for (int i = 0; i < 5; ++i) {
    scene.objects.push_back({});
    if (i == 3) continue;
    const bool onB = i == 1 || i == 4;
    instances[static_cast<size_t>(i)].mesh = onB ? tb : ta;
    roots[static_cast<size_t>(i)] = atlas.roots().at(onB ? "b" : "a").ref;
    glm::mat4 m =
        glm::rotate(glm::mat4(1.0f), at(rng), glm::normalize(glm::vec3(at(rng), at(rng), 1)));
    m[3] = glm::vec4(at(rng), at(rng), at(rng), 1.0f);
    instances[static_cast<size_t>(i)].model =
        glm::scale(m, glm::vec3(0.5f + 0.2f * static_cast<float>(i)));
    instances[static_cast<size_t>(i)].inverse =
        glm::inverse(instances[static_cast<size_t>(i)].model);
  }
  scene.objects[2].material = Material::Mirror;  // not in the Phong objects' top level
  const SceneBvh bvh = buildSceneBvh(instances);
  const int first = static_cast<int>(atlas.texelCount()) + 7;  // any texel past the meshes
  const PackedScene packed = packScene(scene, bvh, roots, {}, first);
  EXPECT_EQ(packed.header, first);
  EXPECT_EQ(packed.shading.size(), 5u * kInstanceTexels * 4u);
  std::vector<float> texels = allTexels(atlas);
  texels.resize(static_cast<size_t>(first) * 4, 0.0f);
  texels.insert(texels.end(), packed.traversal.begin(), packed.traversal.end());
  const PackedWalk walk{texels};

  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0;
  int phongSteps = 0, skipSteps = 0;
  for (int r = 0; r < 3000; ++r) {
    const glm::vec3 o(at(rng) * 2.0f, at(rng) * 2.0f, at(rng) * 2.0f);
    // Aim at a vertex of a placed object, so most rays meet something.
    const size_t aim = static_cast<size_t>(r) % 5 == 3 ? 0 : static_cast<size_t>(r) % 5;
    const MeshData& aimed = aim == 1 || aim == 4 ? b : a;
    const glm::vec3 vertex =
        aimed.vertices[static_cast<size_t>(r * 7) % aimed.vertices.size()].position;
    const glm::vec3 target(instances[aim].model * glm::vec4(vertex, 1.0f));
    const glm::vec3 d = glm::normalize(target - o);
    const int skip = r % 7 == 0 ? 2 : -1;
    const int only = r % 11 == 0 ? 4 : -1;
    const RayHit want = intersectScene(bvh, o, d, 0.0f, INFINITY, skip, only);
    const RayHit got = walk.trace(packed.header, o, d, skip, only);
    ASSERT_EQ(got.instance, want.instance) << "ray " << r;
    // The Phong objects' top level meets what the whole scene's meets past its mirror, in fewer
    // turns over all the rays (it never visits the mirror's slot).
    const RayHit pastMirror = intersectScene(bvh, o, d, 0.0f, INFINITY, 2, only);
    EXPECT_EQ(walk.trace(packed.phongHeader, o, d, -1, only, &phongSteps).t, pastMirror.t)
        << "ray " << r;
    walk.trace(packed.header, o, d, 2, only, &skipSteps);
    if (want.instance < 0) continue;
    ++hits;
    EXPECT_EQ(got.t, want.t) << "ray " << r;
    // The slot names the triangle in the normals' order: mesh a's, then b's.
    const int offset = want.instance == 1 || want.instance == 4 ? 300 : 0;  // b after a
    EXPECT_EQ(got.slot, want.slot + offset) << "ray " << r;
  }
  EXPECT_GT(hits, 600);  // aimed at vertices (on edges, some slip past): 782 meet one
  EXPECT_FALSE(packed.phongEmpty);
  EXPECT_LT(phongSteps, skipSteps);
}

TEST(Bvh, TheGroundIsTestedBeforeTheWalk) {
  // A ground quad (two triangles: its tree a single leaf), two figures above it and a mirror: both
  // top levels leave the quad out of their trees and test it first; every ray meets what the
  // scene's traversal meets, and the Phong level's walks take fewer turns than with the quad in
  // the tree.
  MeshData quad;
  for (const glm::vec3& p :
       {glm::vec3(-1, 0, -1), glm::vec3(1, 0, -1), glm::vec3(1, 0, 1), glm::vec3(-1, 0, 1)}) {
    Vertex v;
    v.position = p;
    v.normal = glm::vec3(0, 1, 0);
    quad.vertices.push_back(v);
  }
  quad.indices = {0, 2, 1, 0, 3, 2};
  quad.bounds = computeBounds(quad.vertices);
  const MeshData figure = randomTriangles(200, 6);
  const auto tq = std::make_shared<const MeshBvh>(buildMeshBvh(shared(quad)));
  const auto tf = std::make_shared<const MeshBvh>(buildMeshBvh(shared(figure)));
  BvhAtlas atlas;
  atlas.add("quad", tq);
  atlas.add("figure", tf);
  ASSERT_EQ(atlas.roots().at("quad").ref.count, 2);  // a single leaf: tested before the walk
  Scene scene;
  scene.objects.resize(4);
  scene.objects[3].material = Material::Mirror;
  std::vector<BvhInstance> instances(4);
  std::vector<PackedRef> roots(4);
  const glm::mat4 placements[4] = {
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0)), glm::vec3(10, 1, 10)),
      glm::translate(glm::mat4(1.0f), glm::vec3(4, 1, 0)),
      glm::translate(glm::mat4(1.0f), glm::vec3(-4, 1, 1)),
      glm::scale(glm::mat4(1.0f), glm::vec3(0.5f))};
  for (size_t i = 0; i < 4; ++i) {
    instances[i].mesh = i == 0 ? tq : tf;
    roots[i] = atlas.roots().at(i == 0 ? "quad" : "figure").ref;
    instances[i].model = placements[i];
    instances[i].inverse = glm::inverse(placements[i]);
  }
  const SceneBvh bvh = buildSceneBvh(instances);
  const int first = static_cast<int>(atlas.texelCount());
  const PackedScene packed = packScene(scene, bvh, roots, {}, first);
  std::vector<float> texels = allTexels(atlas);
  texels.insert(texels.end(), packed.traversal.begin(), packed.traversal.end());
  const PackedWalk walk{texels};
  // Both headers name the quad's slot (object 0, the first slot) in their last two texels.
  for (int header : {packed.header, packed.phongHeader}) {
    EXPECT_EQ(walk.at(header + 2).w, static_cast<float>(first + kStepTexels)) << header;
    EXPECT_EQ(walk.at(header + 3).w, 1.0f) << header;
    EXPECT_EQ(walk.at(header + 2).y, -1.0f) << header;  // the ground's world box, y = -1
  }
  // Straight down from the mirror, away from the figures: the quad's two triangles are the whole
  // walk (with the quad in the tree: its root, the quad's slot, then each triangle).
  int down = 0;
  EXPECT_EQ(
      walk.trace(packed.phongHeader, glm::vec3(0, -0.5f, 0), glm::vec3(0, -1, 0), 3, -1, &down)
          .instance,
      0);
  EXPECT_EQ(down, 2);

  std::mt19937 rng(12);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int grounds = 0, figures = 0;
  for (int r = 0; r < 2000; ++r) {
    // From the mirror's surface, every way (the sky, the ground), and every other ray at a vertex
    // of a figure.
    glm::vec3 d = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
    const glm::vec3 o = 0.5f * d;
    if (r % 2 == 1) {
      const glm::vec3 vertex =
          figure.vertices[static_cast<size_t>(r * 7) % figure.vertices.size()].position;
      d = glm::normalize(glm::vec3(placements[1 + r % 4 / 2] * glm::vec4(vertex, 1.0f)) - o);
    }
    const int skip = r % 5 == 0 ? 0 : 3;  // sometimes leaving the ground itself
    const int only = r % 9 == 0 ? 1 : -1;
    const RayHit want = intersectScene(bvh, o, d, 0.0f, INFINITY, skip, only);
    const RayHit got = walk.trace(packed.header, o, d, skip, only);
    ASSERT_EQ(got.instance, want.instance) << "ray " << r;
    EXPECT_EQ(got.t, want.t) << "ray " << r;
    if (want.instance >= 0) {
      EXPECT_EQ(got.slot - (want.instance == 0 ? 0 : 2), want.slot) << "ray " << r;
    }
    const RayHit phong = walk.trace(packed.phongHeader, o, d, 3, only);
    const RayHit phongWant = intersectScene(bvh, o, d, 0.0f, INFINITY, 3, only);
    ASSERT_EQ(phong.instance, phongWant.instance) << "ray " << r;
    EXPECT_EQ(phong.t, phongWant.t) << "ray " << r;
    grounds += phong.instance == 0;
    figures += phong.instance == 1 || phong.instance == 2;
  }
  EXPECT_GT(grounds, 250);
  EXPECT_GT(figures, 250);
}

TEST(Bvh, TheWalksStackHoldsTheDeepestPathOfBothLevels) {
  // A path meets at most objects - 1 interior nodes of the top level and depth - 1 of a tree.
  EXPECT_EQ(traceStackFor(4, 15), 24);  // 3 + 14, in steps of 8
  EXPECT_EQ(traceStackFor(1, 1), 8);
  EXPECT_EQ(traceStackFor(0, 0), 8);
  EXPECT_EQ(traceStackFor(9, 9), 16);
  EXPECT_EQ(traceStackFor(100, 20), 2 * kBvhMaxDepth + 2);  // never more than both full levels
  EXPECT_EQ(traceStackFor(1, 99), 32);                      // a tree is at most kBvhMaxDepth
  // The walk on the CPU, whose stack grows as it needs, never needs more: a skewed scene of
  // many objects in a row and a deep mesh, every ray through all of them.
  const MeshData strip = randomTriangles(2000, 3);
  const auto tree = std::make_shared<const MeshBvh>(buildMeshBvh(shared(strip)));
  std::vector<BvhInstance> instances(12);
  for (size_t i = 0; i < instances.size(); ++i) {
    instances[i].mesh = tree;
    instances[i].model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -3.0f * float(i)));
    instances[i].inverse = glm::inverse(instances[i].model);
  }
  BvhAtlas atlas;
  atlas.add("m", tree);
  Scene scene;
  scene.objects.resize(instances.size());
  const std::vector<PackedRef> roots(instances.size(), atlas.roots().at("m").ref);
  const int first = static_cast<int>(atlas.texelCount());
  const PackedScene packed = packScene(scene, buildSceneBvh(instances), roots, {}, first);
  std::vector<float> texels = allTexels(atlas);
  texels.insert(texels.end(), packed.traversal.begin(), packed.traversal.end());
  const PackedWalk walk{texels};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> at(-1.0f, 1.0f);
  for (int r = 0; r < 500; ++r) {
    const glm::vec3 d = glm::normalize(glm::vec3(0.1f * at(rng), 0.1f * at(rng), -1.0f));
    walk.trace(packed.header, glm::vec3(at(rng), at(rng), 10.0f), d);
  }
  EXPECT_GT(walk.deepest, 4u);
  EXPECT_LE(walk.deepest, static_cast<size_t>(traceStackFor(instances.size(), tree->tree.depth)));
}

TEST(Bvh, NoPhongObjectLeavesThePhongTopLevelEmpty) {
  const auto mesh = std::make_shared<const MeshBvh>(buildMeshBvh(shared(randomTriangles(20, 8))));
  BvhAtlas atlas;
  atlas.add("m", mesh);
  Scene scene;
  scene.objects.resize(2);
  scene.objects[0].material = Material::Mirror;
  scene.objects[1].material = Material::Glass;
  std::vector<BvhInstance> instances(2);
  for (BvhInstance& i : instances) i.mesh = mesh;
  const std::vector<PackedRef> roots(2, atlas.roots().at("m").ref);
  const PackedScene packed =
      packScene(scene, buildSceneBvh(instances), roots, {}, static_cast<int>(atlas.texelCount()));
  EXPECT_FALSE(packed.empty);
  EXPECT_TRUE(packed.phongEmpty);
}

TEST(Bvh, ALeafOfSeveralObjectsIsSplitIntoSlots) {
  // Identical boxes past the depth limit would leave a top-level leaf of several objects; the
  // packer gives each its own slot. Forty objects in one place, a ray through them all.
  const auto mesh = std::make_shared<const MeshBvh>(buildMeshBvh(shared(randomTriangles(20, 8))));
  BvhAtlas atlas;
  atlas.add("m", mesh);
  Scene scene;
  std::vector<BvhInstance> instances(40);
  for (BvhInstance& i : instances) {
    scene.objects.push_back({});
    i.mesh = mesh;
  }
  SceneBvh bvh = buildSceneBvh(instances);
  // Force the worst case: one leaf holding every object.
  bvh.top.nodes.resize(1);
  bvh.top.nodes[0].first = 0;
  bvh.top.nodes[0].count = 40;
  const std::vector<PackedRef> roots(40, atlas.roots().at("m").ref);
  const int first = static_cast<int>(atlas.texelCount());
  const PackedScene packed = packScene(scene, bvh, roots, {}, first);
  std::vector<float> texels = allTexels(atlas);
  texels.insert(texels.end(), packed.traversal.begin(), packed.traversal.end());
  const PackedWalk walk{texels};
  for (int r = 0; r < 200; ++r) {
    const glm::vec3 o(0.013f * static_cast<float>(r) - 1.3f, 0.2f, 3.0f);
    const RayHit want = intersectScene(bvh, o, glm::vec3(0, 0, -1));
    const RayHit got = walk.trace(packed.header, o, glm::vec3(0, 0, -1));
    EXPECT_EQ(got.t, want.t) << "ray " << r;
    EXPECT_EQ(got.instance >= 0, want.instance >= 0) << "ray " << r;
  }
}

}  // namespace
}  // namespace reflect
