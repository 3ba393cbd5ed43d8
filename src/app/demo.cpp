#include "app/demo.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>

#include "core/mesh_chunks.h"
#include "core/mesh_lod.h"
#include "core/obj_loader.h"
#include "core/probe_layout.h"
#include "core/scene_file.h"
#include "core/settings_schema.h"
#include "gfx/gl.h"

namespace reflect {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The exact mode needs no cube map but a cube-textured object's: the other probes capture
// nothing.
}  // namespace

Demo::Demo(Scene scene) : scene_(std::move(scene)), camera_(scene_.camera) {}

Demo::~Demo() = default;

std::string Demo::loadMesh(const std::string& name, const std::string& path) {
  return adoptLoaded(name, loadObjFile(path));
}

std::string Demo::loadMeshText(const std::string& name, const std::string& text,
                               const std::string& source) {
  return adoptLoaded(name, parseObj(text, source));
}

std::string Demo::setLoadedMesh(const std::string& name, Result<LoadedMesh> loaded) {
  return adoptLoaded(name, std::move(loaded));
}

std::string Demo::adoptLoaded(const std::string& name, Result<LoadedMesh> loaded) {
  lastWarnings_.clear();
  if (!loaded) return loaded.error();
  LoadedMesh mesh = loaded.take();
  std::string error = adopt(name, Result<MeshData>(std::move(mesh.mesh)));
  if (error.empty()) lastWarnings_ = std::move(mesh.warnings);
  return error;
}

std::string Demo::setMeshData(const std::string& name, MeshData mesh) {
  return adopt(name, Result<MeshData>(std::move(mesh)));
}

std::string Demo::adopt(const std::string& name, Result<MeshData> mesh) {
  if (!mesh) return mesh.error();
  MeshEntry entry;
  entry.base = std::make_shared<MeshData>(mesh.take());
  entry.base->chunks.clear();
  entry.base->sphereRadius = sphereRadiusOf(*entry.base);
  // Drawn whole at first; chunks and levels follow (after the first frame).
  for (SceneRenderer* r : {renderer_.get(), exactRenderer_.get()}) {
    if (r) r->setMesh(name, 0, *entry.base);
  }
  // The exact mode's tree: built now only while that mode (or the error view) is set up, else
  // when it is (setUpExact), so a load that never traces pays nothing.
  bvhs_.erase(name);
  if (exactTracer_) exactTracer_->setMesh(name, bvhFor(name, entry.base));
  auto it = meshes_.find(name);
  if (it != meshes_.end()) {
    if (it->second.pending.valid()) abandoned_.push_back(std::move(it->second.pending));
    it->second = std::move(entry);
  } else {
    meshes_.emplace(name, std::move(entry));
  }
  // Unique across demos: a level built for a mesh of an earlier scene never fits a later one.
  static std::atomic<uint32_t> nextRevision{1};
  meshRevisions_[name] = nextRevision++;
  if (firstFrameDrawn_) startBuilds();
  return {};
}

bool Demo::needsLevels() const {
  return plannerSettings_.captureLod > 0.0f || plannerSettings_.viewLod > 0.0f;
}

bool Demo::lodReady() const {
  for (const auto& [name, entry] : meshes_) {
    if (entry.pending.valid() || !entry.chunked) return false;
    if (needsLevels() && !entry.levelsBuilt) return false;
  }
  return true;
}

std::vector<Demo::LevelJob> Demo::levelJobs() const {
  std::vector<LevelJob> jobs;
  for (const auto& [name, entry] : meshes_) {
    const bool coarser = needsLevels() && !entry.levelsBuilt;
    if (entry.chunked && !coarser) continue;
    auto revision = meshRevisions_.find(name);
    jobs.push_back(LevelJob{name, revision == meshRevisions_.end() ? 0 : revision->second,
                            !entry.chunked, coarser});
  }
  return jobs;
}

