// The per-frame part of the shader's textures (core/bvh.h): the top level over the placed
// objects, their slots and what the shading needs of each, packed after the atlas.
#include "core/bvh.h"

#include <algorithm>
#include <array>
#include <optional>

#include "core/frustum.h"
#include "core/normal_matrix.h"

namespace reflect {
namespace {

void pushTexel(std::vector<float>& t, const glm::vec3& v, float w) {
  t.insert(t.end(), {v.x, v.y, v.z, w});
}

// A child's two texels in its parent's node: (min, ref texel), (max, ref count).
void pushChild(std::vector<float>& t, const Bounds& box, const PackedRef& ref) {
  pushTexel(t, box.min, static_cast<float>(ref.texel));
  pushTexel(t, box.max, static_cast<float>(ref.count));
}

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

// Packs `bvh`'s top level: its header (the root's box and reference, kStepTexels texels) onto
// `header`, and returns its interior nodes, to be placed at texel `firstNode`; every leaf refers
// to its object's slot, object i's at `slotsTexel` + kSlotTexels i.
std::vector<float> packTop(const SceneBvh& bvh, const std::vector<Bounds>& worldBoxes,
                           int slotsTexel, int firstNode, std::vector<float>& header) {
  TopPacker top{bvh, worldBoxes, firstNode, slotsTexel, {}};
  PackedRef root{-1, 0};
  Bounds rootBox{glm::vec3(0.0f), glm::vec3(0.0f)};
  if (!bvh.top.nodes.empty()) {
    root = top.node(0);
    rootBox = {bvh.top.nodes[0].min, bvh.top.nodes[0].max};
  }
  const size_t start = header.size();
  pushChild(header, rootBox, root);
  header.resize(start + kStepTexels * 4, 0.0f);
  return top.nodes;
}

// The object a top level's rays test before their walk (-1: none): of `instances`' traced
// objects whose tree is a single leaf of at most kTestedTriangles (a quad, a few triangles), the
// one whose world box has the largest surface (in the shipped scenes, the ground).
int testedObject(const std::vector<BvhInstance>& instances, const std::vector<PackedRef>& roots,
                 const std::vector<Bounds>& worldBoxes) {
  int best = -1;
  float bestArea = -1.0f;
  for (size_t i = 0; i < instances.size() && i < roots.size(); ++i) {
    if (!instances[i].mesh || roots[i].count <= 0 || roots[i].count > kTestedTriangles) continue;
    const glm::vec3 size = worldBoxes[i].max - worldBoxes[i].min;
    const float area = size.x * size.y + size.y * size.z + size.z * size.x;
    if (area > bestArea) {
      bestArea = area;
      best = static_cast<int>(i);
    }
  }
  return best;
}

struct TopLevel {
  std::vector<float> header;  // kStepTexels
  std::vector<float> nodes;
  bool empty = true;  // nothing to test and nothing to walk
};

// A top level over `instances`' objects with a mesh (`bvh`, built over them, or null to build it
// here), but the one it tests first: that one leaves the tree and goes in the header's last two
// texels (its world box and slot), where the walk tests its triangles before the tree, so the
// tree's walk starts with the nearest hit the ground gives. Interior nodes from texel `firstNode`.
TopLevel packTopLevel(std::vector<BvhInstance> instances, const SceneBvh* bvh,
                      const std::vector<PackedRef>& roots, const std::vector<Bounds>& worldBoxes,
                      int slotsTexel, int firstNode) {
  const int tested = testedObject(instances, roots, worldBoxes);
  if (tested >= 0) instances[static_cast<size_t>(tested)].mesh.reset();
  std::optional<SceneBvh> built;
  if (!bvh || tested >= 0) bvh = &built.emplace(buildSceneBvh(std::move(instances)));
  TopLevel top;
  top.nodes = packTop(*bvh, worldBoxes, slotsTexel, firstNode, top.header);
  top.empty = bvh->top.nodes.empty() && tested < 0;
  if (tested >= 0) {
    const Bounds& box = worldBoxes[static_cast<size_t>(tested)];
    const float slot = static_cast<float>(slotsTexel + kSlotTexels * tested);
    const std::array<float, 8> texels{box.min.x, box.min.y, box.min.z, slot,
                                      box.max.x, box.max.y, box.max.z, 1.0f};
    std::copy(texels.begin(), texels.end(), top.header.begin() + 2 * 4);
  }
  return top;
}

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
  const int slotsTexel = firstTexel + kStepTexels;
  std::vector<float>& t = packed.traversal;
  const TopLevel all = packTopLevel(bvh.instances, &bvh, roots, worldBoxes, slotsTexel,
                                    slotsTexel + kSlotTexels * static_cast<int>(count));
  packed.empty = all.empty;
  t.insert(t.end(), all.header.begin(), all.header.end());
  t.insert(t.end(), slots.begin(), slots.end());
  t.insert(t.end(), all.nodes.begin(), all.nodes.end());

  std::vector<BvhInstance> phong = bvh.instances;
  for (size_t i = 0; i < phong.size(); ++i) {
    if (i >= count || scene.objects[i].material != Material::Phong) phong[i].mesh.reset();
  }
  packed.phongHeader = firstTexel + static_cast<int>(t.size() / 4);
  const TopLevel phongTop = packTopLevel(std::move(phong), nullptr, roots, worldBoxes, slotsTexel,
                                         packed.phongHeader + kStepTexels);
  packed.phongEmpty = phongTop.empty;
  t.insert(t.end(), phongTop.header.begin(), phongTop.header.end());
  t.insert(t.end(), phongTop.nodes.begin(), phongTop.nodes.end());
  return packed;
}

int traceStackFor(size_t objects, int deepestTree) {
  constexpr int kLargest = 2 * kBvhMaxDepth + 2;
  const size_t top = std::max<size_t>(objects, 1) - 1;
  const int tree = std::clamp(deepestTree, 1, kBvhMaxDepth) - 1;
  if (top >= static_cast<size_t>(kLargest)) return kLargest;
  const int needed = std::max(static_cast<int>(top) + tree, 1);
  return std::min((needed + 7) / 8 * 8, kLargest);
}

}  // namespace reflect
