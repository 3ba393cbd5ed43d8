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
  // An item's centroid, from its box each time: a figure of the course's weight would keep
  // 1.9 MB of them through the build, and WebAssembly's heap keeps its largest size.
  glm::vec3 centroid(uint32_t item) const { return boxes[item].centre(); }
  Bvh& out;
  int maxLeaf;

  // `bounds`: the items' boxes together; `centres`: their centroids' bounds (the caller knows
  // both: the root's from one pass, a child's from its side of the parent's bins).
  void build(size_t nodeIndex, uint32_t first, uint32_t count, int depth, const Bounds& bounds,
             const Bounds& centres) {
    out.depth = std::max(out.depth, depth);
    out.nodes[nodeIndex].min = bounds.min;
    out.nodes[nodeIndex].max = bounds.max;
    const auto leaf = [&] {
      out.nodes[nodeIndex].first = first;
      out.nodes[nodeIndex].count = count;
    };
    if (count <= static_cast<uint32_t>(maxLeaf) || depth >= kBvhMaxDepth) return leaf();

    // One pass bins every item on the three axes at once.
    struct Bin {
      Bounds box = emptyBounds(), centres = emptyBounds();
      uint32_t count = 0;
    };
    std::array<std::array<Bin, kBins>, 3> bins;
    glm::vec3 scale(0.0f);
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centres.max[axis] - centres.min[axis];
      scale[axis] = extent > 0.0f ? kBins / extent : 0.0f;
    }
    const auto binOf = [&](const glm::vec3& c, int axis) {
      return std::min(kBins - 1, static_cast<int>((c[axis] - centres.min[axis]) * scale[axis]));
    };
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t item = out.order[i];
      const glm::vec3 c = centroid(item);
      for (int axis = 0; axis < 3; ++axis) {
        if (scale[axis] == 0.0f) continue;
        Bin& b = bins[static_cast<size_t>(axis)][static_cast<size_t>(binOf(c, axis))];
        ++b.count;
        grow(b.box, boxes[item]);
        grow(b.centres, {c, c});
      }
    }

    // The cheapest of the bins' split planes on the three axes (surface area heuristic).
    float bestCost = kInfinity;
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (scale[axis] == 0.0f) continue;
      const std::array<Bin, kBins>& b = bins[static_cast<size_t>(axis)];
      std::array<float, kBins> rightCost{};
      Bounds right = emptyBounds();
      uint32_t rightCount = 0;
      for (int k = kBins - 1; k > 0; --k) {
        grow(right, b[static_cast<size_t>(k)].box);
        rightCount += b[static_cast<size_t>(k)].count;
        rightCost[static_cast<size_t>(k)] = rightCount ? halfArea(right) * rightCount : 0.0f;
      }
      Bounds left = emptyBounds();
      uint32_t leftCount = 0;
      for (int k = 0; k < kBins - 1; ++k) {
        grow(left, b[static_cast<size_t>(k)].box);
        leftCount += b[static_cast<size_t>(k)].count;
        if (leftCount == 0 || leftCount == count) continue;
        const float cost = halfArea(left) * leftCount + rightCost[static_cast<size_t>(k + 1)];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = k;
        }
      }
    }
    uint32_t middle = 0;
    Bounds leftBox = emptyBounds(), leftCentres = emptyBounds();
    Bounds rightBox = emptyBounds(), rightCentres = emptyBounds();
    if (bestAxis >= 0) {
      auto* begin = out.order.data() + first;
      auto* split = std::partition(begin, begin + count, [&](uint32_t item) {
        return binOf(centroid(item), bestAxis) <= bestSplit;
      });
      middle = static_cast<uint32_t>(split - begin);
      for (int k = 0; k < kBins; ++k) {
        const Bin& b = bins[static_cast<size_t>(bestAxis)][static_cast<size_t>(k)];
        grow(k <= bestSplit ? leftBox : rightBox, b.box);
        grow(k <= bestSplit ? leftCentres : rightCentres, b.centres);
      }
    }
    if (middle == 0 || middle == count) {  // one centroid for all: halve them
      middle = count / 2;
      leftBox = leftCentres = rightBox = rightCentres = emptyBounds();
      for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t item = out.order[i];
        const bool isLeft = i < first + middle;
        grow(isLeft ? leftBox : rightBox, boxes[item]);
        const glm::vec3 c = centroid(item);
        grow(isLeft ? leftCentres : rightCentres, {c, c});
      }
    }

    const size_t left = out.nodes.size();
    out.nodes.emplace_back();
    out.nodes.emplace_back();
    out.nodes[nodeIndex].first = static_cast<uint32_t>(left);
    out.nodes[nodeIndex].count = 0;
    build(left, first, middle, depth + 1, leftBox, leftCentres);
    build(left + 1, first + middle, count - middle, depth + 1, rightBox, rightCentres);
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
  Builder builder{boxes, out, std::max(maxLeaf, 1)};
  // About 0.62 nodes a triangle with leaves of up to 4: one allocation, no regrowth.
  out.nodes.reserve(boxes.size() * 7 / 10 + 1);
  out.nodes.emplace_back();
  Bounds bounds = emptyBounds(), centres = emptyBounds();
  for (size_t i = 0; i < boxes.size(); ++i) {
    grow(bounds, boxes[i]);
    const glm::vec3 c = builder.centroid(static_cast<uint32_t>(i));
    grow(centres, {c, c});
  }
  builder.build(0, 0, static_cast<uint32_t>(boxes.size()), 1, bounds, centres);
  out.nodes.shrink_to_fit();
  return out;
}

