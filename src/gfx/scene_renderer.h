// Draws a Scene with GL ES 3.0 as a FramePlan says: the capture (probe_capture.h: each probe's
// planned faces), the rough levels filtered from them (prefiltered_probes.h), then the main pass
// (main_pass.h). It assembles the parts and owns what they share (the programs, the probes' cubes,
// the sky, the glass exits); each job is its part's:
//   - programs: scene_programs.h (one typed class a program, built once a variant);
//   - which variant, and what a reflector reads: environment_binding.h;
//   - drawing a pass's items: pass_drawer.h;
//   - the capture: probe_capture.h; the rough levels: prefiltered_probes.h; the main pass:
//     main_pass.h;
//   - glass's far side: glass_exits.h.
// Materials: Phong, mirror and glass (an environment lookup), cube-textured (Ex12-1); the skybox
// is drawn last into every target.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/result.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/environment_binding.h"
#include "gfx/exact_tracer.h"
#include "gfx/glass_exits.h"
#include "gfx/main_pass.h"
#include "gfx/mesh_buffer.h"
#include "gfx/pass_drawer.h"
#include "gfx/prefiltered_probes.h"
#include "gfx/probe_capture.h"
#include "gfx/probe_irradiance.h"
#include "gfx/scene_programs.h"
#include "gfx/skybox_pass.h"

namespace reflect {

class SceneRenderer {
 public:
  static Result<SceneRenderer> create(const AccuracySettings& accuracy = {});
  const AccuracySettings& accuracy() const { return accuracy_; }

  // The meshes it draws, by the names the scene knows them by; not owned. Every renderer of a
  // demo draws from the same set, so each mesh is on the GPU once.
  void setMeshes(const MeshBuffers* meshes) { meshes_ = meshes; }
  // The static cube map behind the scene (and the environment of Skybox-lit objects).
  std::string setSkybox(const CubeFaces& faces);

  // Renders the plan's faces, then filters the rough levels the plan asks for. `lightingEye` is
  // the main camera's eye: the course lights captures as seen from it. Probe targets are created
  // (or resized) on first use. `afterStep` (null: none) is told after each step and may stop the
  // capture (then nothing is filtered).
  Result<PassCounts> capture(const Scene& scene, const FramePlan& plan,
                             const glm::vec3& lightingEye,
                             const CaptureStepObserver* afterStep = nullptr);
  // `draws`: every object with its level of detail (planViewDraws). Probed objects sample the
  // cubes of `plan`'s probes (as a capture left them). With `outputDirections` (one of the
  // kOutput values below), mirrors and glass write what they looked up instead of a colour, for
  // a float target to read back.
  PassCounts drawMain(const Scene& scene, const FramePlan& plan, const ViewParams& camera,
                      const std::vector<DrawItem>& draws, unsigned framebuffer, int width,
                      int height, int outputDirections = 0);
  // drawMain's outputDirections (environment.frag's u_outputDirection): the colour; the unit
  // direction looked up along (the accuracy measurement); or the search's own result unnormalised
  // (pick a pixel): the point it landed on relative to the probe centre, in the capture's
  // near-plane units, or the ray's direction itself where it searched nothing.
  static constexpr int kOutputColour = 0;
  static constexpr int kOutputDirection = 1;
  static constexpr int kOutputSearchPoint = 2;

  // The cube captured for the probe owned by object `owner` (0 before its first capture).
  GLuint probeTexture(int owner) const;
  // Its depth chain (0 without one), for tests.
  const CubeCaptureTarget* probeTarget(int owner) const { return capture_.target(owner); }
  // Prefiltered cubes made so far (one per probe with a rough reader), and the GGX samples the
  // last capture's prefilter passes took (texels x samples): for tests and the frame's stats.
  size_t prefilteredCubes() const { return rough_.probeCubes(); }
  // The static sky's prefiltered cube (0 when no rough reader reads the sky), for tests.
  GLuint skyPrefilteredTexture() const { return rough_.skyTexture(); }
  double lastFilterSamples() const { return rough_.lastSamples(); }
  // The probes' irradiance (probe-lit objects' diffuse light), and how many were projected in
  // the last capture: for tests and the frame's stats.
  const ProbeIrradiance& irradiance() const { return irradiance_; }
  int lastIrradianceProjections() const { return lastProjections_; }
  // Told just before (true) and after (false) each capture's filtering (the box chains and the
  // prefilter pass) and its irradiance projection, so that the caller can time them on its own
  // clock (Demo's stats); unset (the default), nothing is called.
  enum class AfterCapture { Prefilter, Irradiance };
  using PrefilterTiming = std::function<void(AfterCapture stage, bool starting)>;
  void setPrefilterTiming(PrefilterTiming timing) { prefilterTiming_ = std::move(timing); }
  // Glass interior maps made so far (one per non-sphere glass mesh in use), for tests.
  size_t glassInteriorMaps() const { return glass_.count(); }
  // The exact mode's scene (search: exact), bound with the environment program; not owned.
  void setExactTracer(const ExactTracer* tracer) { exact_ = tracer; }
  // The last program that failed to build, as "environment.frag (main, exact): ...", or "".
  const std::string& programError() const { return programs_.lastError(); }
  // Programs built so far (each variant once), for tests.
  size_t programCount() const { return programs_.size(); }
  // The active uniforms of the programs built so far that no table entry sets, as
  // "<variant>: <name>", for tests: a uniform a shader reads and C++ never writes.
  std::vector<std::string> unsetUniforms() const;

 private:
  SceneRenderer(ProbeCapture capture, ProbeIrradiance irradiance)
      : capture_(std::move(capture)), irradiance_(std::move(irradiance)) {}
  // What this frame's reflectors read, from the parts that own it.
  EnvironmentSources environments() const;

  ProgramCache programs_{false};
  ProbeCapture capture_;
  ProbeIrradiance irradiance_;
  PrefilteredProbes rough_;
  GlassExits glass_;
  std::unique_ptr<SkyboxPass> skybox_;
  PrefilterTiming prefilterTiming_;
  int lastProjections_ = 0;
  AccuracySettings accuracy_;
  const MeshBuffers* meshes_ = nullptr;
  const ExactTracer* exact_ = nullptr;
};

}  // namespace reflect
