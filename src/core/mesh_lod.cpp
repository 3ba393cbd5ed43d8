#include "core/mesh_lod.h"

#include <limits>

#if defined(REFLECT_HAVE_MESHOPTIMIZER)
#include <meshoptimizer.h>
#endif

namespace reflect {

MeshData meshFromIndices(const MeshData& base, const std::vector<uint32_t>& indices) {
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  MeshData out;
  out.name = base.name;
  std::vector<uint32_t> remap(base.vertices.size(), kUnused);
  out.indices.reserve(indices.size());
  for (uint32_t index : indices) {
    if (index >= base.vertices.size()) continue;  // a bad index from outside: drop it
    if (remap[index] == kUnused) {
      remap[index] = static_cast<uint32_t>(out.vertices.size());
      out.vertices.push_back(base.vertices[index]);
    }
    out.indices.push_back(remap[index]);
  }
  out.indices.resize(out.indices.size() / 3 * 3);
  out.bounds = computeBounds(out.vertices);
  return out;
}

std::vector<MeshData> buildLodLevels(const MeshData& base, const LodSettings& settings) {
  std::vector<MeshData> levels;
#if defined(REFLECT_HAVE_MESHOPTIMIZER)
  const MeshData* previous = &base;
  for (int level = 1; level < settings.maxLevels; ++level) {
    if (previous->triangleCount() < settings.minTriangles) break;
    const size_t target =
        static_cast<size_t>(static_cast<float>(previous->indices.size()) * settings.triangleRatio) /
        3 * 3;
    std::vector<uint32_t> indices(previous->indices.size());
    const size_t count =
        meshopt_simplify(indices.data(), previous->indices.data(), previous->indices.size(),
                         &previous->vertices[0].position.x, previous->vertices.size(),
                         sizeof(Vertex), target, settings.targetError);
    // Stop when the library could not reduce enough to be worth another draw path.
    if (count == 0 || count > previous->indices.size() * 3 / 4) break;
    indices.resize(count);
    levels.push_back(meshFromIndices(*previous, indices));
    previous = &levels.back();
  }
#else
  (void)base;
  (void)settings;
#endif
  return levels;
}

}  // namespace reflect
