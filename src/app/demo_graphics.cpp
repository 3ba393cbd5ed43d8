#include "app/demo_graphics.h"

#include "gfx/gl.h"

namespace reflect {
namespace {

// Whether the settings may trace some reflector's rays (search exact or planned).
bool mayTrace(const AccuracySettings& accuracy) {
  return accuracy.search == Search::Exact || accuracy.search == Search::Planned;
}

}  // namespace

std::string DemoGraphics::init(const AccuracySettings& accuracy, bool showError,
                               MeshLibrary& library, const CubeFaces* skybox) {
  // The exact mode's tracer and the error view's renderer stay (the page's "auto" switches the
  // accuracy settings back and forth); setUpExact remakes the renderer if its settings changed.
  // So do the meshes: they do not depend on the settings.
  renderer_.reset();
  Result<SceneRenderer> renderer = SceneRenderer::create(accuracy);
  if (!renderer) return renderer.error();
  renderer_ = std::make_unique<SceneRenderer>(renderer.take());
  timer_ = std::make_unique<GpuTimer>();
  if (!meshes_) {
    meshes_ = std::make_unique<MeshBuffers>();
    library.setGpu(meshes_.get());
  }
  renderer_->setMeshes(meshes_.get());
  if (skybox) {
    std::string error = renderer_->setSkybox(*skybox);
    if (!error.empty()) return error;
  }
  std::string error = setUpExact(accuracy, showError, library, skybox);
  if (!error.empty()) return error;
  return checkGlError("init graphics") ? std::string() : "GL error while creating resources";
}

std::string DemoGraphics::setUpExact(const AccuracySettings& accuracy, bool showError,
                                     MeshLibrary& library, const CubeFaces* skybox) {
  if (!renderer_) return {};
  const bool traced = mayTrace(accuracy);
  renderer_->setExactTracer(nullptr);
  if (!traced && !showError) return {};  // what exists stays, unused, for the next time
  if (!tracer_) {
    Result<ExactTracer> tracer = ExactTracer::create();
    if (!tracer) return tracer.error();
    tracer_ = std::make_unique<ExactTracer>(tracer.take());
    for (const std::string& name : library.names()) tracer_->setMesh(name, library.bvh(name));
    std::string error = tracer_->setSkybox(skybox);
    if (!error.empty()) return error;
  }
  if (traced) renderer_->setExactTracer(tracer_.get());
  if (!showError) return {};
  return errorView_.setUp(accuracy, meshes_.get(), skybox, tracer_.get());
}

std::string DemoGraphics::setSkybox(const CubeFaces& faces) {
  if (renderer_) {
    std::string error = renderer_->setSkybox(faces);
    if (!error.empty()) return error;
  }
  std::string error = errorView_.setSkybox(faces);
  if (!error.empty()) return error;
  return tracer_ ? tracer_->setSkybox(&faces) : std::string();
}

void DemoGraphics::meshReplaced(const std::string& name, MeshLibrary& library) {
  if (tracer_) tracer_->setMesh(name, library.bvh(name));
}

Result<CourseFrame*> DemoGraphics::courseFrame(int faceSize) {
  if (!course_ || courseFaceSize_ != faceSize) {
    course_.reset();
    Result<CourseFrame> made = CourseFrame::create(faceSize);
    if (!made) return Result<CourseFrame*>::failure(made.error());
    course_ = std::make_unique<CourseFrame>(made.take());
    courseFaceSize_ = faceSize;
  }
  return course_.get();
}

void DemoGraphics::release(MeshLibrary& library) {
  library.setGpu(nullptr);
  course_.reset();
  errorView_.release();
  tracer_.reset();
  renderer_.reset();
  timer_.reset();
  meshes_.reset();
}

}  // namespace reflect
