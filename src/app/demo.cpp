#include "app/demo.h"

#include <chrono>

#include "core/obj_loader.h"
#include "gfx/gl.h"

namespace reflect {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

Demo::Demo(Scene scene) : scene_(std::move(scene)), camera_(scene_.camera) {}

std::string Demo::loadMesh(const std::string& name, const std::string& path) {
  return adopt(name, loadObjFile(path));
}

std::string Demo::loadMeshText(const std::string& name, const std::string& text,
                               const std::string& source) {
  return adopt(name, parseObj(text, source));
}

std::string Demo::adopt(const std::string& name, Result<MeshData> mesh) {
  if (!mesh) return mesh.error();
  if (renderer_) renderer_->setMesh(name, mesh.value());
  meshes_[name] = mesh.take();
  return {};
}

std::string Demo::loadMeshesFrom(const std::string& directory) {
  for (const std::string& name : scene_.meshNames()) {
    std::string error = loadMesh(name, directory + "/" + name);
    if (!error.empty()) return error;
  }
  return {};
}

bool Demo::hasAllMeshes() const {
  for (const std::string& name : scene_.meshNames()) {
    if (meshes_.count(name) == 0) return false;
  }
  return true;
}

std::string Demo::initGraphics() {
  renderer_.reset();
  Result<SceneRenderer> renderer = SceneRenderer::create(scene_.capture.faceSize);
  if (!renderer) return renderer.error();
  renderer_ = std::make_unique<SceneRenderer>(renderer.take());
  for (const auto& [name, mesh] : meshes_) renderer_->setMesh(name, mesh);
  return checkGlError("init graphics") ? std::string() : "GL error while creating resources";
}

void Demo::loseGraphics() {
  if (renderer_) renderer_->abandon();
  renderer_.reset();
}

const FrameStats& Demo::frame(double dtSeconds, unsigned framebuffer, int width, int height,
                              bool waitForGpu) {
  clock_.advance(dtSeconds);
  stats_ = FrameStats{};
  stats_.timeSeconds = clock_.seconds();
  stats_.orbitDegrees = clock_.orbitDegrees();
  stats_.timing = waitForGpu ? "gpu-finish" : "cpu-submit";
  if (!renderer_ || width < 1 || height < 1) return stats_;  // hidden canvas: nothing to draw
  stats_.cubeFaceSize = renderer_->cubeFaceSize();

  const auto start = std::chrono::steady_clock::now();
  PassCounts counts = renderer_->captureProbe(scene_, stats_.orbitDegrees, camera_.eye());
  if (waitForGpu) reflect::waitForGpu();
  stats_.captureMs = millisecondsSince(start);

  const ViewParams view{camera_.view(),
                        camera_.projection(static_cast<float>(width) / static_cast<float>(height)),
                        camera_.eye()};
  counts += renderer_->drawMain(scene_, stats_.orbitDegrees, view, framebuffer, width, height);
  if (waitForGpu) reflect::waitForGpu();
  stats_.frameMs = millisecondsSince(start);

  stats_.drawCalls = counts.drawCalls;
  stats_.triangles = counts.triangles;
  stats_.facesCaptured = counts.facesCaptured;
  return stats_;
}

}  // namespace reflect
