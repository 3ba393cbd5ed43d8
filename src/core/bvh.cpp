#include "core/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/frustum.h"
#include "core/normal_matrix.h"

namespace reflect {
namespace {

constexpr int kBins = 16;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

Bounds emptyBounds() {
  return {glm::vec3(kInfinity), glm::vec3(-kInfinity)};
}
void grow(Bounds& b, const Bounds& o) {
  b.min = glm::min(b.min, o.min);
  b.max = glm::max(b.max, o.max);
}
float halfArea(const Bounds& b) {
  const glm::vec3 e = glm::max(b.max - b.min, glm::vec3(0.0f));
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

struct Builder {
  const std::vector<Bounds>& boxes;
  std::vector<glm::vec3> centroids;
  Bvh& out;
  int maxLeaf;

  void build(size_t nodeIndex, uint32_t first, uint32_t count, int depth) {
    out.depth = std::max(out.depth, depth);
    Bounds bounds = emptyBounds(), centres = emptyBounds();
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t item = out.order[i];
      grow(bounds, boxes[item]);
      grow(centres, {centroids[item], centroids[item]});
    }
    out.nodes[nodeIndex].min = bounds.min;
    out.nodes[nodeIndex].max = bounds.max;
    const auto leaf = [&] {
      out.nodes[nodeIndex].first = first;
      out.nodes[nodeIndex].count = count;
    };
    if (count <= static_cast<uint32_t>(maxLeaf) || depth >= kBvhMaxDepth) return leaf();

    // The cheapest of the bins' split planes on the three axes (surface area heuristic).
    float bestCost = kInfinity;
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centres.min[axis], extent = centres.max[axis] - lo;
      if (!(extent > 0.0f)) continue;
      std::array<Bounds, kBins> binBounds;
      std::array<uint32_t, kBins> binCount{};
      binBounds.fill(emptyBounds());
      const float scale = kBins / extent;
      for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t item = out.order[i];
        const int b = std::min(kBins - 1, static_cast<int>((centroids[item][axis] - lo) * scale));
        ++binCount[static_cast<size_t>(b)];
        grow(binBounds[static_cast<size_t>(b)], boxes[item]);
      }
      std::array<float, kBins> rightCost{};
      Bounds right = emptyBounds();
      uint32_t rightCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        grow(right, binBounds[static_cast<size_t>(b)]);
        rightCount += binCount[static_cast<size_t>(b)];
        rightCost[static_cast<size_t>(b)] = rightCount ? halfArea(right) * rightCount : 0.0f;
      }
      Bounds left = emptyBounds();
      uint32_t leftCount = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        grow(left, binBounds[static_cast<size_t>(b)]);
        leftCount += binCount[static_cast<size_t>(b)];
        if (leftCount == 0 || leftCount == count) continue;
        const float cost = halfArea(left) * leftCount + rightCost[static_cast<size_t>(b + 1)];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = b;
        }
      }
    }
    uint32_t middle = 0;
    if (bestAxis >= 0) {
      const float lo = centres.min[bestAxis];
      const float scale = kBins / (centres.max[bestAxis] - lo);
      auto* begin = out.order.data() + first;
      auto* split = std::partition(begin, begin + count, [&](uint32_t item) {
        return std::min(kBins - 1, static_cast<int>((centroids[item][bestAxis] - lo) * scale)) <=
               bestSplit;
      });
      middle = static_cast<uint32_t>(split - begin);
    }
    if (middle == 0 || middle == count) middle = count / 2;  // one centroid for all: halve them

    const size_t left = out.nodes.size();
    out.nodes.emplace_back();
    out.nodes.emplace_back();
    out.nodes[nodeIndex].first = static_cast<uint32_t>(left);
    out.nodes[nodeIndex].count = 0;
    build(left, first, middle, depth + 1);
    build(left + 1, first + middle, count - middle, depth + 1);
  }
};

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

Bvh buildBvh(const std::vector<Bounds>& boxes, int maxLeaf) {
  Bvh out;
  if (boxes.empty()) return out;
  out.order.resize(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) out.order[i] = static_cast<uint32_t>(i);
  Builder builder{boxes, {}, out, std::max(maxLeaf, 1)};
  builder.centroids.reserve(boxes.size());
  for (const Bounds& b : boxes) builder.centroids.push_back(b.centre());
  out.nodes.reserve(boxes.size() * 2);
  out.nodes.emplace_back();
  builder.build(0, 0, static_cast<uint32_t>(boxes.size()), 1);
  return out;
}