void Demo::startBuilds() {
  if (levelBuilds_ != LevelBuilds::Background) return;
  const bool coarser = needsLevels();
  for (auto& [name, entry] : meshes_) {
    if (entry.pending.valid()) continue;  // one build of a mesh at a time: it reads the base
    const bool chunks = !entry.chunked;
    const bool levels = coarser && !entry.levelsBuilt;
    if (!chunks && !levels) continue;
    std::shared_ptr<const MeshData> base = entry.base;
    entry.pending = std::async(
        std::launch::async, [base, chunks, levels] { return buildLevels(*base, chunks, levels); });
  }
}

void Demo::collectBuilds(bool wait) {
  abandoned_.erase(std::remove_if(abandoned_.begin(), abandoned_.end(),
                                  [](std::future<BuiltLevels>& f) {
                                    return f.wait_for(std::chrono::seconds(0)) ==
                                           std::future_status::ready;
                                  }),
                   abandoned_.end());
  for (auto& [name, entry] : meshes_) {
    if (!entry.pending.valid()) continue;
    if (!wait && entry.pending.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      continue;
    }
    BuiltLevels built = entry.pending.get();
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
    uploadLevels(name, entry);
  }
}

void Demo::waitForLevels() {
  startBuilds();
  collectBuilds(true);
}

void Demo::uploadLevels(const std::string& name, const MeshEntry& entry) {
  for (SceneRenderer* r : {renderer_.get(), exactRenderer_.get()}) {
    if (!r) continue;
    r->setMesh(name, 0, *entry.base);
    for (size_t k = 0; k < entry.coarser.size(); ++k) {
      // The GPU's copy is compact (the level's own vertices); the CPU keeps the index list.
      r->setMesh(name, static_cast<int>(k + 1),
                 meshFromIndices(*entry.base, entry.coarser[k].indices));
    }
  }
}

std::shared_ptr<const MeshBvh> Demo::bvhFor(const std::string& name,
                                            std::shared_ptr<const MeshData> mesh) {
  auto it = bvhs_.find(name);
  if (it != bvhs_.end()) return it->second;
  const auto start = std::chrono::steady_clock::now();
  auto bvh = std::make_shared<const MeshBvh>(buildMeshBvh(std::move(mesh)));
  bvhBuildMs_ += millisecondsSince(start);
  bvhs_[name] = bvh;
  return bvh;
}

Demo::MeshEntry* Demo::entryAt(const std::string& name, uint32_t revision, std::string* problem) {
  auto it = meshes_.find(name);
  auto current = meshRevisions_.find(name);
  if (it == meshes_.end() || current == meshRevisions_.end()) {
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

std::string Demo::setMeshChunks(const std::string& name, uint32_t revision,
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

std::string Demo::addLodLevel(const std::string& name, uint32_t revision,
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
  for (SceneRenderer* r : {renderer_.get(), exactRenderer_.get()}) {
    if (r)
      r->setMesh(name, static_cast<int>(entry->coarser.size() + 1),
                 meshFromIndices(base, level.indices));
  }
  entry->coarser.push_back(std::move(level));
  return {};
}

std::string Demo::finishLevels(const std::string& name, uint32_t revision) {
  std::string problem;
  MeshEntry* entry = entryAt(name, revision, &problem);
  if (!entry) return problem;
  entry->levelsBuilt = true;
  return {};
}

size_t Demo::meshGpuBytes() const {
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

size_t Demo::meshCpuBytes() const {
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

std::vector<Demo::LevelInfo> Demo::levelInfo(const std::string& name) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end()) return {};
  const MeshData& base = *it->second.base;
  std::vector<LevelInfo> levels{{base.triangleCount(), base.chunks.size(), base.vertices.size()}};
  for (const CoarseLevel& level : it->second.coarser) {
    levels.push_back({level.indices.size() / 3, level.chunks.size(), level.vertices});
  }
  return levels;
}

std::vector<size_t> Demo::levelTriangles(const std::string& name) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end()) return {};
  std::vector<size_t> triangles{it->second.base->triangleCount()};
  for (const CoarseLevel& level : it->second.coarser) triangles.push_back(level.indices.size() / 3);
  return triangles;
}

std::string Demo::addObject(const SceneObject& object) {
  if (meshes_.count(object.mesh) == 0) return object.mesh + ": not loaded";
  if (scene_.objects.size() >= kMaxSceneObjects) {
    return "the scene already has " + std::to_string(kMaxSceneObjects) + " objects";
  }
  scene_.objects.push_back(object);
  return {};
}

std::string Demo::setMaterialJson(int index, const std::string& json) {
  if (index < 0 || index >= static_cast<int>(scene_.objects.size())) {
    return "no object " + std::to_string(index);
  }
  return applyMaterialJson(json, "material", scene_.objects[static_cast<size_t>(index)]);
}

std::string Demo::setSkybox(CubeFaces faces) {
  for (SceneRenderer* r : {renderer_.get(), exactRenderer_.get()}) {
    if (!r) continue;
    std::string error = r->setSkybox(faces);
    if (!error.empty()) return error;
  }
  if (exactTracer_) {
    std::string error = exactTracer_->setSkybox(&faces);
    if (!error.empty()) return error;
  }
  skyboxContent_ = contentHash(faces);
  skybox_ = std::move(faces);
  return {};
}

const MeshData* Demo::meshLevel(const std::string& name, int lod) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end() || lod != 0) return nullptr;
  return it->second.base.get();
}

