// What a reflector reads, and so which program variant (program_key.h) draws it in a pass: its
// probe's colour cubes and depth pyramid as the capture left them, its rough levels, or the sky;
// or the scene's BVH when its rays are traced (exact_tracer.h). It sets the environment
// program's per-object uniforms (the material's mix and the search's) and binds those textures.
// Built for each frame's passes from what owns them: it owns nothing.
#pragma once

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/scene.h"
#include "gfx/capture_state.h"
#include "gfx/exact_tracer.h"
#include "gfx/glass_exits.h"
#include "gfx/mesh_buffer.h"
#include "gfx/prefiltered_probes.h"
#include "gfx/program_key.h"
#include "gfx/scene_programs.h"
#include "gfx/skybox_pass.h"

namespace reflect {

class ProbeCapture;
class ProbeIrradiance;

// Where the reflectors' environments live this frame; none owned.
struct EnvironmentSources {
  const AccuracySettings& accuracy;
  const MeshBuffers* meshes;
  const ProbeCapture& probes;      // the captured cubes and depth pyramids
  const PrefilteredProbes& rough;  // their prefiltered levels, and the sky's
  const SkyboxPass* sky;           // null: no skybox
  const GlassExits& glass;
  const ExactTracer* exact;           // the traced scene (null: none yet)
  const ProbeIrradiance& irradiance;  // the probes' irradiance, for probe-lit Phong objects
};

class EnvironmentBinding {
 public:
  explicit EnvironmentBinding(const EnvironmentSources& sources) : s_(sources) {}

  // The variant that draws `item` in `pass`: its look; for a mirror or glass, whether its rays
  // are traced, its probe searched (and how) or looked up plainly.
  ProgramKey keyFor(const Scene& scene, const FramePlan& plan, const DrawItem& item,
                    const CaptureState& pass) const;
  // The traced scene's uniforms, once a pass, for a program that traces.
  void bindTracer(const EnvironmentUniforms& u, const ProgramKey& key) const;
  // Per object: a reflector's material and environment; a cube-textured object's cube; a
  // probe-lit Phong object its probe's irradiance (other Phong objects read none).
  void setForObject(const PhongUniforms&, const ProgramKey& key, const Scene&,
                    const FramePlan& plan, int object) const;
  void setForObject(const EnvironmentUniforms& u, const ProgramKey& key, const Scene& scene,
                    const FramePlan& plan, int object) const;
  // A probe-lit object that sets no radius: its parallax for each vertex of `mesh`, the mesh it is
  // drawn with (ProbeIrradiance::feedParallax), for mesh.vert's a_ambientParallax; else 0.
  GLuint parallaxFor(const Scene& scene, const FramePlan& plan, int object,
                     const MeshBuffer& mesh) const;
  void setForObject(const CubeTexturedUniforms& u, const ProgramKey& key, const Scene& scene,
                    const FramePlan& plan, int object) const;

 private:
  // The textures object `index` looks its environment up in (its probe's layers, or the sky).
  struct Textures {
    GLuint colour = 0, colour2 = 0, pyramid = 0, prefiltered = 0;
    int layers = 1, faceSize = 1, topLevel = 0;
    int filteredFaceSize = 1;  // the face size of the cube the rough levels were filtered from
    glm::vec3 centre{0.0f};
  };
  Textures texturesOf(const Scene& scene, const FramePlan& plan, int index) const;
  // The environment program's search uniforms and textures for `t`, bound to their units.
  void bind(const EnvironmentUniforms& u, const ProgramKey& key, const Scene& scene,
            const SceneObject& object, const Textures& t) const;
  // Whether object `index`'s lookup searches its probe's depths (its probe is captured, is no
  // skybox, and not every surface it sees is far enough for the plain lookup).
  bool searchesFor(const Scene& scene, const FramePlan& plan, int index) const;

  EnvironmentSources s_;
};

}  // namespace reflect
