#include "gfx/prefiltered_probes.h"

#include "core/ggx.h"

namespace reflect {

GLuint PrefilteredProbes::probeTexture(int owner) const {
  auto it = probes_.find(owner);
  return it == probes_.end() ? 0 : it->second.texture();
}

Result<ProbePrefilter*> PrefilteredProbes::pass() {
  if (!pass_) {
    Result<ProbePrefilter> made = ProbePrefilter::create();
    if (!made) return Result<ProbePrefilter*>::failure(made.error());
    pass_ = std::make_unique<ProbePrefilter>(made.take());
  }
  if (!emptyVertexArray_) emptyVertexArray_ = VertexArrayHandle(genVertexArray());
  glBindVertexArray(emptyVertexArray_.id());
  return pass_.get();
}

Result<double> PrefilteredProbes::filter(const FramePlan& plan, const CapturedCube& captured,
                                         const SkyboxPass* sky, const AccuracySettings& accuracy) {
  lastSamples_ = 0.0;
  // A probe no rough reader reads any more keeps no filtered cube.
  for (auto it = probes_.begin(); it != probes_.end();) {
    const ProbePlan* probe = plan.probeOf(it->first);
    const bool needed = probe && probe->reflector == it->first && !probe->roughLevels.empty();
    it = needed ? std::next(it) : probes_.erase(it);
  }
  for (const ProbePlan& probe : plan.probes) {
    if (probe.filterFaces == 0 || probe.roughLevels.empty()) continue;
    const CubeCaptureTarget* t = captured(probe.reflector);
    if (!t) continue;  // nothing captured yet to filter
    Result<ProbePrefilter*> filterPass = pass();
    if (!filterPass) return Result<double>::failure(filterPass.error());
    const PrefilterJob job{t->texture(0),
                           t->faceSize(),
                           t->format().halfFloat,
                           probe.roughLevels,
                           usableRoughLevels(accuracy.roughLevels, t->faceSize()),
                           accuracy.filterSamples,
                           probe.filterFaces};
    Result<double> taken = filterPass.value()->filter(job, probes_[probe.reflector]);
    if (!taken) return taken;
    lastSamples_ += taken.value();
  }
  Result<double> skyTaken = filterSky(plan, sky, accuracy);
  if (!skyTaken) return skyTaken;
  lastSamples_ += skyTaken.value();
  glBindVertexArray(0);
  return lastSamples_;
}

Result<double> PrefilteredProbes::filterSky(const FramePlan& plan, const SkyboxPass* sky,
                                            const AccuracySettings& accuracy) {
  if (!sky || plan.skyRoughLevels.empty()) {
    sky_.reset();  // no rough reader reads the sky
    return 0.0;
  }
  // The plan filters the static sky once, when its readers' levels change. A renderer that has
  // no filtered sky yet (made after the plan's first frame, e.g. after a lost context, or given a
  // new skybox) filters it now all the same: a rough reader must never read an empty cube.
  if (!plan.filterSky && sky_) return 0.0;
  Result<ProbePrefilter*> filterPass = pass();
  if (!filterPass) return Result<double>::failure(filterPass.error());
  if (!sky_) sky_ = std::make_unique<PrefilteredCube>();
  const int faceSize = sky->faceSize();
  const PrefilterJob job{sky->texture(),
                         faceSize,
                         false,  // the sky is RGBA8
                         plan.skyRoughLevels,
                         usableRoughLevels(accuracy.roughLevels, faceSize),
                         accuracy.filterSamples,
                         0x3Fu};
  return filterPass.value()->filter(job, *sky_);
}

}  // namespace reflect
