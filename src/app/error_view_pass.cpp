#include "app/error_view_pass.h"

#include <chrono>

namespace reflect {

std::string ErrorViewPass::setUp(const AccuracySettings& current, const MeshBuffers* meshes,
                                 const CubeFaces* skybox, ExactTracer* tracer) {
  tracer_ = tracer;
  AccuracySettings exact = current;
  exact.search = Search::Exact;
  if (!renderer_ || !(renderer_->accuracy() == exact)) {
    renderer_.reset();
    Result<SceneRenderer> renderer = SceneRenderer::create(exact);
    if (!renderer) return renderer.error();
    renderer_ = std::make_unique<SceneRenderer>(renderer.take());
    renderer_->setMeshes(meshes);
    if (skybox) {
      std::string error = renderer_->setSkybox(*skybox);
      if (!error.empty()) return error;
    }
    remade_ = true;  // it holds no capture yet
  }
  // The shared meshes and the tracer may have been made again since (after a lost context).
  renderer_->setMeshes(meshes);
  renderer_->setExactTracer(tracer);
  if (!view_) {
    Result<ErrorView> view = ErrorView::create();
    if (!view) return view.error();
    view_ = std::make_unique<ErrorView>(view.take());
  }
  return {};
}

std::string ErrorViewPass::setSkybox(const CubeFaces& faces) {
  return renderer_ ? renderer_->setSkybox(faces) : std::string();
}

bool ErrorViewPass::prepare(int width, int height) {
  return view_ && renderer_ && tracer_ && view_->resize(width, height).empty();
}

bool ErrorViewPass::render(const Scene& scene, const FrameRecord& frame, unsigned framebuffer,
                           FrameStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  const FramePlan& plan = *frame.exactPlan;
  Result<PassCounts> capture = renderer_->capture(scene, plan, frame.view.eye);
  tracer_->setMark(true);
  renderer_->drawMain(scene, plan, frame.view, frame.mainDraws, view_->exactFramebuffer(),
                      frame.width, frame.height);
  tracer_->setMark(false);
  const ErrorViewStats e = view_->compose(framebuffer);
  stats.errorView = true;
  stats.errorPsnrDb = e.psnrDb;
  stats.errorRmse = e.rmse;
  stats.errorPixelsOver32 = e.pixelsOverThreshold;
  stats.errorReflectorPixels = e.reflectorPixels;
  stats.errorMax = e.maxError;
  stats.errorViewMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return static_cast<bool>(capture);
}

void ErrorViewPass::release() {
  renderer_.reset();
  view_.reset();
  tracer_ = nullptr;
}

}  // namespace reflect
