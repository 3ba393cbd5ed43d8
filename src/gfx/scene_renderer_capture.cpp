// SceneRenderer's capture: each probe's planned faces, pass by pass (core/frame_steps.h names the
// passes and their order, one rule for the renderer and the step list), then the faces' depth
// pyramid. With an observer, it is told after each step and may stop the capture there (Inside
// the frame, "Step through a frame"); without one the passes run as they always did.
#include <cmath>

#include "core/cube_faces.h"
#include "core/depth_code.h"
#include "core/frame_steps.h"
#include "core/ggx.h"
#include "core/normal_matrix.h"
#include "gfx/scene_renderer.h"
#include "gfx/scene_renderer_detail.h"

namespace reflect {
namespace {

// Whether any surface of a mesh drawn with `model` may face away from `centre` (the fragment
// test capture_output.glsl's pass 3 keeps). A flat mesh faces one way from every point: when
// `centre` is clearly on its front side, pass 3 discards all of it, and need not draw it (the
// ground quad covered half of four faces and all of a fifth there, every fragment discarded).
bool mayFaceAway(const MeshBuffer* mesh, const glm::mat4& model, const glm::vec3& centre) {
  if (!mesh || !mesh->flat()) return true;
  const glm::vec3 normal = normalMatrixOf(glm::mat3(model)) * mesh->flatNormal();
  const glm::vec3 offset = glm::vec3(model * glm::vec4(mesh->flatPoint(), 1.0f)) - centre;
  // A margin for the interpolated normal's rounding: a probe (nearly) in the plane draws it.
  return glm::dot(normal, offset) > -1e-4f * glm::length(normal) * glm::length(offset);
}

}  // namespace

using renderer_detail::bindTexture;

// What every face of one capture shares.
struct SceneRenderer::CaptureJob {
  const Scene& scene;
  double seconds;
  const FramePlan& plan;
  glm::vec3 lightingEye;
  glm::mat4 projection;
  // Where nothing is drawn, the stored distance is the far plane's: the world ends there, as it
  // does for the main camera. (Measured on the default scene, this beat an infinite distance for
  // the linear search by 2 dB.) A skybox is drawn over it, infinitely far, and is seen along the
  // ray's own direction.
  float farAlpha;
  unsigned farCode;
  const CaptureStepObserver* afterStep;  // null: no stepping
  int nextStep = 0;
  // Tells the observer a step is drawn; true when it asks to stop there.
  bool stopAfterStep() { return afterStep != nullptr && !(*afterStep)(nextStep++); }
};

Result<CubeCaptureTarget*> SceneRenderer::captureTarget(const Scene& scene,
                                                        const ProbePlan& probe) {
  // Depths only for a probe whose reflectors search them.
  const bool depths = capturesDepths(probe, accuracy_);
  const CaptureFormat format{
      scene.capture.faceSize,   accuracy_.halfFloat, accuracy_.depthBits, accuracy_.mipmaps, depths,
      depths ? probe.layers : 1};
  auto target = probes_.find(probe.reflector);
  if (target == probes_.end() || !(target->second.format() == format)) {
    Result<CubeCaptureTarget> created = CubeCaptureTarget::create(format);
    if (!created) return Result<CubeCaptureTarget*>::failure(created.error());
    probes_.erase(probe.reflector);
    target = probes_.emplace(probe.reflector, created.take()).first;
  }
  return &target->second;
}

PassCounts SceneRenderer::capturePass(const CaptureJob& job, const ProbePlan& probe,
                                      const CubeCaptureTarget& t, const FacePlan& face,
                                      StepPass step, const std::vector<DrawItem>& backDraws) {
  const Scene& scene = job.scene;
  const int layer = static_cast<int>(step);
  const glm::mat4 view = cubeFaceView(probe.centre, face.face);
  const glm::vec3 axis = kCubeFaces[static_cast<size_t>(face.face)].direction;
  if (layer == 3) {
    t.bindBackPass(face.face);
  } else {
    t.bindFace(face.face, layer - 1);
    const float clear[3] = {scene.clearColour.r, scene.clearColour.g, scene.clearColour.b};
    const unsigned codes[2] = {job.farCode, job.farCode};
    t.clearFace(clear, capturedSearch(accuracy_.search) == Search::Linear ? job.farAlpha : 1.0f,
                codes);
  }
  // Passes 2 and 3 peel behind pass 1's depths, and pass 2 behind pass 3's backs.
  bindTexture(kPeelDepthsUnit, GL_TEXTURE_2D_ARRAY,
              layer == 1 ? emptyDepths_.id() : t.faceDepths(0));
  bindTexture(kPeelBacksUnit, GL_TEXTURE_2D_ARRAY, layer == 2 ? t.backs() : emptyDepths_.id());
  // Other mirrors in view use their cube as it was before this frame's capture of them (one
  // bounce); they are seen from the probe centre.
  const DrawPass pass{scene,
                      job.seconds,
                      job.plan,
                      job.projection * view,
                      job.lightingEye,
                      probe.centre,
                      {layer, probe.centre, axis, scene.capture.near, face.face},
                      kOutputColour};
  const PassCounts counts = drawItems(pass, layer == 1   ? face.draws
                                            : layer == 3 ? backDraws
                                                         : face.secondLayerDraws);
  if (skybox_ && layer != 3) skybox_->draw(job.projection, view, pass.capture);
  if (layer == 3) CubeCaptureTarget::endBackPass();
  return counts;
}

bool SceneRenderer::captureFace(CaptureJob& job, const ProbePlan& probe, const CubeCaptureTarget& t,
                                const FacePlan& face, PassCounts& counts) {
  const Scene& scene = job.scene;
  const std::vector<StepPass> passes = capturePasses(face);
  // A face of a two-layer probe that needs one layer clears what the other two passes would
  // write.
  if (t.format().layers == 2 && face.layers == 1) {
    const float clear[3] = {scene.clearColour.r, scene.clearColour.g, scene.clearColour.b};
    const unsigned codes[2] = {job.farCode, job.farCode};
    t.bindFace(face.face, 1);
    t.clearFace(clear, 1.0f, codes);
    t.bindBackPass(face.face);
    CubeCaptureTarget::endBackPass();
  }
  // Pass 3 keeps only surfaces facing away from the probe: it skips what cannot have any.
  std::vector<DrawItem> backDraws;
  if (face.layers == 2) {
    for (const DrawItem& d : face.draws) {
      const SceneObject& object = scene.objects[static_cast<size_t>(d.object)];
      if (mayFaceAway(mesh(object.mesh, d.lod), job.plan.modelOf(d.object), probe.centre)) {
        backDraws.push_back(d);
      }
    }
  }
  bool stopped = false;
  for (StepPass pass : passes) {
    counts += capturePass(job, probe, t, face, pass, backDraws);
    if (job.stopAfterStep()) {
      stopped = true;
      break;
    }
  }
  bindTexture(kPeelDepthsUnit, GL_TEXTURE_2D_ARRAY, emptyDepths_.id());
  bindTexture(kPeelBacksUnit, GL_TEXTURE_2D_ARRAY, emptyDepths_.id());
  return !stopped;
}

Result<PassCounts> SceneRenderer::capture(const Scene& scene, double seconds, const FramePlan& plan,
                                          const glm::vec3& lightingEye,
                                          const CaptureStepObserver* afterStep) {
  forgetReplacedGlassMeshes(scene);
  prepareGlassExits(scene, plan);
  PassCounts counts;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  CaptureJob job{scene,
                 seconds,
                 plan,
                 lightingEye,
                 cubeFaceProjection(scene.capture.near, scene.capture.far),
                 scene.capture.far / (scene.capture.far + scene.capture.near),
                 depthCode(scene.capture.far / scene.capture.near),
                 afterStep};
  bool going = true;
  for (const ProbePlan& probe : plan.probes) {
    if (probe.faces.empty() || !going) continue;
    Result<CubeCaptureTarget*> target = captureTarget(scene, probe);
    if (!target) return Result<PassCounts>::failure(target.error());
    const CubeCaptureTarget& t = *target.value();
    for (const FacePlan& face : probe.faces) {
      going = going && captureFace(job, probe, t, face, counts);
    }
    if (!going) break;
    glBindVertexArray(emptyVertexArray_.id());
    unsigned captured = 0;
    for (const FacePlan& face : probe.faces) captured |= 1u << face.face;
    t.finish(pyramid_, captured);
    glEnable(GL_DEPTH_TEST);
    if (capturesDepths(probe, accuracy_) && job.stopAfterStep()) going = false;
  }
  if (going) {
    if (prefilterTiming_) prefilterTiming_(true);
    Result<double> filtered = prefilterProbes(plan);
    if (prefilterTiming_) prefilterTiming_(false);
    if (!filtered) return Result<PassCounts>::failure(filtered.error());
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  checkGlError("capture");
  return counts;
}

Result<double> SceneRenderer::prefilterProbes(const FramePlan& plan) {
  lastFilterSamples_ = 0.0;
  // A probe no rough reader reads any more keeps no filtered cube.
  for (auto it = prefiltered_.begin(); it != prefiltered_.end();) {
    const ProbePlan* probe = plan.probeOf(it->first);
    const bool needed = probe && probe->reflector == it->first && !probe->roughLevels.empty();
    it = needed ? std::next(it) : prefiltered_.erase(it);
  }
  for (const ProbePlan& probe : plan.probes) {
    if (probe.filterFaces == 0 || probe.roughLevels.empty()) continue;
    auto captured = probes_.find(probe.reflector);
    if (captured == probes_.end()) continue;  // nothing captured yet to filter
    Result<ProbePrefilter*> pass = prefilterPass();
    if (!pass) return Result<double>::failure(pass.error());
    const CubeCaptureTarget& t = captured->second;
    glBindVertexArray(emptyVertexArray_.id());
    const PrefilterJob job{t.texture(0),
                           t.faceSize(),
                           t.format().halfFloat,
                           probe.roughLevels,
                           usableRoughLevels(accuracy_.roughLevels, t.faceSize()),
                           accuracy_.filterSamples,
                           probe.filterFaces};
    Result<double> taken = pass.value()->filter(job, prefiltered_[probe.reflector]);
    if (!taken) return taken;
    lastFilterSamples_ += taken.value();
  }
  Result<double> sky = prefilterSky(plan);
  if (!sky) return sky;
  lastFilterSamples_ += sky.value();
  return lastFilterSamples_;
}

Result<ProbePrefilter*> SceneRenderer::prefilterPass() {
  if (!prefilter_) {
    Result<ProbePrefilter> made = ProbePrefilter::create();
    if (!made) return Result<ProbePrefilter*>::failure(made.error());
    prefilter_ = std::make_unique<ProbePrefilter>(made.take());
  }
  return prefilter_.get();
}

Result<double> SceneRenderer::prefilterSky(const FramePlan& plan) {
  if (!skybox_ || plan.skyRoughLevels.empty()) {
    skyPrefiltered_.reset();  // no rough reader reads the sky
    return 0.0;
  }
  // The plan filters the static sky once, when its readers' levels change. A renderer that has
  // no filtered sky yet (made after the plan's first frame, e.g. after a lost context, or given a
  // new skybox) filters it now all the same: a rough reader must never read an empty cube.
  if (!plan.filterSky && skyPrefiltered_) return 0.0;
  Result<ProbePrefilter*> pass = prefilterPass();
  if (!pass) return Result<double>::failure(pass.error());
  if (!skyPrefiltered_) skyPrefiltered_ = std::make_unique<PrefilteredCube>();
  glBindVertexArray(emptyVertexArray_.id());
  const int faceSize = skybox_->faceSize();
  const PrefilterJob job{skybox_->texture(),
                         faceSize,
                         false,  // the sky is RGBA8
                         plan.skyRoughLevels,
                         usableRoughLevels(accuracy_.roughLevels, faceSize),
                         accuracy_.filterSamples,
                         0x3Fu};
  return pass.value()->filter(job, *skyPrefiltered_);
}

}  // namespace reflect
