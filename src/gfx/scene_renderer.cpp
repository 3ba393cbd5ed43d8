#include "gfx/scene_renderer.h"

namespace reflect {

Result<SceneRenderer> SceneRenderer::create(const AccuracySettings& accuracy) {
  Result<ProbeCapture> capture = ProbeCapture::create();
  if (!capture) return Result<SceneRenderer>::failure(capture.error());
  Result<ProbeIrradiance> irradiance = ProbeIrradiance::create();
  if (!irradiance) return Result<SceneRenderer>::failure(irradiance.error());
  SceneRenderer r(capture.take(), irradiance.take());
  r.accuracy_ = accuracy;
  r.programs_ = ProgramCache(accuracy.mediump);
  // The programs every scene's main pass needs are built now, so a shader that does not build
  // fails here, loudly; the other variants when a draw first needs them.
  for (const ProgramKey& key : {ProgramKey{}, ProgramKey{Look::Environment}}) {
    if (!r.programs_.get(key)) return Result<SceneRenderer>::failure(r.programs_.lastError());
  }
  if (!checkGlError("create scene renderer")) {
    return Result<SceneRenderer>::failure("GL error while creating the scene renderer");
  }
  return r;
}

std::string SceneRenderer::setSkybox(const CubeFaces& faces) {
  Result<SkyboxPass> pass = SkyboxPass::create(faces);
  if (!pass) return pass.error();
  skybox_ = std::make_unique<SkyboxPass>(pass.take());
  rough_.forgetSky();  // the old sky's levels: the next capture filters the new one
  return {};
}

EnvironmentSources SceneRenderer::environments() const {
  return {accuracy_, meshes_, capture_, rough_, skybox_.get(), glass_, exact_, irradiance_};
}

Result<PassCounts> SceneRenderer::capture(const Scene& scene, const FramePlan& plan,
                                          const glm::vec3& lightingEye,
                                          const CaptureStepObserver* afterStep) {
  glass_.update(scene, plan, meshes_, accuracy_);
  const EnvironmentBinding binding(environments());
  const PassDrawer drawer(programs_, binding, meshes_);
  const CaptureRequest request{scene, plan, lightingEye, accuracy_, skybox_.get(), afterStep};
  Result<ProbeCapture::Outcome> captured = capture_.capture(request, drawer);
  if (!captured) return Result<PassCounts>::failure(captured.error());
  if (captured.value().finished) {
    if (prefilterTiming_) prefilterTiming_(AfterCapture::Prefilter, true);
    capture_.buildBoxChains(plan);
    Result<double> filtered = rough_.filter(
        plan, [this](int owner) { return capture_.target(owner); }, skybox_.get(), accuracy_);
    if (prefilterTiming_) prefilterTiming_(AfterCapture::Prefilter, false);
    if (!filtered) return Result<PassCounts>::failure(filtered.error());
    if (prefilterTiming_) prefilterTiming_(AfterCapture::Irradiance, true);
    lastProjections_ = irradiance_.update(plan, [this](int owner) {
      const CubeCaptureTarget* t = capture_.target(owner);
      return std::pair<GLuint, int>(t ? t->texture() : 0, t ? t->faceSize() : 0);
    });
    if (prefilterTiming_) prefilterTiming_(AfterCapture::Irradiance, false);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  return captured.value().counts;
}

PassCounts SceneRenderer::drawMain(const Scene& scene, const FramePlan& plan,
                                   const ViewParams& camera, const std::vector<DrawItem>& draws,
                                   unsigned framebuffer, int width, int height,
                                   int outputDirections) {
  glass_.update(scene, plan, meshes_, accuracy_);
  const EnvironmentBinding binding(environments());
  const PassDrawer drawer(programs_, binding, meshes_);
  return drawMainPass(drawer, skybox_.get(), scene, plan, camera, draws,
                      {framebuffer, width, height, outputDirections});
}

GLuint SceneRenderer::probeTexture(int owner) const {
  const CubeCaptureTarget* t = capture_.target(owner);
  return t ? t->texture() : 0;
}

std::vector<std::string> SceneRenderer::unsetUniforms() const {
  std::vector<std::string> out = programs_.unsetUniforms();
  if (skybox_) {
    for (const std::string& name : skybox_->unlisted()) out.push_back("skybox: " + name);
  }
  for (const std::string& name : capture_.unlisted()) out.push_back("depth pyramid: " + name);
  return out;
}

}  // namespace reflect
