#include "app/mesh_library.h"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "core/mesh_chunks.h"

namespace reflect {

std::string MeshLibrary::adoptLoaded(const std::string& name, Result<LoadedMesh> loaded) {
  lastWarnings_.clear();
  if (!loaded) return loaded.error();
  LoadedMesh mesh = loaded.take();
  std::string error = adopt(name, Result<MeshData>(std::move(mesh.mesh)));
  if (error.empty()) lastWarnings_ = std::move(mesh.warnings);
  return error;
}

std::string MeshLibrary::adopt(const std::string& name, Result<MeshData> mesh) {
  if (!mesh) return mesh.error();
  MeshEntry entry;
  entry.base = std::make_shared<MeshData>(mesh.take());
  entry.base->chunks.clear();
  entry.base->sphereRadius = sphereRadiusOf(*entry.base);
  // Drawn whole at first; chunks and levels follow (after the first frame).
  if (gpu_) gpu_->set(name, 0, *entry.base);
  // The exact mode's tree is built when it is first asked for, so a load that never traces pays
  // nothing.
  bvhs_.erase(name);
  auto it = meshes_.find(name);
  if (it != meshes_.end()) {
    if (it->second.pending.valid()) abandoned_.push_back(std::move(it->second.pending));
    it->second = std::move(entry);
  } else {
    meshes_.emplace(name, std::move(entry));
  }
  // Unique across libraries: a level built for a mesh of an earlier scene never fits a later one.
  static std::atomic<uint32_t> nextRevision{1};
  revisions_[name] = nextRevision++;
  if (buildsAllowed_) startBuilds();
  return {};
}

const MeshData* MeshLibrary::base(const std::string& name) const {
  auto it = meshes_.find(name);
  return it == meshes_.end() ? nullptr : it->second.base.get();
}

std::vector<MeshLibrary::LevelInfo> MeshLibrary::levelInfo(const std::string& name) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end()) return {};
  const MeshData& base = *it->second.base;
  std::vector<LevelInfo> levels{{base.triangleCount(), base.chunks.size(), base.vertices.size()}};
  for (const CoarseLevel& level : it->second.coarser) {
    levels.push_back({level.indices.size() / 3, level.chunks.size(), level.vertices});
  }
  return levels;
}

void MeshLibrary::describe(const std::string& name, PlannedObject& object) const {
  auto it = meshes_.find(name);
  if (it != meshes_.end()) {
    const MeshData& base = *it->second.base;
    object.localBounds = base.bounds;
    object.levels.push_back(PlannedLevel{base.triangleCount(), &base.chunks});
    for (const CoarseLevel& level : it->second.coarser) {
      object.levels.push_back(PlannedLevel{level.indices.size() / 3, &level.chunks});
    }
  }
  auto revision = revisions_.find(name);
  object.meshRevision = revision == revisions_.end() ? 0 : revision->second;
}

void MeshLibrary::setLodSettings(bool captureLod, bool viewLod) {
  captureLod_ = captureLod;
  viewLod_ = viewLod;
  if (buildsAllowed_) startBuilds();  // a LOD setting turned on: its levels may be wanted now
}

void MeshLibrary::noteCaptures() {
  if (captures_) return;
  captures_ = true;
  if (buildsAllowed_) startBuilds();
}

void MeshLibrary::askForLevels() {
  asked_ = true;
}

void MeshLibrary::allowBuilds() {
  buildsAllowed_ = true;
  startBuilds();
}

bool MeshLibrary::lodReady() const {
  for (const auto& [name, entry] : meshes_) {
    if (entry.pending.valid() || !entry.chunked) return false;
    if ((captureLod_ || viewLod_) && !entry.levelsBuilt) return false;
  }
  return true;
}

bool MeshLibrary::levelsWanted() const {
  return std::any_of(meshes_.begin(), meshes_.end(), [this](const auto& mesh) {
    return chunksLeft(mesh.second) || coarserLeft(mesh.second);
  });
}

void MeshLibrary::waitForLevels() {
  askForLevels();
  startBuilds();
  collectBuilds(true);
}

