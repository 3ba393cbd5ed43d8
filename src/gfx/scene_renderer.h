// Draws a Scene with GL ES 3.0: the probe capture (six cube faces from the reflector's centre,
// everything but the reflector) and the main pass (everything, the reflector sampling the probe).
#pragma once

#include <map>
#include <optional>
#include <string>

#include <glm/glm.hpp>

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
  int facesCaptured = 0;
  PassCounts& operator+=(const PassCounts& o) {
    drawCalls += o.drawCalls;
    triangles += o.triangles;
    facesCaptured += o.facesCaptured;
    return *this;
  }
};

class SceneRenderer {
 public:
  static Result<SceneRenderer> create(int cubeFaceSize);

  // Uploads (or replaces) the mesh the scene knows by `name`.
  void setMesh(const std::string& name, const MeshData& mesh);
  bool hasMesh(const std::string& name) const { return meshes_.count(name) != 0; }

  // World-space centre of the reflector's mesh bounds; nullopt if the scene has no reflector.
  std::optional<glm::vec3> probeCentre(const Scene& scene, double orbitDegrees) const;
  // `lightingEye` is the main camera's eye: the course lights captures as seen from it.
  PassCounts captureProbe(const Scene& scene, double orbitDegrees, const glm::vec3& lightingEye);
  PassCounts drawMain(const Scene& scene, double orbitDegrees, const ViewParams& camera,
                      GLuint framebuffer, int width, int height);

  int cubeFaceSize() const { return capture_.faceSize(); }
  GLuint environmentTexture() const { return capture_.texture(); }
  // After a lost context: drop every GL name without deleting (the context took them).
  void abandon();

 private:
  struct PhongProgram {
    ShaderProgram program;
    GLint viewProjection, model, normalMatrix, colour, lightPosition, viewPosition, ambient,
        diffuse, specular, shininess;
  };
  struct ReflectProgram {
    ShaderProgram program;
    GLint viewProjection, model, normalMatrix, colour, viewPosition, reflectionWeight, baseWeight,
        environment;
  };

  SceneRenderer(PhongProgram phong, ReflectProgram reflect, CubeCaptureTarget capture);
  PassCounts drawPhongObjects(const Scene& scene, double orbitDegrees, const glm::mat4& viewProj,
                              const glm::vec3& viewPosition);
  const MeshBuffer* mesh(const std::string& name) const;

  PhongProgram phong_;
  ReflectProgram reflect_;
  CubeCaptureTarget capture_;
  std::map<std::string, MeshBuffer> meshes_;
};

}  // namespace reflect