MeshBvh buildMeshBvh(std::shared_ptr<const MeshData> mesh) {
  MeshBvh m;
  if (!mesh) return m;
  const size_t count = mesh->triangleCount();
  {
    std::vector<Bounds> boxes(count);
    for (size_t i = 0; i < count; ++i) {
      const glm::vec3& a = mesh->vertices[mesh->indices[i * 3]].position;
      const glm::vec3& b = mesh->vertices[mesh->indices[i * 3 + 1]].position;
      const glm::vec3& c = mesh->vertices[mesh->indices[i * 3 + 2]].position;
      boxes[i] = {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
    }
    m.tree = buildBvh(boxes);
  }
  m.corners.resize(count * 3);
  for (size_t s = 0; s < count; ++s) {
    for (size_t k = 0; k < 3; ++k) {
      m.corners[s * 3 + k] = mesh->indices[static_cast<size_t>(m.tree.order[s]) * 3 + k];
    }
  }
  m.mesh = std::move(mesh);
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

void BvhAtlas::add(const std::string& name, std::shared_ptr<const MeshBvh> mesh) {
  if (!mesh || mesh->tree.nodes.empty()) return;
  const std::vector<BvhNode>& nodes = mesh->tree.nodes;
  Part part;
  part.base = texels_;
  part.firstSlot = triangles_;
  part.nodeTexel.assign(nodes.size(), -1);
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].count > 0) continue;
    part.nodeTexel[i] = static_cast<int>(part.base + kNodeTexels * part.interiorNodes.size());
    part.interiorNodes.push_back(static_cast<uint32_t>(i));
  }
  part.triangles = part.base + kNodeTexels * part.interiorNodes.size();
  part.mesh = std::move(mesh);
  texels_ = part.triangles + kTriangleTexels * part.mesh->triangleCount();
  triangles_ += static_cast<int>(part.mesh->triangleCount());
  roots_[name] = {refOf(part, 0), {nodes[0].min, nodes[0].max}};
  parts_.push_back(std::move(part));
}

PackedRef BvhAtlas::refOf(const Part& part, uint32_t node) const {
  const BvhNode& n = part.mesh->tree.nodes[node];
  if (n.count > 0) {
    return PackedRef{static_cast<int>(part.triangles + kTriangleTexels * n.first),
                     static_cast<int>(n.count)};
  }
  return PackedRef{part.nodeTexel[node], 0};
}

namespace {

void putTexel(float* out, const glm::vec3& v, float w) {
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
  out[3] = w;
}

}  // namespace

void BvhAtlas::writeTexels(size_t first, size_t count, float* out) const {
  std::fill(out, out + 4 * count, 0.0f);
  const size_t end = first + count;
  for (const Part& part : parts_) {
    const size_t partEnd = part.triangles + kTriangleTexels * part.mesh->triangleCount();
    if (partEnd <= first || part.base >= end) continue;
    const std::vector<BvhNode>& nodes = part.mesh->tree.nodes;
    for (size_t t = std::max(first, part.base); t < std::min(end, partEnd); ++t) {
      float* texel = out + 4 * (t - first);
      if (t < part.triangles) {  // an interior node: (min, ref), (max, count) of each child
        const size_t k = (t - part.base) / kNodeTexels, within = (t - part.base) % kNodeTexels;
        const uint32_t child = nodes[part.interiorNodes[k]].first + (within >= 2 ? 1 : 0);
        const PackedRef ref = refOf(part, child);
        if (within % 2 == 0) {
          putTexel(texel, nodes[child].min, static_cast<float>(ref.texel));
        } else {
          putTexel(texel, nodes[child].max, static_cast<float>(ref.count));
        }
      } else {  // a triangle: v0 (w: its slot), v1 - v0, v2 - v0
        const size_t s = (t - part.triangles) / kTriangleTexels;
        const int k = static_cast<int>((t - part.triangles) % kTriangleTexels);
        const glm::vec3& v0 = part.mesh->corner(s, 0).position;
        if (k == 0) {
          putTexel(texel, v0, static_cast<float>(part.firstSlot + static_cast<int>(s)));
        } else {
          putTexel(texel, part.mesh->corner(s, k).position - v0, 0.0f);
        }
      }
    }
  }
}

void BvhAtlas::writeNormals(size_t first, size_t count, float* out) const {
  std::fill(out, out + 4 * count, 0.0f);
  const size_t end = first + count;
  for (const Part& part : parts_) {
    const size_t partFirst = 3 * static_cast<size_t>(part.firstSlot);
    const size_t partEnd = partFirst + 3 * part.mesh->triangleCount();
    for (size_t t = std::max(first, partFirst); t < std::min(end, partEnd); ++t) {
      const size_t s = (t - partFirst) / 3;
      putTexel(out + 4 * (t - first),
               part.mesh->corner(s, static_cast<int>((t - partFirst) % 3)).normal, 0.0f);
    }
  }
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
