#include "gfx/probe_capture.h"

#include <cmath>

#include "core/cube_faces.h"
#include "core/depth_code.h"
#include "core/frame_steps.h"
#include "core/normal_matrix.h"
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

Result<ProbeCapture> ProbeCapture::create() {
  Result<DepthPyramidPrograms> pyramid = DepthPyramidPrograms::create();
  if (!pyramid) return Result<ProbeCapture>::failure(pyramid.error());
  ProbeCapture c;
  c.pyramid_ = pyramid.take();
  c.emptyDepths_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_2D_ARRAY, c.emptyDepths_.id());
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG16UI, 1, 1, 6);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  c.emptyPyramid_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_2D, c.emptyPyramid_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RG16UI, 1, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  for (GLint unit : {kPeelDepthsUnit, kPeelBacksUnit}) {
    bindTexture(unit, GL_TEXTURE_2D_ARRAY, c.emptyDepths_.id());
  }
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, c.emptyPyramid_.id());
  glActiveTexture(GL_TEXTURE0);
  c.lobeSampler_ = filteredSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glSamplerParameteri(c.lobeSampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(c.lobeSampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  c.emptyVertexArray_ = VertexArrayHandle(genVertexArray());
  if (!checkGlError("create probe capture")) {
    return Result<ProbeCapture>::failure("GL error while creating the probe capture");
  }
  return c;
}

const CubeCaptureTarget* ProbeCapture::target(int owner) const {
  auto it = targets_.find(owner);
  return it == targets_.end() ? nullptr : &it->second;
}

// What every face of one capture shares.
struct ProbeCapture::Job {
  const Scene& scene;
  const FramePlan& plan;
  glm::vec3 lightingEye;
  const AccuracySettings& accuracy;
  const PassDrawer& drawer;
  const SkyboxPass* sky;
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

void ProbeCapture::buildBoxChains(const FramePlan& plan) const {
  for (const ProbePlan& probe : plan.probes) {
    if (probe.faces.empty()) continue;
    if (const CubeCaptureTarget* t = target(probe.reflector)) t->buildBoxChain();
  }
}

Result<CubeCaptureTarget*> ProbeCapture::targetFor(const Scene& scene, const ProbePlan& probe,
                                                   const AccuracySettings& accuracy) {
  // Depths only for a probe whose reflectors search them.
  const bool depths = capturesDepths(probe, accuracy);
  CaptureFormat format{probe.faceSize > 0 ? probe.faceSize : scene.capture.faceSize,
                       accuracy.halfFloat,
                       accuracy.depthBits,
                       accuracy.mipmaps,
                       false,
                       depths,
                       depths ? probe.layers : 1};
  // The chain of box-filtered mips: what irradiance projects and lobe taps read.
  format.boxChain = !probe.diffuseReaders.empty() || probe.lobeTapReaders;
  auto target = targets_.find(probe.reflector);
  if (target == targets_.end() || !(target->second.format() == format)) {
    Result<CubeCaptureTarget> created = CubeCaptureTarget::create(format);
    if (!created) return Result<CubeCaptureTarget*>::failure(created.error());
    targets_.erase(probe.reflector);
    target = targets_.emplace(probe.reflector, created.take()).first;
  }
  return &target->second;
}

PassCounts ProbeCapture::capturePass(const Job& job, const ProbePlan& probe,
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
    t.clearFace(clear, capturedSearch(job.accuracy.search) == Search::Linear ? job.farAlpha : 1.0f,
                codes);
  }
  // Passes 2 and 3 peel behind pass 1's depths, and pass 2 behind pass 3's backs.
  bindTexture(kPeelDepthsUnit, GL_TEXTURE_2D_ARRAY,
              layer == 1 ? emptyDepths_.id() : t.faceDepths(0));
  bindTexture(kPeelBacksUnit, GL_TEXTURE_2D_ARRAY, layer == 2 ? t.backs() : emptyDepths_.id());
  // Other mirrors in view use their cube as it was before this frame's capture of them (one
  // bounce); they are seen from the probe centre.
  const DrawPass pass{scene,
                      job.plan,
                      job.projection * view,
                      job.lightingEye,
                      probe.centre,
                      {layer, probe.centre, axis, scene.capture.near, face.face},
                      0};  // colour
  const PassCounts counts = job.drawer.draw(pass, layer == 1   ? face.draws
                                                  : layer == 3 ? backDraws
                                                               : face.secondLayerDraws);
  if (job.sky && layer != 3) job.sky->draw(job.projection, view, pass.capture);
  if (layer == 3) CubeCaptureTarget::endBackPass();
  return counts;
}

bool ProbeCapture::captureFace(Job& job, const ProbePlan& probe, const CubeCaptureTarget& t,
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
      if (mayFaceAway(job.drawer.mesh(object.mesh, d.lod), job.plan.modelOf(d.object),
                      probe.centre)) {
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

Result<ProbeCapture::Outcome> ProbeCapture::capture(const CaptureRequest& request,
                                                    const PassDrawer& drawer) {
  const Scene& scene = request.scene;
  Outcome outcome;
  PassCounts& counts = outcome.counts;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  Job job{scene,
          request.plan,
          request.lightingEye,
          request.accuracy,
          drawer,
          request.sky,
          cubeFaceProjection(scene.capture.near, scene.capture.far),
          scene.capture.far / (scene.capture.far + scene.capture.near),
          depthCode(scene.capture.far / scene.capture.near),
          request.afterStep};
  bool& going = outcome.finished;
  for (const ProbePlan& probe : request.plan.probes) {
    if (probe.faces.empty() || !going) continue;
    Result<CubeCaptureTarget*> target = targetFor(scene, probe, request.accuracy);
    if (!target) return Result<Outcome>::failure(target.error());
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
    if (capturesDepths(probe, request.accuracy) && job.stopAfterStep()) going = false;
  }
  glBindVertexArray(0);
  checkGlError("capture");
  return outcome;
}

}  // namespace reflect
