// Draws a Scene with GL ES 3.0 as a FramePlan says: each probe's planned cube faces (objects at
// their planned level of detail; a second, peeled layer where the plan asks for one; then the
// faces' depth chains), then the main pass. Materials: Phong, mirror and glass (an environment
// lookup), cube-textured (Ex12-1); the skybox is drawn last into every target.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/frame_steps.h"
#include "core/mesh_data.h"
#include "core/result.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/capture_state.h"
#include "gfx/cube_capture_target.h"
#include "gfx/exact_tracer.h"
#include "gfx/glass_interior_map.h"
#include "gfx/mesh_buffer.h"
#include "gfx/probe_prefilter.h"
#include "gfx/program_key.h"
#include "gfx/scene_programs.h"
#include "gfx/shader_program.h"
#include "gfx/skybox_pass.h"
#include "gfx/uniform_table.h"

namespace reflect {

struct ViewParams {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
};

// Step through a frame: told after each capture step (core/frame_steps.h's order, from 0) is
// drawn; returns false to stop the capture there.
using CaptureStepObserver = std::function<bool(int step)>;

struct PassCounts {
  int drawCalls = 0;
  size_t triangles = 0;
  PassCounts& operator+=(const PassCounts& o) {
    drawCalls += o.drawCalls;
    triangles += o.triangles;
    return *this;
  }
};

class SceneRenderer {
 public:
  static Result<SceneRenderer> create(const AccuracySettings& accuracy = {});
  const AccuracySettings& accuracy() const { return accuracy_; }

  // The meshes it draws, by the names the scene knows them by; not owned. Every renderer of a
  // demo draws from the same set, so each mesh is on the GPU once.
  void setMeshes(const MeshBuffers* meshes) { meshes_ = meshes; }
  // The static cube map behind the scene (and the environment of Skybox-lit objects).
  std::string setSkybox(const CubeFaces& faces);