std::string Demo::loadMeshesFrom(const std::string& directory) {
  std::vector<std::string> warnings;
  for (const std::string& name : scene_.meshNames()) {
    std::string error = loadMesh(name, directory + "/" + name);
    if (!error.empty()) return error;
    warnings.insert(warnings.end(), lastWarnings_.begin(), lastWarnings_.end());
  }
  lastWarnings_ = std::move(warnings);
  return {};
}

bool Demo::hasAllMeshes() const {
  for (const std::string& name : scene_.meshNames()) {
    if (meshes_.count(name) == 0) return false;
  }
  return true;
}

void Demo::setPlannerSettings(const PlannerSettings& settings) {
  plannerSettings_ = settings;
  if (firstFrameDrawn_) startBuilds();  // a LOD setting turned on: its levels are wanted now
}

std::string Demo::setCubeFaceSize(int size) {
  scene_.capture.faceSize = std::clamp(size, 1, kMaxCubeFaceSize);
  if (scene_.capture.faceSize == size) return {};
  return "cube size " + std::to_string(size) + " is outside 1.." +
         std::to_string(kMaxCubeFaceSize) + "; using " + std::to_string(scene_.capture.faceSize);
}

unsigned Demo::environmentTexture() const {
  // The first reflector in object order owns the probe it samples.
  const int reflector = scene_.reflectorIndex();
  return renderer_ && reflector >= 0 ? renderer_->probeTexture(reflector) : 0;
}

std::string Demo::initGraphics() {
  // The exact mode's tracer and the error view's renderer stay (the page's "auto" switches the
  // accuracy settings back and forth); setUpExact remakes the renderer if its settings changed.
  renderer_.reset();
  planner_.invalidate();  // a new renderer has no captures yet
  Result<SceneRenderer> renderer = SceneRenderer::create(accuracy_);
  if (!renderer) return renderer.error();
  renderer_ = std::make_unique<SceneRenderer>(renderer.take());
  // The GL may allow less than kMaxCubeFaceSize; capture targets are made at what it allows.
  GLint maxCubeSize = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxCubeSize);
  scene_.capture.faceSize = std::clamp(scene_.capture.faceSize, 1, std::max(1, maxCubeSize));
  gpuTimer_ = std::make_unique<GpuTimer>();
  for (const auto& [name, entry] : meshes_) uploadLevels(name, entry);
  if (skybox_) {
    std::string error = renderer_->setSkybox(*skybox_);
    if (!error.empty()) return error;
  }
  std::string error = setUpExact();
  if (!error.empty()) return error;
  return checkGlError("init graphics") ? std::string() : "GL error while creating resources";
}

bool Demo::mayTrace() const {
  return accuracy_.search == Search::Exact || accuracy_.search == Search::Planned;
}

