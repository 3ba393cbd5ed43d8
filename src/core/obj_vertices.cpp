#include "core/obj_vertices.h"

#include <cmath>
#include <limits>
#include <utility>

namespace reflect {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// A position's vertices (one per distinct normal) are found by walking a chain; past this many
// the rest go to a hash map, so a file that gives one position thousands of normals stays linear.
constexpr int kChainLimit = 32;

uint64_t keyOf(uint32_t position, int32_t normal) {
  return (static_cast<uint64_t>(position) << 32) | static_cast<uint32_t>(normal);
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return (length > 1e-20f && std::isfinite(length)) ? v / length : fallback;
}

// Gives every vertex of `out` still without a normal the area-weighted normal of its position's
// triangles (`keys[v].position` is vertex v's position; `sums` has room for one per position).
template <class Keys>
void addComputedNormals(std::vector<Vertex>& out, const Keys& keys,
                        const BlockArray<uint32_t>& indices, BlockArray<glm::vec3>& sums) {
  for (size_t p = 0; p < sums.size(); ++p) sums[p] = glm::vec3(0.0f);
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = out[indices[t]].position;
    const glm::vec3& b = out[indices[t + 1]].position;
    const glm::vec3& c = out[indices[t + 2]].position;
    const glm::vec3 areaNormal = glm::cross(b - a, c - a);  // length = 2 x area
    for (size_t k = 0; k < 3; ++k) sums[keys[indices[t + k]].position] += areaNormal;
  }
  for (size_t v = 0; v < keys.size(); ++v) {
    if (out[v].normal == glm::vec3(0.0f)) {
      out[v].normal = normalizedOr(sums[keys[v].position], {0.0f, 1.0f, 0.0f});
    }
  }
}

}  // namespace

void ObjVertices::addPosition() {
  firstOfPosition_.push_back(kNone);
}

uint32_t ObjVertices::vertexOf(const ObjCorner& c) {
  uint32_t id = firstOfPosition_[c.position];
  int steps = 0;
  for (; id != kNone; id = keys_[id].nextSamePosition, ++steps) {
    if (keys_[id].normal == c.normal) return id;
  }
  const uint64_t key = keyOf(c.position, c.normal);
  if (steps >= kChainLimit) {
    auto it = overflow_.find(key);
    if (it != overflow_.end()) return it->second;
  }
  const uint32_t created = static_cast<uint32_t>(keys_.size());
  if (steps < kChainLimit) {
    keys_.push_back(Key{c.position, c.normal, firstOfPosition_[c.position]});
    firstOfPosition_[c.position] = created;
  } else {
    keys_.push_back(Key{c.position, c.normal, kNone});
    overflow_.emplace(key, created);
  }
  return created;
}

bool ObjVertices::anyNormalPast(size_t normalCount) const {
  const int32_t total = static_cast<int32_t>(normalCount);
  for (size_t v = 0; v < keys_.size(); ++v) {
    if (keys_[v].normal >= total) return true;
  }
  return false;
}

void ObjVertices::mergeUndefinedNormals(size_t normalCount, BlockArray<uint32_t>& indices) {
  const int32_t total = static_cast<int32_t>(normalCount);
  std::unordered_map<uint64_t, uint32_t> vertexOfKey;
  std::vector<uint32_t> renumbered(keys_.size());
  uint32_t next = 0;
  for (size_t v = 0; v < keys_.size(); ++v) {
    Key vertex = keys_[v];
    if (vertex.normal >= total) vertex.normal = -1;
    auto [it, inserted] = vertexOfKey.try_emplace(keyOf(vertex.position, vertex.normal), next);
    // The new number is never above the old: moving down is safe in place.
    if (inserted) keys_[next++] = vertex;
    renumbered[v] = it->second;
  }
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = renumbered[indices[i]];
  keys_.truncate(next);
}

void ObjVertices::releaseChains() {
  firstOfPosition_.clear();
  // A new map, as `= {}` would keep the old one's buckets.
  overflow_ = std::unordered_map<uint64_t, uint32_t>();
}

// The vertex array is the one allocation made while the parse's arrays are all held, so it sets
// the peak; everything else is freed before the caller makes the index array, which then fits in
// the space the positions and normals leave when the file lists them before its faces (they lie
// side by side then: core/block_array.h). The positions' storage holds the computed normals' sums
// once the positions are copied into the vertices.
std::vector<Vertex> ObjVertices::makeVertices(BlockArray<glm::vec3>& positions,
                                              BlockArray<glm::vec3>& normals,
                                              const BlockArray<uint32_t>& indices) {
  std::vector<Vertex> out;
  out.reserve(keys_.size());
  const int32_t total = static_cast<int32_t>(normals.size());
  bool needComputed = false;
  for (size_t v = 0; v < keys_.size(); ++v) {
    const Key& key = keys_[v];
    glm::vec3 normal(0.0f);
    if (key.normal >= 0 && key.normal < total) {
      normal = normalizedOr(normals[static_cast<size_t>(key.normal)], glm::vec3(0.0f));
    }
    needComputed |= normal == glm::vec3(0.0f);
    out.push_back(Vertex{positions[key.position], normal});
  }
  normals.clear();
  if (needComputed) {
    BlockArray<glm::vec3> sums;
    std::swap(sums, positions);
    addComputedNormals(out, keys_, indices, sums);
  }
  positions.clear();
  keys_.clear();
  return out;
}

size_t ObjVertices::heldBytes() const {
  return keys_.capacityBytes() + firstOfPosition_.capacityBytes() +
         overflow_.size() * (sizeof(uint64_t) + sizeof(uint32_t));
}

}  // namespace reflect
