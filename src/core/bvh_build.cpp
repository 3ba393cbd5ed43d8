// The BVH builds (core/bvh.h): a binned SAH build over any boxes, and the two trees made with it,
// a mesh's over its triangles and a scene's over its placed objects.
#include "core/bvh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "core/float_limits.h"
#include "core/frustum.h"

namespace reflect {
namespace {

constexpr int kBins = 16;

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

// The items of one node binned by their centroids, on the three axes at once.
struct Binning {
  struct Bin {
    Bounds box = emptyBounds(), centres = emptyBounds();
    uint32_t count = 0;
  };
  std::array<std::array<Bin, kBins>, 3> bins;
  Bounds centres;         // the items' centroids' bounds
  glm::vec3 scale{0.0f};  // bins per unit along each axis; 0: every centroid at one place

  explicit Binning(const Bounds& itemCentres) : centres(itemCentres) {
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centres.max[axis] - centres.min[axis];
      scale[axis] = extent > 0.0f ? kBins / extent : 0.0f;
    }
  }
  int binOf(const glm::vec3& c, int axis) const {
    return std::min(kBins - 1, static_cast<int>((c[axis] - centres.min[axis]) * scale[axis]));
  }
  void add(const Bounds& box, const glm::vec3& c) {
    for (int axis = 0; axis < 3; ++axis) {
      if (scale[axis] == 0.0f) continue;
      Bin& b = bins[static_cast<size_t>(axis)][static_cast<size_t>(binOf(c, axis))];
      ++b.count;
      grow(b.box, box);
      grow(b.centres, {c, c});
    }
  }
};

// The cheapest of the bins' split planes on the three axes (surface area heuristic): the axis
// (-1: none splits the `count` items) and the last bin on the left.
struct Split {
  int axis = -1;
  int lastLeftBin = 0;
};
Split cheapestSplit(const Binning& binning, uint32_t count) {
  float bestCost = kInfinity;
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    if (binning.scale[axis] == 0.0f) continue;
    const std::array<Binning::Bin, kBins>& b = binning.bins[static_cast<size_t>(axis)];
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
        best = Split{axis, k};
      }
    }
  }
  return best;
}

// A node's two halves: where its items split, and each side's boxes and centroids' bounds.
struct Halves {
  uint32_t middle = 0;
  Bounds leftBox = emptyBounds(), leftCentres = emptyBounds();
  Bounds rightBox = emptyBounds(), rightCentres = emptyBounds();
};

struct Builder {
  const std::vector<Bounds>& boxes;
  // An item's centroid, from its box each time: a figure of the course's weight would keep
  // 1.9 MB of them through the build, and WebAssembly's heap keeps its largest size.
  glm::vec3 centroid(uint32_t item) const { return boxes[item].centre(); }
  Bvh& out;
  int maxLeaf;

  // The items [first, first + count) split by the cheapest plane, their order partitioned.
  Halves splitBySah(uint32_t first, uint32_t count, const Bounds& centres) {
    Binning binning(centres);
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t item = out.order[i];
      binning.add(boxes[item], centroid(item));
    }
    const Split split = cheapestSplit(binning, count);
    Halves h;
    if (split.axis < 0) return h;
    auto* begin = out.order.data() + first;
    auto* middle = std::partition(begin, begin + count, [&](uint32_t item) {
      return binning.binOf(centroid(item), split.axis) <= split.lastLeftBin;
    });
    h.middle = static_cast<uint32_t>(middle - begin);
    for (int k = 0; k < kBins; ++k) {
      const Binning::Bin& b = binning.bins[static_cast<size_t>(split.axis)][static_cast<size_t>(k)];
      grow(k <= split.lastLeftBin ? h.leftBox : h.rightBox, b.box);
      grow(k <= split.lastLeftBin ? h.leftCentres : h.rightCentres, b.centres);
    }
    return h;
  }

  // The items [first, first + count) halved in their order (one centroid for all).
  Halves splitInHalf(uint32_t first, uint32_t count) const {
    Halves h;
    h.middle = count / 2;
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t item = out.order[i];
      const bool isLeft = i < first + h.middle;
      grow(isLeft ? h.leftBox : h.rightBox, boxes[item]);
      const glm::vec3 c = centroid(item);
      grow(isLeft ? h.leftCentres : h.rightCentres, {c, c});
    }
    return h;
  }

  // `bounds`: the items' boxes together; `centres`: their centroids' bounds (the caller knows
  // both: the root's from one pass, a child's from its side of the parent's bins).
  void build(size_t nodeIndex, uint32_t first, uint32_t count, int depth, const Bounds& bounds,
             const Bounds& centres) {
    out.depth = std::max(out.depth, depth);
    out.nodes[nodeIndex].min = bounds.min;
    out.nodes[nodeIndex].max = bounds.max;
    if (count <= static_cast<uint32_t>(maxLeaf) || depth >= kBvhMaxDepth) {
      out.nodes[nodeIndex].first = first;
      out.nodes[nodeIndex].count = count;
      return;
    }
    Halves h = splitBySah(first, count, centres);
    if (h.middle == 0 || h.middle == count) h = splitInHalf(first, count);

    const size_t left = out.nodes.size();
    out.nodes.emplace_back();
    out.nodes.emplace_back();
    out.nodes[nodeIndex].first = static_cast<uint32_t>(left);
    out.nodes[nodeIndex].count = 0;
    build(left, first, h.middle, depth + 1, h.leftBox, h.leftCentres);
    build(left + 1, first + h.middle, count - h.middle, depth + 1, h.rightBox, h.rightCentres);
  }
};

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

}  // namespace reflect