std::string Demo::setUpExact() {
  if (!renderer_) return {};
  const bool traced = mayTrace();
  renderer_->setExactTracer(nullptr);
  if (!traced && !showError_) return {};  // what exists stays, unused, for the next time
  if (!exactTracer_) {
    Result<ExactTracer> tracer = ExactTracer::create();
    if (!tracer) return tracer.error();
    exactTracer_ = std::make_unique<ExactTracer>(tracer.take());
    for (const auto& [name, entry] : meshes_) exactTracer_->setMesh(name, bvhFor(name, entry.base));
    std::string error = exactTracer_->setSkybox(skyboxFaces());
    if (!error.empty()) return error;
  }
  if (traced) renderer_->setExactTracer(exactTracer_.get());
  AccuracySettings exact = accuracy_;
  exact.search = Search::Exact;
  if (showError_ && (!exactRenderer_ || !(exactRenderer_->accuracy() == exact))) {
    exactRenderer_.reset();
    Result<SceneRenderer> renderer = SceneRenderer::create(exact);
    if (!renderer) return renderer.error();
    exactRenderer_ = std::make_unique<SceneRenderer>(renderer.take());
    for (const auto& [name, entry] : meshes_) uploadLevels(name, entry);
    if (skybox_) {
      std::string error = exactRenderer_->setSkybox(*skybox_);
      if (!error.empty()) return error;
    }
    exactRenderer_->setExactTracer(exactTracer_.get());
    exactPlanner_.invalidate();
  }
  if (showError_ && !errorView_) {
    Result<ErrorView> view = ErrorView::create();
    if (!view) return view.error();
    errorView_ = std::make_unique<ErrorView>(view.take());
  }
  return {};
}

std::string Demo::setShowError(bool on) {
  if (on == showError_) return {};
  showError_ = on;
  return setUpExact();
}

const MeshBvh* Demo::meshBvh(const std::string& name) const {
  auto it = bvhs_.find(name);
  return it == bvhs_.end() ? nullptr : it->second.get();
}

std::string Demo::setAccuracySettings(const AccuracySettings& settings) {
  for (const auto& field : accuracyFields()) {
    std::string problem = field.info.check(field.get(settings));
    if (!problem.empty()) return problem;
  }
  if (settings == accuracy_) return {};
  accuracy_ = settings;
  return renderer_ ? initGraphics() : std::string();
}

void Demo::renderLookupDirections(unsigned framebuffer, int width, int height) {
  if (!renderer_ || width < 1 || height < 1) return;
  const ViewParams view{camera_.view(),
                        camera_.projection(static_cast<float>(width) / static_cast<float>(height)),
                        camera_.eye()};
  const std::vector<PlannedObject> objects = plannedObjects(clock_.seconds());
  FramePlan plan = FramePlanner::layout(objects, captureContext());
  // Each reflector the way the last frame drew it: traced, or from its probe.
  std::erase_if(plan.probes, [&](const ProbePlan& probe) {
    return std::any_of(lastTraced_.begin(), lastTraced_.end(),
                       [&](const ProbeLayout& t) { return t.reflector == probe.reflector; });
  });
  plan.traced = lastTraced_;
  renderer_->drawMain(scene_, clock_.seconds(), plan, view, viewDraws(objects, width, height),
                      framebuffer, width, height, true);
}

std::vector<ScreenBox> Demo::screenBoxes(int width, int height) const {
  const float aspect = height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
  const glm::mat4 viewProjection = camera_.projection(aspect) * camera_.view();
  std::vector<ScreenBox> boxes;
  for (const PlannedObject& object : plannedObjects(clock_.seconds())) {
    boxes.push_back(screenBox(object.localBounds, object.model, viewProjection));
  }
  return boxes;
}

std::vector<DrawItem> Demo::viewDraws(const std::vector<PlannedObject>& objects, int width,
                                      int height) const {
  const PlannerView view = plannerView(width, height);
  return planViewDraws(objects, view.eye, view.pixelsPerTangent, plannerSettings_);
}