void MeshLibrary::startBuilds() {
  if (levelBuilds_ != LevelBuilds::Background) return;
  for (auto& [name, entry] : meshes_) {
    if (entry.pending.valid()) continue;  // one build of a mesh at a time: it reads the base
    const bool chunks = chunksLeft(entry);
    const bool levels = coarserLeft(entry);
    if (!chunks && !levels) continue;
    std::shared_ptr<const MeshData> base = entry.base;
    entry.pending = std::async(
        std::launch::async, [base, chunks, levels] { return buildLevels(*base, chunks, levels); });
  }
}

void MeshLibrary::collectBuilds(bool wait) {
  const auto ready = [](std::future<BuiltLevels>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  };
  abandoned_.erase(std::remove_if(abandoned_.begin(), abandoned_.end(), ready), abandoned_.end());
  for (auto& [name, entry] : meshes_) {
    if (!entry.pending.valid()) continue;
    if (!wait && !ready(entry.pending)) continue;
    takeIn(entry, entry.pending.get());
    uploadLevels(name, entry);
  }
}

void MeshLibrary::takeIn(MeshEntry& entry, BuiltLevels built) {
  MeshData& base = *entry.base;
  if (built.chunked) {
    Result<std::vector<MeshChunk>> chunks =
        chunksFromCounts(base.vertices, built.base.indices, built.base.chunkTriangles);
    if (chunks) {
      base.indices = std::move(built.base.indices);
      base.chunks = chunks.take();
    }
    entry.chunked = true;  // a failure (never expected) leaves the mesh drawn whole
  }
  if (built.coarse) {
    entry.coarser.clear();
    for (LevelIndices& level : built.coarser) {
      Result<std::vector<MeshChunk>> chunks =
          chunksFromCounts(base.vertices, level.indices, level.chunkTriangles);
      if (!chunks) break;
      CoarseLevel coarse;
      coarse.vertices = verticesUsed(base.vertices.size(), level.indices);
      coarse.indices = std::move(level.indices);
      coarse.chunks = chunks.take();
      entry.coarser.push_back(std::move(coarse));
    }
    entry.levelsBuilt = true;
  }
}

std::vector<MeshLibrary::LevelJob> MeshLibrary::levelJobs() const {
  std::vector<LevelJob> jobs;
  for (const auto& [name, entry] : meshes_) {
    const bool chunks = chunksLeft(entry);
    const bool coarser = coarserLeft(entry);
    if (!chunks && !coarser) continue;
    auto revision = revisions_.find(name);
    jobs.push_back(
        LevelJob{name, revision == revisions_.end() ? 0 : revision->second, chunks, coarser});
  }
  return jobs;
}

MeshLibrary::MeshEntry* MeshLibrary::entryAt(const std::string& name, uint32_t revision,
                                             std::string* problem) {
  auto it = meshes_.find(name);
  auto current = revisions_.find(name);
  if (it == meshes_.end() || current == revisions_.end()) {
    *problem = name + ": no such mesh";
    return nullptr;
  }
  if (current->second != revision) {
    *problem = name + ": the mesh has changed since (revision " + std::to_string(revision) +
               ", now " + std::to_string(current->second) + ")";
    return nullptr;
  }
  return &it->second;
}

std::string MeshLibrary::setMeshChunks(const std::string& name, uint32_t revision,
                                       std::span<const uint32_t> indices,
                                       const std::vector<uint32_t>& chunkTriangles) {
  std::string problem;
  MeshEntry* entry = entryAt(name, revision, &problem);
  if (!entry) return problem;
  MeshData& base = *entry->base;
  if (indices.size() != base.indices.size()) {
    return name + ": the chunked triangles are " + std::to_string(indices.size() / 3) +
           ", the mesh has " + std::to_string(base.triangleCount());
  }
  Result<std::vector<MeshChunk>> chunks = chunksFromCounts(base.vertices, indices, chunkTriangles);
  if (!chunks) return name + ": " + chunks.error();
  std::copy(indices.begin(), indices.end(), base.indices.begin());
  base.chunks = chunks.take();
  entry->chunked = true;
  uploadLevels(name, *entry);
  return {};
}