MeshBvh buildMeshBvh(const MeshData& mesh) {
  const size_t count = mesh.triangleCount();
  std::vector<Bounds> boxes(count);
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3& a = mesh.vertices[mesh.indices[i * 3]].position;
    const glm::vec3& b = mesh.vertices[mesh.indices[i * 3 + 1]].position;
    const glm::vec3& c = mesh.vertices[mesh.indices[i * 3 + 2]].position;
    boxes[i] = {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
  }
  MeshBvh m;
  m.tree = buildBvh(boxes);
  m.positions.reserve(count * 3);
  m.normals.reserve(count * 3);
  m.triangles = m.tree.order;
  for (uint32_t triangle : m.tree.order) {
    for (int k = 0; k < 3; ++k) {
      const Vertex& v = mesh.vertices[mesh.indices[static_cast<size_t>(triangle) * 3 + k]];
      m.positions.push_back(v.position);
      m.normals.push_back(v.normal);
    }
  }
  return m;
}

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

SceneBvh buildSceneBvh(std::vector<BvhInstance> instances) {
  SceneBvh scene;
  std::vector<Bounds> boxes;
  std::vector<uint32_t> traced;
  for (size_t i = 0; i < instances.size(); ++i) {
    const BvhInstance& instance = instances[i];
    if (!instance.mesh || instance.mesh->tree.nodes.empty()) continue;
    const BvhNode& root = instance.mesh->tree.nodes[0];
    boxes.push_back(transformBounds({root.min, root.max}, instance.model));
    traced.push_back(static_cast<uint32_t>(i));
  }
  scene.top = buildBvh(boxes, 1);
  for (uint32_t& item : scene.top.order) item = traced[item];
  scene.instances = std::move(instances);
  return scene;
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
          if (intersectTriangle(o, d, mesh.positions[s * 3], mesh.positions[s * 3 + 1],
                                mesh.positions[s * 3 + 2], tMin, best.t, &t, &u, &v)) {
            best.t = t;
            best.instance = index;
            best.slot = static_cast<int>(s);
            best.triangle = static_cast<int>(mesh.triangles[s]);
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

namespace {

void pushTexel(std::vector<float>& t, const glm::vec3& v, float w) {
  t.insert(t.end(), {v.x, v.y, v.z, w});
}

// A child's two texels in its parent's node: (min, ref texel), (max, ref count).
void pushChild(std::vector<float>& t, const Bounds& box, const PackedRef& ref) {
  pushTexel(t, box.min, static_cast<float>(ref.texel));
  pushTexel(t, box.max, static_cast<float>(ref.count));
}

}  // namespace

void BvhAtlas::add(const std::string& name, const MeshBvh& mesh) {
  const std::vector<BvhNode>& nodes = mesh.tree.nodes;
  if (nodes.empty()) return;
  // Interior nodes first, each kNodeTexels, in the tree's order; then the triangles.
  const int base = static_cast<int>(texels.size() / 4);
  std::vector<int> nodeTexel(nodes.size(), -1);
  int interior = 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].count == 0) nodeTexel[i] = base + kNodeTexels * interior++;
  }
  const int firstTriangle = base + kNodeTexels * interior;
  const auto refOf = [&](size_t i) {
    const BvhNode& n = nodes[i];
    if (n.count > 0) {
      return PackedRef{firstTriangle + kTriangleTexels * static_cast<int>(n.first),
                       static_cast<int>(n.count)};
    }
    return PackedRef{nodeTexel[i], 0};
  };
  for (const BvhNode& n : nodes) {
    if (n.count > 0) continue;
    for (uint32_t child : {n.first, n.first + 1}) {
      pushChild(texels, {nodes[child].min, nodes[child].max}, refOf(child));
    }
  }
  for (size_t s = 0; s < mesh.triangleCount(); ++s) {
    const glm::vec3& v0 = mesh.positions[s * 3];
    pushTexel(texels, v0, static_cast<float>(triangles + static_cast<int>(s)));
    pushTexel(texels, mesh.positions[s * 3 + 1] - v0, 0.0f);
    pushTexel(texels, mesh.positions[s * 3 + 2] - v0, 0.0f);
    for (int k = 0; k < 3; ++k) pushTexel(normals, mesh.normals[s * 3 + k], 0.0f);
  }
  roots[name] = {refOf(0), {nodes[0].min, nodes[0].max}};
  triangles += static_cast<int>(mesh.triangleCount());
}

namespace {

// The top level in the atlas's layout: each interior node's texels written where it was placed,
// every leaf a placed object's slot. A leaf of several objects (the build's depth limit) becomes
// a small subtree of its own, so every leaf reference is one slot.
struct TopPacker {
  const SceneBvh& bvh;
  const std::vector<Bounds>& worldBoxes;  // by object index
  int firstNode = 0;                      // texel of the first interior node
  int slots = 0;                          // texel of object 0's slot
  std::vector<float> nodes;

