#include "app/demo.h"

#include <algorithm>

#include "core/capture_near.h"
#include "core/scene_file.h"
#include "core/settings_schema.h"
#include "gfx/gl.h"
#include "gfx/gl_handle.h"

namespace reflect {

Demo::Demo(Scene scene) : scene_(std::move(scene)), camera_(scene_.camera) {
  meshes_.setLodSettings(plannerSettings_.captureLod > 0.0f, plannerSettings_.viewLod > 0.0f);
}

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

std::string Demo::setMeshData(const std::string& name, MeshData mesh) {
  return adopt(name, Result<MeshData>(std::move(mesh)));
}

std::string Demo::adoptLoaded(const std::string& name, Result<LoadedMesh> loaded) {
  std::string error = meshes_.adoptLoaded(name, std::move(loaded));
  if (error.empty()) graphics_.meshReplaced(name, meshes_);
  return error;
}

std::string Demo::adopt(const std::string& name, Result<MeshData> mesh) {
  std::string error = meshes_.adopt(name, std::move(mesh));
  if (error.empty()) graphics_.meshReplaced(name, meshes_);
  return error;
}

void Demo::noteLevelUse(const FramePlan& plan) {
  // Chunks cull a captured face's draws, and capture LOD's levels are drawn only there: a frame
  // that captures no probe draws neither (the main pass draws whole meshes, or view LOD's levels,
  // which the settings alone ask for). But the planner prices a capture by the triangles its
  // faces would draw, at the levels there are: a traced reflector counts as well where its
  // capture, priced with no triangles at all, would have won (by the planner's own margin), so
  // that levels not built yet never keep the planner from the capture they would make cheaper.
  bool captures = !plan.probes.empty();
  const MethodCosts& costs = planner_.costs();
  for (const MethodChoice& choice : planner_.choices()) {
    const double withoutTriangles = choice.captureMs - choice.capture.triangles * costs.triangle;
    captures = captures || withoutTriangles * costs.hysteresis < choice.traceMs;
  }
  if (captures) meshes_.noteCaptures();
}

std::string Demo::loadMeshesFrom(const std::string& directory) {
  std::vector<std::string> warnings;
  for (const std::string& name : scene_.meshNames()) {
    std::string error = loadMesh(name, directory + "/" + name);
    if (!error.empty()) return error;
    const std::vector<std::string>& some = meshes_.lastWarnings();
    warnings.insert(warnings.end(), some.begin(), some.end());
  }
  meshes_.lastWarnings() = std::move(warnings);
  return {};
}

std::string Demo::captureNearNotice() const {
  return reflect::captureNearNotice(scene_, [this](const std::string& name) -> const Bounds* {
    const MeshData* mesh = meshes_.base(name);
    return mesh ? &mesh->bounds : nullptr;
  });
}

const MeshData* Demo::meshLevel(const std::string& name, int lod) const {
  return lod == 0 ? meshes_.base(name) : nullptr;
}

std::vector<size_t> Demo::levelTriangles(const std::string& name) const {
  std::vector<size_t> triangles;
  for (const LevelInfo& level : meshes_.levelInfo(name)) triangles.push_back(level.triangles);
  return triangles;
}

std::string Demo::addObject(const SceneObject& object) {
  if (!meshes_.has(object.mesh)) return object.mesh + ": not loaded";
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
  std::string error = graphics_.setSkybox(faces);
  if (!error.empty()) return error;
  skyboxContent_ = contentHash(faces);
  skybox_ = std::move(faces);
  return {};
}

void Demo::setPlannerSettings(const PlannerSettings& settings) {
  plannerSettings_ = settings;
  meshes_.setLodSettings(settings.captureLod > 0.0f, settings.viewLod > 0.0f);
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
  const SceneRenderer* renderer = graphics_.renderer();
  return renderer && reflector >= 0 ? renderer->probeTexture(reflector) : 0;
}

std::string Demo::initGraphics() {
  planner_.invalidate();  // a new renderer has no captures yet
  generalCaptured_ = false;
  // The GL may allow less than kMaxCubeFaceSize; capture targets are made at what it allows.
  GLint maxCubeSize = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxCubeSize);
  scene_.capture.faceSize = std::clamp(scene_.capture.faceSize, 1, std::max(1, maxCubeSize));
  return graphics_.init(accuracy_, showError_, meshes_, skyboxFaces());
}

std::string Demo::setShowError(bool on) {
  if (on == showError_) return {};
  showError_ = on;
  return graphics_.setUpExact(accuracy_, showError_, meshes_, skyboxFaces());
}

std::string Demo::setAccuracySettings(const AccuracySettings& settings) {
  for (const auto& field : accuracyFields()) {
    std::string problem = field.info.check(field.get(settings));
    if (!problem.empty()) return problem;
  }
  if (settings == accuracy_) return {};
  accuracy_ = settings;
  return graphics_.ready() ? initGraphics() : std::string();
}

void Demo::releaseGraphics() {
  graphics_.release(meshes_);
  inside_.release();
  pick_.release();
  planner_.invalidate();
  exactPlanner_.invalidate();
  generalCaptured_ = false;
}

void Demo::loseGraphics() {
  markGlContextLost();
  releaseGraphics();
}

}  // namespace reflect
