// The demo's meshes on the CPU (kept so a lost GL context can be rebuilt), with a revision each,
// their levels of detail, and their trees for the exact mode.
//
// First frame first: a loaded mesh is drawn as it was parsed. Its chunks (the capture's culling
// units) and coarser levels are built afterwards, and only once something draws them: chunks and
// capture LOD's levels serve captured cube faces alone (the main pass draws whole meshes, and a
// traced reflector reads its own trees), so they are wanted once a frame captures a probe
// (noteCaptures); view LOD's levels are wanted while it is on. Natively they are built on a
// background thread (std::async) started after the first frame and taken in at the start of a
// later frame; waitForLevels() asks for everything the LOD settings could draw and waits for it
// (tests and benchmarks: the same meshes whatever the frames drew). In the page a Web Worker
// builds them and hands them in through setMeshChunks / addLodLevel / finishLevels
// (LevelBuilds::External), each answer carrying the revision its job was given. Coarser levels
// are kept as index lists over level 0's vertices. Whatever changes a mesh's levels is uploaded to
// the GPU set attached with setGpu.
#pragma once

#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/bvh.h"
#include "core/frame_planner.h"
#include "core/mesh_data.h"
#include "core/mesh_lod.h"
#include "core/obj_loader.h"
#include "core/result.h"
#include "gfx/mesh_buffer.h"

namespace reflect {

class MeshLibrary {
 public:
  MeshLibrary() = default;
  MeshLibrary(const MeshLibrary&) = delete;
  MeshLibrary& operator=(const MeshLibrary&) = delete;

  // Adopts a parse (its warnings go to lastWarnings()) or a mesh made in memory as mesh `name`,
  // drawn whole until its chunks are built. Returns "" or the parse's message (the mesh it had
  // stays).
  std::string adoptLoaded(const std::string& name, Result<LoadedMesh> loaded);
  std::string adopt(const std::string& name, Result<MeshData> mesh);
  std::vector<std::string>& lastWarnings() { return lastWarnings_; }
  const std::vector<std::string>& lastWarnings() const { return lastWarnings_; }
  bool has(const std::string& name) const { return meshes_.count(name) > 0; }

  // Level 0 of mesh `name` (its triangles in chunk order once chunks are built), or null.
  const MeshData* base(const std::string& name) const;
  // Each level of mesh `name`, level 0 first: its triangles, chunks and the vertices its GPU
  // copy holds (level 0: all of the mesh's; a coarser level: the ones it uses).
  struct LevelInfo {
    size_t triangles = 0;
    size_t chunks = 0;
    size_t vertices = 0;
  };
  std::vector<LevelInfo> levelInfo(const std::string& name) const;
  // What the planner knows of mesh `name`: its bounds, every level's triangles and chunks, and
  // its revision (none of it when there is no such mesh).
  void describe(const std::string& name, PlannedObject& object) const;

  enum class LevelBuilds { Background, External };
  void setLevelBuilds(LevelBuilds builds) { levelBuilds_ = builds; }
  // Which LOD settings are on: capture LOD's levels are drawn into captured faces only, view
  // LOD's in the main pass.
  void setLodSettings(bool captureLod, bool viewLod);
  // A frame captured a probe (or weighed a capture that levels could make the cheaper): from now
  // on chunks and, under capture LOD, coarser levels are wanted, for every mesh of this library.
  void noteCaptures();
  // Everything the LOD settings could draw is wanted from now on, whatever the frames draw:
  // every mesh's chunks and, while a LOD setting is on, its levels (the page's demo.lodReady()).
  void askForLevels();
  // Whether builds may start (after the first frame). Any of these turning something on starts
  // what is left.
  void allowBuilds();
  // Everything the LOD settings could draw is built: every mesh chunked and, while a LOD setting
  // is on, its levels made (whether or not a frame wanted them yet).
  bool lodReady() const;
  // Something wanted is not built yet (the page's worker has work: levelJobs() is not empty).
  bool levelsWanted() const;
  // Background: asks for everything (askForLevels), starts what is left and waits for it (it is
  // taken in before this returns).
  void waitForLevels();
  // Takes in the background builds that are done, without waiting.
  void collectFinished() { collectBuilds(false); }