  Bounds boxOf(const uint32_t* items, size_t count) const {
    Bounds b = worldBoxes[items[0]];
    for (size_t k = 1; k < count; ++k) {
      b.min = glm::min(b.min, worldBoxes[items[k]].min);
      b.max = glm::max(b.max, worldBoxes[items[k]].max);
    }
    return b;
  }
  PackedRef place(const Bounds& leftBox, const PackedRef& left, const Bounds& rightBox,
                  const PackedRef& right, size_t at) {
    std::vector<float> node;
    pushChild(node, leftBox, left);
    pushChild(node, rightBox, right);
    std::copy(node.begin(), node.end(), nodes.begin() + static_cast<std::ptrdiff_t>(at));
    return {firstNode + static_cast<int>(at / 4), 0};
  }
  size_t reserve() {
    nodes.resize(nodes.size() + kNodeTexels * 4, 0.0f);
    return nodes.size() - kNodeTexels * 4;
  }
  PackedRef items(const uint32_t* first, size_t count) {
    if (count == 1) return {slots + kSlotTexels * static_cast<int>(first[0]), kInstanceRef};
    const size_t at = reserve();
    const size_t half = count / 2;
    const PackedRef left = items(first, half), right = items(first + half, count - half);
    return place(boxOf(first, half), left, boxOf(first + half, count - half), right, at);
  }
  PackedRef node(uint32_t index) {
    const BvhNode& n = bvh.top.nodes[index];
    if (n.count > 0) return items(bvh.top.order.data() + n.first, n.count);
    const size_t at = reserve();
    const PackedRef left = node(n.first), right = node(n.first + 1);
    const BvhNode& l = bvh.top.nodes[n.first];
    const BvhNode& r = bvh.top.nodes[n.first + 1];
    return place({l.min, l.max}, left, {r.min, r.max}, right, at);
  }
};

}  // namespace

PackedScene packScene(const Scene& scene, const SceneBvh& bvh, const std::vector<PackedRef>& roots,
                      const std::vector<glm::vec3>& probeCentres, int firstTexel) {
  PackedScene packed;
  const size_t count = scene.objects.size();
  packed.instances = static_cast<int>(count);
  packed.header = firstTexel;
  std::vector<float>& s = packed.shading;
  std::vector<Bounds> worldBoxes(count);
  std::vector<float> slots;
  for (size_t i = 0; i < count; ++i) {
    const SceneObject& o = scene.objects[i];
    const BvhInstance* instance = i < bvh.instances.size() ? &bvh.instances[i] : nullptr;
    const glm::mat4 model = instance ? instance->model : glm::mat4(1.0f);
    const glm::mat4 inverse = instance ? instance->inverse : glm::mat4(1.0f);
    const glm::mat3 normal = normalMatrixOf(glm::mat3(model));
    for (int column = 0; column < 3; ++column) pushTexel(s, normal[column], 0.0f);
    pushTexel(s, o.colour, static_cast<float>(static_cast<int>(o.material)));
    s.insert(s.end(), {o.reflection, o.base, std::max(o.ior, 1e-3f), o.fresnel ? 1.0f : 0.0f});
    const glm::vec3 centre = i < probeCentres.size() ? probeCentres[i] : glm::vec3(0.0f);
    pushTexel(s, centre, 0.0f);
    float epsilon = 1e-7f;
    if (instance && instance->mesh && !instance->mesh->tree.nodes.empty()) {
      const BvhNode& r = instance->mesh->tree.nodes[0];
      worldBoxes[i] = transformBounds({r.min, r.max}, model);
      epsilon = std::max(1e-5f * glm::length(worldBoxes[i].max - worldBoxes[i].min), 1e-7f);
    }
    pushTexel(s, glm::vec3(epsilon, 0.0f, 0.0f), 0.0f);
    for (int row = 0; row < 3; ++row) {
      const glm::vec4 r(inverse[0][row], inverse[1][row], inverse[2][row], inverse[3][row]);
      pushTexel(slots, glm::vec3(r), r.w);
      pushTexel(s, glm::vec3(r), r.w);
    }
    const PackedRef root = i < roots.size() ? roots[i] : PackedRef{-1, 0};
    slots.insert(slots.end(), {static_cast<float>(root.texel), static_cast<float>(root.count),
                               static_cast<float>(i), 0.0f});
  }
  packed.empty = bvh.top.nodes.empty();
  TopPacker top{bvh, worldBoxes, 0, 0, {}};
  top.slots = firstTexel + kStepTexels;
  top.firstNode = top.slots + kSlotTexels * static_cast<int>(count);
  PackedRef root{-1, 0};
  Bounds rootBox{glm::vec3(0.0f), glm::vec3(0.0f)};
  if (!packed.empty) {
    root = top.node(0);
    rootBox = {bvh.top.nodes[0].min, bvh.top.nodes[0].max};
  }
  std::vector<float>& t = packed.traversal;
  pushChild(t, rootBox, root);
  t.resize(kStepTexels * 4, 0.0f);
  t.insert(t.end(), slots.begin(), slots.end());
  t.insert(t.end(), top.nodes.begin(), top.nodes.end());
  return packed;
}

}  // namespace reflect