PlannerView Demo::plannerView(int width, int height) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return PlannerView{
      camera_.eye(),
      0.5f * static_cast<float>(height) / std::tan(glm::radians(camera_.fovYDeg(aspect)) * 0.5f),
      static_cast<float>(width) * static_cast<float>(height)};
}

void Demo::releaseGraphics() {
  exactRenderer_.reset();
  errorView_.reset();
  exactTracer_.reset();
  renderer_.reset();
  gpuTimer_.reset();
  inside_.release();
  planner_.invalidate();
}

void Demo::loseGraphics() {
  if (renderer_) renderer_->abandon();
  renderer_.reset();
  if (exactRenderer_) exactRenderer_->abandon();
  exactRenderer_.reset();
  if (errorView_) errorView_->abandon();
  errorView_.reset();
  if (exactTracer_) exactTracer_->abandon();
  exactTracer_.reset();
  if (gpuTimer_) gpuTimer_->abandon();
  gpuTimer_.reset();
  inside_.abandon();
  planner_.invalidate();
}

CaptureContext Demo::captureContext() const {
  return CaptureContext{camera_.eye(),
                        scene_.capture.faceSize,
                        scene_.capture.near,
                        scene_.capture.far,
                        scene_.light,
                        scene_.clearColour,
                        skyboxContent_,
                        accuracy_,
                        plannerSettings_.captureLod};
}

std::vector<PlannedObject> Demo::plannedObjects(double seconds) const {
  std::vector<PlannedObject> planned;
  planned.reserve(scene_.objects.size());
  for (const SceneObject& object : scene_.objects) {
    PlannedObject p;
    auto it = meshes_.find(object.mesh);
    if (it != meshes_.end()) {
      const MeshData& base = *it->second.base;
      p.localBounds = base.bounds;
      p.levels.push_back(PlannedLevel{base.triangleCount(), &base.chunks});
      for (const CoarseLevel& level : it->second.coarser) {
        p.levels.push_back(PlannedLevel{level.indices.size() / 3, &level.chunks});
      }
    }
    auto revision = meshRevisions_.find(object.mesh);
    p.meshRevision = revision == meshRevisions_.end() ? 0 : revision->second;
    p.model = scene_.modelMatrix(object, seconds);
    p.colour = object.colour;
    p.look = object.look();
    p.probed = object.needsLiveProbe();
    p.probeGroup = object.probeGroup;
    p.probeCentre = capturePoint(object.probeCentre, accuracy_.captureAtOrigin);
    planned.push_back(p);
  }
  return planned;
}

