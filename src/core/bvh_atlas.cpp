// The atlas (core/bvh.h): every mesh's tree in the float texture the shader walks, and the vertex
// normals beside it, written on demand a range of texels at a time.
#include "core/bvh.h"

#include <algorithm>

namespace reflect {
namespace {

void putTexel(float* out, const glm::vec3& v, float w) {
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
  out[3] = w;
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

}  // namespace reflect
