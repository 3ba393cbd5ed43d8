// Draws one pass's items (core's DrawItem: an object at a level of detail, with its chunk
// ranges), grouped by program: each group with its program's own typed uniforms
// (scene_programs.h), the light and the pass once, the model and the material per object. The
// capture's passes and the main pass both draw through it; which variant an object gets and what
// it reads are the environment binding's (environment_binding.h).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/frame_planner.h"
#include "core/scene.h"
#include "gfx/capture_state.h"
#include "gfx/environment_binding.h"
#include "gfx/mesh_buffer.h"
#include "gfx/scene_programs.h"

namespace reflect {

struct PassCounts {
  int drawCalls = 0;
  size_t triangles = 0;
  PassCounts& operator+=(const PassCounts& o) {
    drawCalls += o.drawCalls;
    triangles += o.triangles;
    return *this;
  }
};

// What every draw of one pass shares.
struct DrawPass {
  const Scene& scene;
  const FramePlan& plan;
  glm::mat4 viewProjection;
  glm::vec3 lightingEye;     // where Phong's viewer is (the main camera's eye, as the course)
  glm::vec3 environmentEye;  // where a mirror's view rays start (a capture: the probe centre)
  CaptureState capture;      // layer 0: the main pass
  int outputDirections = 0;  // environment.frag's u_outputDirection (SceneRenderer::kOutput...)
  // > 0 (the main pass: core/frustum.h nearPlaneReach): a closed solid (MeshBuffer::
  // closedOutward) farther than this from environmentEye is drawn without its back faces, which
  // only its own front faces would cover. The same pixels, half the fragments: a mirror's each
  // trace a ray. 0 (the captures: their third pass draws backs) draws every face.
  float cullReach = 0.0f;
};

class PassDrawer {
 public:
  PassDrawer(ProgramCache& programs, const EnvironmentBinding& environments,
             const MeshBuffers* meshes)
      : programs_(programs), environments_(environments), meshes_(meshes) {}
  PassCounts draw(const DrawPass& pass, const std::vector<DrawItem>& draws) const;
  const MeshBuffer* mesh(const std::string& name, int lod) const {
    return meshes_ ? meshes_->find(name, lod) : nullptr;
  }

 private:
  // What each program sets once a pass: the light, or where the view rays start, the output and
  // the tracer; one overload a program type.
  void setForPass(const PhongUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  void setForPass(const EnvironmentUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  void setForPass(const CubeTexturedUniforms& u, const ProgramKey& key, const DrawPass& pass) const;
  template <typename Uniforms>
  PassCounts drawObject(const Uniforms& u, const ProgramKey& key, const DrawPass& pass,
                        const DrawItem& item) const;

  ProgramCache& programs_;
  const EnvironmentBinding& environments_;
  const MeshBuffers* meshes_;
};

}  // namespace reflect