  struct LevelJob {
    std::string name;
    uint32_t revision = 0;
    bool chunks = false;
    bool coarser = false;
  };
  std::vector<LevelJob> levelJobs() const;
  std::string setMeshChunks(const std::string& name, uint32_t revision,
                            std::span<const uint32_t> indices,
                            const std::vector<uint32_t>& chunkTriangles);
  std::string addLodLevel(const std::string& name, uint32_t revision, std::vector<uint32_t> indices,
                          const std::vector<uint32_t>& chunkTriangles);
  std::string finishLevels(const std::string& name, uint32_t revision);

  // Bytes as the GPU holds the meshes (every level's vertices and indices) and as kept here
  // (level 0's arrays, the coarser levels' index lists and every chunk table, by capacity).
  size_t gpuBytes() const;
  size_t cpuBytes() const;

  // Where uploads go (null: no GL resources now). Attaching uploads every mesh's levels.
  void setGpu(MeshBuffers* gpu);
  // Mesh `name`'s tree for the exact mode, built on first need (null: no such mesh); the tree
  // already built, without building one.
  std::shared_ptr<const MeshBvh> bvh(const std::string& name);
  const MeshBvh* builtBvh(const std::string& name) const;
  std::vector<std::string> names() const;
  // Time spent building trees so far (load-time accounting).
  double bvhBuildMs() const { return bvhBuildMs_; }

 private:
  // A coarser level: its triangles over level 0's vertices, in chunk order.
  struct CoarseLevel {
    std::vector<uint32_t> indices;
    std::vector<MeshChunk> chunks;
    size_t vertices = 0;  // distinct vertices it uses: what its GPU copy holds
  };
  struct MeshEntry {
    std::shared_ptr<MeshData> base;  // shared with a background build that reads it
    std::vector<CoarseLevel> coarser;
    bool chunked = false;
    bool levelsBuilt = false;          // coarser levels made (possibly none: small meshes)
    std::future<BuiltLevels> pending;  // a background build under way
  };

  // What is wanted now (see noteCaptures): coarser levels are always built after the mesh's
  // chunks, in chunk order, so wanting them wants the chunks too.
  bool wantsCoarser() const { return viewLod_ || (captureLod_ && (captures_ || asked_)); }
  bool wantsChunks() const { return captures_ || asked_ || wantsCoarser(); }
  // What is left to build of `entry`: its chunks, its coarser levels.
  bool chunksLeft(const MeshEntry& entry) const { return wantsChunks() && !entry.chunked; }
  bool coarserLeft(const MeshEntry& entry) const { return wantsCoarser() && !entry.levelsBuilt; }
  // Starts a background build for every mesh with work left and none under way.
  void startBuilds();
  // Takes in the builds that are done (all of them, waiting, with `wait`).
  void collectBuilds(bool wait);
  void takeIn(MeshEntry& entry, BuiltLevels built);
  // The mesh `name` at `revision`, or the reason it is not.
  MeshEntry* entryAt(const std::string& name, uint32_t revision, std::string* problem);
  // Uploads every level of `name` (level 0 first: it drops the old levels).
  void uploadLevels(const std::string& name, const MeshEntry& entry);

  std::map<std::string, MeshEntry> meshes_;
  std::map<std::string, uint32_t> revisions_;
  // Builds of meshes since replaced: their results are dropped once they are done (a future of
  // std::async would wait for its thread if it were destroyed before).
  std::vector<std::future<BuiltLevels>> abandoned_;
  LevelBuilds levelBuilds_ = LevelBuilds::Background;
  bool captureLod_ = true;  // the default planner settings have capture LOD on
  bool viewLod_ = false;
  bool captures_ = false;  // a frame captured (noteCaptures)
  bool asked_ = false;     // askForLevels
  bool buildsAllowed_ = false;
  std::vector<std::string> lastWarnings_;
  MeshBuffers* gpu_ = nullptr;
  std::map<std::string, std::shared_ptr<const MeshBvh>> bvhs_;  // level 0's, by mesh name
  double bvhBuildMs_ = 0.0;
};

}  // namespace reflect
