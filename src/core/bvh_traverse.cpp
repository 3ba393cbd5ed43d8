// The BVH traversal on the CPU (core/bvh.h): a stack, nearer child first, the same steps as the
// shader's walk (shaders/exact_trace.glsl); the reference tests check its hits against Embree.
#include "core/bvh.h"
#include "core/float_limits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace reflect {
namespace {

// 1 / d with zero components made tiny, so the slabs never compute 0 * infinity.
glm::vec3 inverseDirection(const glm::vec3& d) {
  glm::vec3 r;
  for (int i = 0; i < 3; ++i) {
    const float c = std::abs(d[i]) < 1e-20f ? std::copysign(1e-20f, d[i]) : d[i];
    r[i] = 1.0f / c;
  }
  return r;
}

// Where the ray enters the node's box within [tMin, tMax], or infinity when it misses it.
float boxEntry(const BvhNode& n, const glm::vec3& o, const glm::vec3& invD, float tMin,
               float tMax) {
  const glm::vec3 t0 = (n.min - o) * invD, t1 = (n.max - o) * invD;
  const glm::vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
  const float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, tMin));
  const float leave = std::min(std::min(hi.x, hi.y), std::min(hi.z, tMax));
  return enter <= leave ? enter : kInfinity;
}

// Walks `tree` nearer child first; `leafItems(first, count)` tests a leaf's items.
template <class LeafTest>
void traverse(const Bvh& tree, const glm::vec3& o, const glm::vec3& d, float tMin,
              const float& tBest, LeafTest leafItems) {
  if (tree.nodes.empty()) return;
  const glm::vec3 invD = inverseDirection(d);
  if (boxEntry(tree.nodes[0], o, invD, tMin, tBest) == kInfinity) return;
  std::array<uint32_t, kBvhMaxDepth + 1> stack{};
  std::array<float, kBvhMaxDepth + 1> entries{};
  int top = 0;
  uint32_t node = 0;
  for (;;) {
    const BvhNode& n = tree.nodes[node];
    bool descended = false;
    if (n.count > 0) {
      leafItems(n.first, n.count);
    } else {
      const float tl = boxEntry(tree.nodes[n.first], o, invD, tMin, tBest);
      const float tr = boxEntry(tree.nodes[n.first + 1], o, invD, tMin, tBest);
      if (tl != kInfinity || tr != kInfinity) {
        const bool leftFirst = tl <= tr;
        node = leftFirst ? n.first : n.first + 1;
        const float farEntry = leftFirst ? tr : tl;
        if (farEntry != kInfinity) {
          stack[static_cast<size_t>(top)] = leftFirst ? n.first + 1 : n.first;
          entries[static_cast<size_t>(top)] = farEntry;
          ++top;
        }
        descended = true;
      }
    }
    if (descended) continue;
    // The nearest pushed node that the best hit so far has not ruled out.
    bool found = false;
    while (top > 0) {
      --top;
      if (entries[static_cast<size_t>(top)] <= tBest) {
        node = stack[static_cast<size_t>(top)];
        found = true;
        break;
      }
    }
    if (!found) return;
  }
}

}  // namespace

bool intersectTriangle(const glm::vec3& o, const glm::vec3& d, const glm::vec3& v0,
                       const glm::vec3& v1, const glm::vec3& v2, float tMin, float tMax, float* t,
                       float* u, float* v) {
  const glm::vec3 e1 = v1 - v0, e2 = v2 - v0;
  const glm::vec3 p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (det == 0.0f) return false;
  const float inv = 1.0f / det;
  const glm::vec3 s = o - v0;
  const float bu = glm::dot(s, p) * inv;
  if (bu < 0.0f || bu > 1.0f) return false;
  const glm::vec3 q = glm::cross(s, e1);
  const float bv = glm::dot(d, q) * inv;
  if (bv < 0.0f || bu + bv > 1.0f) return false;
  const float bt = glm::dot(e2, q) * inv;
  if (!(bt > tMin && bt < tMax)) return false;
  *t = bt;
  *u = bu;
  *v = bv;
  return true;
}

RayHit intersectScene(const SceneBvh& scene, const glm::vec3& origin, const glm::vec3& direction,
                      float tMin, float tMax, int skip, int only) {
  RayHit best;
  best.t = tMax;
  traverse(scene.top, origin, direction, tMin, best.t, [&](uint32_t first, uint32_t count) {
    for (uint32_t k = first; k < first + count; ++k) {
      const int index = static_cast<int>(scene.top.order[k]);
      if (index == skip || (only >= 0 && index != only)) continue;
      const BvhInstance& instance = scene.instances[static_cast<size_t>(index)];
      const MeshBvh& mesh = *instance.mesh;
      const glm::vec3 o(instance.inverse * glm::vec4(origin, 1.0f));
      const glm::vec3 d(glm::mat3(instance.inverse) * direction);
      traverse(mesh.tree, o, d, tMin, best.t, [&](uint32_t firstTriangle, uint32_t triangles) {
        for (uint32_t s = firstTriangle; s < firstTriangle + triangles; ++s) {
          float t, u, v;
          if (intersectTriangle(o, d, mesh.corner(s, 0).position, mesh.corner(s, 1).position,
                                mesh.corner(s, 2).position, tMin, best.t, &t, &u, &v)) {
            best.t = t;
            best.instance = index;
            best.slot = static_cast<int>(s);
            best.triangle = static_cast<int>(mesh.tree.order[s]);
            best.u = u;
            best.v = v;
          }
        }
      });
    }
  });
  if (best.instance < 0) best.t = kInfinity;
  return best;
}

}  // namespace reflect
