#include "core/mesh_lod.h"

#include <algorithm>
#include <limits>

#include "core/mesh_chunks.h"
#include "core/mesh_simplify.h"

namespace reflect {

MeshData meshFromIndices(const MeshData& base, const std::vector<uint32_t>& indices) {
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  MeshData out;
  out.name = base.name;
  std::vector<uint32_t> remap(base.vertices.size(), kUnused);
  out.vertices.reserve(verticesUsed(base.vertices.size(), indices));
  out.indices.reserve(indices.size() / 3 * 3);
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    // A triangle with a bad index from outside is dropped whole.
    if (indices[i] >= base.vertices.size() || indices[i + 1] >= base.vertices.size() ||
        indices[i + 2] >= base.vertices.size()) {
      continue;
    }
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t index = indices[i + k];
      if (remap[index] == kUnused) {
        remap[index] = static_cast<uint32_t>(out.vertices.size());
        out.vertices.push_back(base.vertices[index]);
      }
      out.indices.push_back(remap[index]);
    }
  }
  out.bounds = computeBounds(out.vertices);
  return out;
}

size_t verticesUsed(size_t vertexCount, const std::vector<uint32_t>& indices) {
  std::vector<bool> used(vertexCount, false);
  size_t count = 0;
  for (uint32_t index : indices) {
    if (index < vertexCount && !used[index]) {
      used[index] = true;
      ++count;
    }
  }
  return count;
}

BuiltLevels buildLevels(const MeshData& base, bool chunkBase, bool coarser,
                        const LodSettings& settings) {
  BuiltLevels built;
  const std::vector<uint32_t>* previous = &base.indices;
  if (chunkBase) {
    built.chunked = true;
    built.base.indices = base.indices;
    built.base.chunkTriangles = chunkOrder(base.vertices, built.base.indices);
    previous = &built.base.indices;
  }
  if (!coarser) return built;
  built.coarse = true;
  built.coarser.reserve(
      static_cast<size_t>(std::max(settings.maxLevels, 1)));  // `previous` stays valid
  for (int level = 1; level < settings.maxLevels; ++level) {
    if (previous->size() / 3 < settings.minTriangles) break;
    const size_t target =
        static_cast<size_t>(static_cast<float>(previous->size()) * settings.triangleRatio) / 3 * 3;
    LevelIndices next;
    next.indices = simplifyMesh(base.vertices, *previous, target, settings.targetError);
    // Stop when the simplifier could not reduce enough to be worth another draw path.
    if (next.indices.empty() || next.indices.size() > previous->size() * 3 / 4) break;
    next.chunkTriangles = chunkOrder(base.vertices, next.indices);
    built.coarser.push_back(std::move(next));
    previous = &built.coarser.back().indices;
  }
  return built;
}

}  // namespace reflect