const FrameStats& Demo::frame(double dtSeconds, unsigned framebuffer, int width, int height,
                              bool waitForGpu) {
  collectBuilds(false);  // levels built since the last frame join this one
  clock_.advance(dtSeconds);
  stats_ = FrameStats{};
  stats_.timeSeconds = clock_.seconds();
  stats_.orbitDegrees = clock_.orbitDegrees();
  stats_.timing = waitForGpu ? "gpu-finish" : "cpu-submit";
  stats_.policy = policyName(plannerSettings_.policy);
  stats_.cubeFaceSize = scene_.capture.faceSize;
  stats_.width = width;
  stats_.height = height;
  stats_.lodReady = lodReady();
  stats_.meshBytes = meshGpuBytes();
  stats_.meshCpuBytes = meshCpuBytes();
  if (!renderer_ || width < 1 || height < 1) return stats_;  // hidden canvas: nothing to draw

  const auto start = std::chrono::steady_clock::now();
  const CaptureContext context = captureContext();
  const std::vector<PlannedObject> objects = plannedObjects(stats_.timeSeconds);
  const FramePlan plan =
      planner_.plan(objects, context, plannerSettings_, plannerView(width, height));
  lastTraced_ = plan.traced;
  if (exactTracer_ && (!plan.traced.empty() || showError_)) {
    exactTracer_->prepare(scene_, stats_.timeSeconds, plan, camera_.eye());
  }
  gpuTimer_->begin(GpuTimer::kCapture);
  Result<PassCounts> capture = renderer_->capture(scene_, stats_.timeSeconds, plan, camera_.eye());
  gpuTimer_->end();
  if (!capture) {
    stats_.error = "capture failed: " + capture.error();
    std::fprintf(stderr, "%s\n", stats_.error.c_str());
    planner_.invalidate();  // nothing it planned was drawn
  } else {
    stats_.captureDrawCalls = capture.value().drawCalls;
    stats_.captureTriangles = capture.value().triangles;
  }
  if (waitForGpu) reflect::waitForGpu();
  stats_.captureMs = millisecondsSince(start);
  stats_.probes = static_cast<int>(plan.probes.size());
  stats_.tracedReflectors = 0;
  for (const ProbeLayout& t : plan.traced)
    stats_.tracedReflectors += static_cast<int>(t.members.size());
  stats_.facesCaptured = plan.facesCaptured();

  const ViewParams view{camera_.view(),
                        camera_.projection(static_cast<float>(width) / static_cast<float>(height)),
                        camera_.eye()};
  const bool errorView =
      showError_ && errorView_ && exactRenderer_ && errorView_->resize(width, height).empty();
  const std::vector<DrawItem> draws = viewDraws(objects, width, height);
  gpuTimer_->begin(GpuTimer::kMain);
  const PassCounts main = renderer_->drawMain(
      scene_, stats_.timeSeconds, plan, view, draws,
      errorView ? errorView_->currentFramebuffer() : framebuffer, width, height);
  gpuTimer_->end();
  gpuTimer_->endFrame();
  if (waitForGpu) reflect::waitForGpu();
  stats_.frameMs = millisecondsSince(start);
  if (gpuTimer_->lastMs(GpuTimer::kCapture) && gpuTimer_->lastMs(GpuTimer::kMain)) {
    stats_.gpuCaptureMs = *gpuTimer_->lastMs(GpuTimer::kCapture);
    stats_.gpuFrameMs = stats_.gpuCaptureMs + *gpuTimer_->lastMs(GpuTimer::kMain);
  }
  stats_.mainDrawCalls = main.drawCalls;
  stats_.mainTriangles = main.triangles;
  if (stats_.error.empty() && !renderer_->programError().empty()) {
    stats_.error = "a shader did not build: " + renderer_->programError();
  }
  if (errorView) renderErrorView(objects, view, draws, framebuffer);
  lastPlan_ = plan;
  inside_.afterFrame(plan);
  if (inside_.on()) inside_.draw(*renderer_, scene_, plan, framebuffer, width, height);
  if (!firstFrameDrawn_) {
    // The first frame is on screen: now build what the meshes were drawn without.
    firstFrameDrawn_ = true;
    startBuilds();
  }
  return stats_;
}

void Demo::renderErrorView(const std::vector<PlannedObject>& objects, const ViewParams& view,
                           const std::vector<DrawItem>& draws, unsigned framebuffer) {
  const auto start = std::chrono::steady_clock::now();
  CaptureContext context = captureContext();
  context.accuracy.search = Search::Exact;
  context.captureLod = 0.0f;
  const FramePlan plan = exactPlanner_.plan(objects, context, PlannerSettings{});
  Result<PassCounts> capture =
      exactRenderer_->capture(scene_, stats_.timeSeconds, plan, camera_.eye());
  if (!capture) exactPlanner_.invalidate();
  exactTracer_->setMark(true);
  exactRenderer_->drawMain(scene_, stats_.timeSeconds, plan, view, draws,
                           errorView_->exactFramebuffer(), stats_.width, stats_.height);
  exactTracer_->setMark(false);
  const ErrorViewStats e = errorView_->compose(framebuffer);
  stats_.errorView = true;
  stats_.errorPsnrDb = e.psnrDb;
  stats_.errorRmse = e.rmse;
  stats_.errorPixelsOver32 = e.pixelsOverThreshold;
  stats_.errorReflectorPixels = e.reflectorPixels;
  stats_.errorMax = e.maxError;
  stats_.errorViewMs = millisecondsSince(start);
}

}  // namespace reflect
