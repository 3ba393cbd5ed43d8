// Draws a Scene with GL ES 3.0 as a FramePlan says: each probe's planned cube faces (objects at
// their planned level of detail), then the main pass, where each reflector samples its own probe.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/frame_planner.h"
#include "core/mesh_data.h"
#include "core/result.h"
#include "core/scene.h"
#include "gfx/cube_capture_target.h"
#include "gfx/mesh_buffer.h"
#include "gfx/shader_program.h"

namespace reflect {

struct ViewParams {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
};

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
  static Result<SceneRenderer> create();

  // Uploads (or replaces) level `lod` of the mesh the scene knows by `name` (0 = full detail;
  // setting level 0 drops the coarser levels, which belonged to the old mesh).
  void setMesh(const std::string& name, int lod, const MeshData& mesh);

  // Renders the plan's faces. `lightingEye` is the main camera's eye: the course lights captures
  // as seen from it. Probe targets are created (or resized) on first use.
  Result<PassCounts> capture(const Scene& scene, double orbitDegrees, const FramePlan& plan,
                             const glm::vec3& lightingEye);
  PassCounts drawMain(const Scene& scene, double orbitDegrees, const ViewParams& camera,
                      unsigned framebuffer, int width, int height);

  // The live cube map that reflective object `reflector` samples (0 if none yet).
  GLuint environmentTexture(int reflector) const;
  // After a lost context: drop every GL name without deleting (the context took them).
  void abandon();

 private:
  struct PhongProgram {
    ShaderProgram program;
    GLint viewProjection, model, normalMatrix, colour, lightPosition, viewPosition, ambient,
        diffuse, specular, shininess;
  };
  struct MirrorProgram {
    ShaderProgram program;
    GLint viewProjection, model, normalMatrix, colour, viewPosition, reflectionWeight, baseWeight,
        environment;
  };

  SceneRenderer(PhongProgram phong, MirrorProgram mirror);
  void usePhong(const Scene& scene, const glm::mat4& viewProj, const glm::vec3& viewPosition);
  void useMirror(const glm::mat4& viewProj, const glm::vec3& viewPosition);
  // Draws one object (or the planned ranges of it) with the program in use for its material.
  PassCounts drawObject(const Scene& scene, const DrawItem& item, double orbitDegrees);
  const MeshBuffer* mesh(const std::string& name, int lod) const;

  PhongProgram phong_;
  MirrorProgram mirror_;
  std::map<int, CubeCaptureTarget> probes_;  // by owning reflector's object index
  std::map<int, int> ownerOf_;                // reflector -> owner of the probe it samples
  std::map<std::string, std::vector<MeshBuffer>> meshes_;
};

}  // namespace reflect