  // Renders the plan's faces (scene_renderer_capture.cpp). `lightingEye` is the main camera's
  // eye: the course lights captures as seen from it. Probe targets are created (or resized) on
  // first use. `afterStep` (null: none) is told after each step and may stop the capture.
  Result<PassCounts> capture(const Scene& scene, double seconds, const FramePlan& plan,
                             const glm::vec3& lightingEye,
                             const CaptureStepObserver* afterStep = nullptr);
  // `draws`: every object with its level of detail (planViewDraws). Probed objects sample the
  // cubes of `plan`'s probes (as a capture left them). With `outputDirections` (one of the
  // kOutput values below), mirrors and glass write what they looked up instead of a colour, for
  // a float target to read back.
  PassCounts drawMain(const Scene& scene, double seconds, const FramePlan& plan,
                      const ViewParams& camera, const std::vector<DrawItem>& draws,
                      unsigned framebuffer, int width, int height, int outputDirections = 0);
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
  const CubeCaptureTarget* probeTarget(int owner) const;
  // Prefiltered cubes made so far (one per probe with a rough reader), and the GGX samples the
  // last capture's prefilter passes took (texels x samples): for tests and the frame's stats.
  size_t prefilteredCubes() const { return prefiltered_.size(); }
  // The static sky's prefiltered cube (0 when no rough reader reads the sky), for tests.
  GLuint skyPrefilteredTexture() const { return skyPrefiltered_ ? skyPrefiltered_->texture() : 0; }
  double lastFilterSamples() const { return lastFilterSamples_; }
  // Told just before (true) and after (false) each capture's prefilter pass, so that the caller
  // can time it on its own clock (Demo's stats); unset (the default), nothing is called.
  using PrefilterTiming = std::function<void(bool starting)>;
  void setPrefilterTiming(PrefilterTiming timing) { prefilterTiming_ = std::move(timing); }
  // Glass interior maps made so far (one per non-sphere glass mesh in use), for tests.
  size_t glassInteriorMaps() const { return glassInteriors_.count(); }
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
  SceneRenderer() = default;
  // The capture's parts (scene_renderer_capture.cpp).
  struct CaptureJob;
  // The probe's target, made (or remade) for the format the probe needs now.
  Result<CubeCaptureTarget*> captureTarget(const Scene& scene, const ProbePlan& probe);
  // Draws `face`'s passes; false when the step observer stopped the capture.
  bool captureFace(CaptureJob& job, const ProbePlan& probe, const CubeCaptureTarget& t,
                   const FacePlan& face, PassCounts& counts);
  PassCounts capturePass(const CaptureJob& job, const ProbePlan& probe, const CubeCaptureTarget& t,
                         const FacePlan& face, StepPass pass,
                         const std::vector<DrawItem>& backDraws);
  // The variant that draws `item` in `pass`: its look; for a mirror or glass, whether its rays
  // are traced, its probe searched (and how) or looked up plainly.
  ProgramKey keyFor(const Scene& scene, const FramePlan& plan, const DrawItem& item,
                    const CaptureState& pass) const;
  // What every draw of one pass shares.
  struct DrawPass {
    const Scene& scene;
    double seconds;
    const FramePlan& plan;
    glm::mat4 viewProjection;
    glm::vec3 lightingEye;     // where Phong's viewer is (the main camera's eye, as the course)
    glm::vec3 environmentEye;  // where a mirror's view rays start (a capture: the probe centre)
    CaptureState capture;
    int outputDirections = 0;
  };
  // Draws `draws` grouped by program, each group with its program's own type.
  PassCounts drawItems(const DrawPass& pass, const std::vector<DrawItem>& draws);
  // What each program sets once a pass (the light; the output and the tracer) and per object
  // (the material and its environment), one overload a program type (scene_programs.h).
  void setForPass(const PhongUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  void setForPass(const EnvironmentUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  void setForPass(const CubeTexturedUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  void setForObject(const PhongUniforms&, const ProgramKey&, const DrawPass&, const DrawItem&,
                    const glm::mat4&) const {}
  void setForObject(const EnvironmentUniforms& u, const ProgramKey& key, const DrawPass& pass,
                    const DrawItem& item, const glm::mat4& model) const;
  void setForObject(const CubeTexturedUniforms& u, const ProgramKey& key, const DrawPass& pass,
                    const DrawItem& item, const glm::mat4& model) const;
  // Draws one object with the program of type `Uniforms` in use.
  template <typename Uniforms>
  PassCounts drawObject(const Uniforms& u, const ProgramKey& key, const DrawPass& pass,
                        const DrawItem& item) const;
  // What object `index` looks its environment up in (its probe's layers, or the sky): bound to
  // their units, for the program in use (scene_renderer_environment.cpp).
  struct EnvironmentBinding {
    GLuint colour = 0, colour2 = 0, pyramid = 0, prefiltered = 0;
    int layers = 1, faceSize = 1, topLevel = 0;
    int filteredFaceSize = 1;  // the face size of the cube the rough levels were filtered from
    glm::vec3 centre{0.0f};
  };
  EnvironmentBinding environmentOf(const Scene& scene, const FramePlan& plan, int index) const;
  // The environment program's search uniforms and textures for `b`.
  void bindEnvironment(const EnvironmentUniforms& u, const ProgramKey& key, const Scene& scene,
                       const SceneObject& object, const EnvironmentBinding& b) const;
  // Whether object `index`'s lookup searches its probe's depths (its probe is captured, is no
  // skybox, and not every surface it sees is far enough for the plain lookup).
  bool searchesFor(const Scene& scene, const FramePlan& plan, int index) const;
  // After the faces are drawn: each probe's rough levels the plan filters this frame.
  Result<double> prefilterProbes(const FramePlan& plan);
  // The static sky's levels for its rough readers (FramePlan::skyRoughLevels): filtered when the
  // plan says so or when its cube does not exist yet; freed when no rough reader reads the sky.
  Result<double> prefilterSky(const FramePlan& plan);
  // The prefilter pass, built the first time something is filtered.
  Result<ProbePrefilter*> prefilterPass();
  // Makes the interior maps of the scene's glass meshes that are not spheres the first time they
  // are needed (glassSurfaces 2).
  void prepareGlassExits(const Scene& scene, const FramePlan& plan);
  // The interior map `object`, placed by `model`, leaves through (nullptr: a sphere, no glass, one
  // surface, or no map).
  const GlassInteriorMap* glassExitOf(const SceneObject& object, const glm::mat4& model) const;
  const MeshBuffer* mesh(const std::string& name, int lod) const;
  // Drops the interior maps of glass meshes replaced in the shared set since they were made.
  void forgetReplacedGlassMeshes(const Scene& scene);

  ProgramCache programs_{false};
  GlassInteriorMaps glassInteriors_;
  DepthPyramidPrograms pyramid_;
  std::unique_ptr<SkyboxPass> skybox_;
  // Bound to the depth units whenever nothing else is, so no program ever samples a texture the
  // pass renders into (a feedback loop WebGL refuses to draw).
  TextureHandle emptyDepths_;
  TextureHandle emptyPyramid_;
  VertexArrayHandle emptyVertexArray_;  // the reduction's fullscreen triangle has no attributes
  std::map<int, CubeCaptureTarget> probes_;          // by owning object's index
  std::map<int, PrefilteredCube> prefiltered_;       // by owning object's index: rough readers only
  std::unique_ptr<ProbePrefilter> prefilter_;        // built the first time a probe is filtered
  std::unique_ptr<PrefilteredCube> skyPrefiltered_;  // the sky's rough levels: rough readers only
  double lastFilterSamples_ = 0.0;
  PrefilterTiming prefilterTiming_;
  AccuracySettings accuracy_;
  const MeshBuffers* meshes_ = nullptr;
  std::map<std::string, uint64_t> glassMeshSerials_;  // each glass mesh's serial when last seen
  const ExactTracer* exact_ = nullptr;
};

}  // namespace reflect