std::string MeshLibrary::addLodLevel(const std::string& name, uint32_t revision,
                                     std::vector<uint32_t> indices,
                                     const std::vector<uint32_t>& chunkTriangles) {
  std::string problem;
  MeshEntry* entry = entryAt(name, revision, &problem);
  if (!entry) return problem;
  if (indices.empty()) return name + ": level of detail has no triangles";
  const MeshData& base = *entry->base;
  Result<std::vector<MeshChunk>> chunks = chunksFromCounts(base.vertices, indices, chunkTriangles);
  if (!chunks) return name + ": " + chunks.error();
  CoarseLevel level;
  level.vertices = verticesUsed(base.vertices.size(), indices);
  level.indices = std::move(indices);
  level.chunks = chunks.take();
  if (gpu_) {
    gpu_->set(name, static_cast<int>(entry->coarser.size() + 1),
              meshFromIndices(base, level.indices));
  }
  entry->coarser.push_back(std::move(level));
  return {};
}

std::string MeshLibrary::finishLevels(const std::string& name, uint32_t revision) {
  std::string problem;
  MeshEntry* entry = entryAt(name, revision, &problem);
  if (!entry) return problem;
  entry->levelsBuilt = true;
  return {};
}

size_t MeshLibrary::gpuBytes() const {
  size_t bytes = 0;
  for (const auto& [name, entry] : meshes_) {
    bytes += entry.base->vertices.size() * sizeof(Vertex) +
             entry.base->indices.size() * sizeof(uint32_t);
    for (const CoarseLevel& level : entry.coarser) {
      bytes += level.vertices * sizeof(Vertex) + level.indices.size() * sizeof(uint32_t);
    }
  }
  return bytes;
}

size_t MeshLibrary::cpuBytes() const {
  size_t bytes = 0;
  for (const auto& [name, entry] : meshes_) {
    const MeshData& base = *entry.base;
    bytes += base.vertices.capacity() * sizeof(Vertex) +
             base.indices.capacity() * sizeof(uint32_t) +
             base.chunks.capacity() * sizeof(MeshChunk);
    for (const CoarseLevel& level : entry.coarser) {
      bytes +=
          level.indices.capacity() * sizeof(uint32_t) + level.chunks.capacity() * sizeof(MeshChunk);
    }
  }
  return bytes;
}

void MeshLibrary::setGpu(MeshBuffers* gpu) {
  gpu_ = gpu;
  for (const auto& [name, entry] : meshes_) uploadLevels(name, entry);
}

void MeshLibrary::uploadLevels(const std::string& name, const MeshEntry& entry) {
  if (!gpu_) return;
  gpu_->set(name, 0, *entry.base);
  for (size_t k = 0; k < entry.coarser.size(); ++k) {
    // The GPU's copy is compact (the level's own vertices); the CPU keeps the index list.
    gpu_->set(name, static_cast<int>(k + 1),
              meshFromIndices(*entry.base, entry.coarser[k].indices));
  }
}

std::shared_ptr<const MeshBvh> MeshLibrary::bvh(const std::string& name) {
  auto built = bvhs_.find(name);
  if (built != bvhs_.end()) return built->second;
  auto it = meshes_.find(name);
  if (it == meshes_.end()) return nullptr;
  const auto start = std::chrono::steady_clock::now();
  auto tree = std::make_shared<const MeshBvh>(buildMeshBvh(it->second.base));
  bvhBuildMs_ +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  bvhs_[name] = tree;
  return tree;
}

const MeshBvh* MeshLibrary::builtBvh(const std::string& name) const {
  auto it = bvhs_.find(name);
  return it == bvhs_.end() ? nullptr : it->second.get();
}

std::vector<std::string> MeshLibrary::names() const {
  std::vector<std::string> names;
  for (const auto& [name, entry] : meshes_) names.push_back(name);
  return names;
}

}  // namespace reflect
