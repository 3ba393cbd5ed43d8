// The rough readers' prefiltered levels (core/ggx.h): after the faces are captured, each probe's
// levels the plan filters this frame, and the static sky's when its readers' levels change. One
// job: it keeps the filtered cubes and runs the prefilter pass (probe_prefilter.h) over what the
// capture left; the caller times it (Demo's stats), the environment binding reads the cubes.
#pragma once

#include <functional>
#include <map>
#include <memory>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/result.h"
#include "gfx/cube_capture_target.h"
#include "gfx/gl_handle.h"
#include "gfx/probe_prefilter.h"
#include "gfx/skybox_pass.h"

namespace reflect {

class PrefilteredProbes {
 public:
  // Filters what `plan` asks for: the levels of each probe whose captured cube `captured(owner)`
  // gives (null: nothing captured yet), and the sky's. Returns the samples taken (texels x
  // samples); a probe no rough reader reads any more loses its filtered cube.
  using CapturedCube = std::function<const CubeCaptureTarget*(int owner)>;
  Result<double> filter(const FramePlan& plan, const CapturedCube& captured, const SkyboxPass* sky,
                        const AccuracySettings& accuracy);
  // The levels filtered for the probe owned by object `owner` (0: none).
  GLuint probeTexture(int owner) const;
  // The static sky's levels (0 when no rough reader reads the sky).
  GLuint skyTexture() const { return sky_ ? sky_->texture() : 0; }
  // A new skybox: its levels are filtered again by the next filter().
  void forgetSky() { sky_.reset(); }
  size_t probeCubes() const { return probes_.size(); }
  double lastSamples() const { return lastSamples_; }

 private:
  Result<ProbePrefilter*> pass();  // built the first time something is filtered
  Result<double> filterSky(const FramePlan& plan, const SkyboxPass* sky,
                           const AccuracySettings& accuracy);

  std::map<int, PrefilteredCube> probes_;  // by owning object's index: rough readers only
  std::unique_ptr<PrefilteredCube> sky_;
  std::unique_ptr<ProbePrefilter> pass_;
  VertexArrayHandle emptyVertexArray_;  // the filter's fullscreen triangle has no attributes
  double lastSamples_ = 0.0;
};

}  // namespace reflect
