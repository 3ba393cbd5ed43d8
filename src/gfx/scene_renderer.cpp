#include "gfx/scene_renderer.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"

namespace reflect {
namespace {

constexpr GLint kEnvironmentTextureUnit = 0;

void setObjectMatrices(GLint model, GLint normalMatrix, const glm::mat4& m) {
  glUniformMatrix4fv(model, 1, GL_FALSE, glm::value_ptr(m));
  const glm::mat3 normal = glm::inverseTranspose(glm::mat3(m));
  glUniformMatrix3fv(normalMatrix, 1, GL_FALSE, glm::value_ptr(normal));
}

void clearTo(const glm::vec3& colour) {
  glClearColor(colour.r, colour.g, colour.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace

Result<SceneRenderer> SceneRenderer::create(int cubeFaceSize) {
  Result<ShaderProgram> phong = ShaderProgram::build("mesh.vert", "phong.frag");
  if (!phong) return Result<SceneRenderer>::failure(phong.error());
  Result<ShaderProgram> mirror = ShaderProgram::build("mesh.vert", "reflect.frag");
  if (!mirror) return Result<SceneRenderer>::failure(mirror.error());
  Result<CubeCaptureTarget> capture = CubeCaptureTarget::create(cubeFaceSize);
  if (!capture) return Result<SceneRenderer>::failure(capture.error());

  const ShaderProgram& p = phong.value();
  PhongProgram phongProgram{ShaderProgram{},        p.uniform("u_viewProjection"),
                            p.uniform("u_model"),   p.uniform("u_normalMatrix"),
                            p.uniform("u_colour"),  p.uniform("u_lightPosition"),
                            p.uniform("u_viewPosition"), p.uniform("u_ambient"),
                            p.uniform("u_diffuse"), p.uniform("u_specular"),
                            p.uniform("u_shininess")};
  phongProgram.program = phong.take();
  const ShaderProgram& r = mirror.value();
  ReflectProgram reflectProgram{ShaderProgram{},          r.uniform("u_viewProjection"),
                                r.uniform("u_model"),     r.uniform("u_normalMatrix"),
                                r.uniform("u_colour"),    r.uniform("u_viewPosition"),
                                r.uniform("u_reflectionWeight"), r.uniform("u_baseWeight"),
                                r.uniform("u_environment")};
  reflectProgram.program = mirror.take();
  return SceneRenderer(std::move(phongProgram), std::move(reflectProgram), capture.take());
}

SceneRenderer::SceneRenderer(PhongProgram phong, ReflectProgram reflect, CubeCaptureTarget capture)
    : phong_(std::move(phong)), reflect_(std::move(reflect)), capture_(std::move(capture)) {}

void SceneRenderer::setMesh(const std::string& name, const MeshData& mesh) {
  meshes_.erase(name);
  meshes_.emplace(name, MeshBuffer(mesh));
}

const MeshBuffer* SceneRenderer::mesh(const std::string& name) const {
  auto it = meshes_.find(name);
  return it == meshes_.end() ? nullptr : &it->second;
}

std::optional<glm::vec3> SceneRenderer::probeCentre(const Scene& scene, double orbitDegrees) const {
  const int index = scene.reflectorIndex();
  if (index < 0) return std::nullopt;
  const SceneObject& reflector = scene.objects[static_cast<size_t>(index)];
  const MeshBuffer* buffer = mesh(reflector.mesh);
  const glm::vec3 localCentre = buffer ? buffer->bounds().centre() : glm::vec3(0.0f);
  return glm::vec3(scene.modelMatrix(reflector, orbitDegrees) * glm::vec4(localCentre, 1.0f));
}

PassCounts SceneRenderer::drawPhongObjects(const Scene& scene, double orbitDegrees,
                                           const glm::mat4& viewProj,
                                           const glm::vec3& viewPosition) {
  PassCounts counts;
  glUseProgram(phong_.program.id());
  glUniformMatrix4fv(phong_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
  glUniform3fv(phong_.lightPosition, 1, glm::value_ptr(scene.light.position));
  glUniform3fv(phong_.viewPosition, 1, glm::value_ptr(viewPosition));
  glUniform1f(phong_.ambient, scene.light.ambient);
  glUniform1f(phong_.diffuse, scene.light.diffuse);
  glUniform1f(phong_.specular, scene.light.specular);
  glUniform1f(phong_.shininess, scene.light.shininess);
  for (const SceneObject& object : scene.objects) {
    // The reflector is left out by what it is, not by a list: its own probe must not see it,
    // and the main pass draws it with the mirror shader.
    if (object.reflective) continue;
    const MeshBuffer* buffer = mesh(object.mesh);
    if (!buffer) continue;
    setObjectMatrices(phong_.model, phong_.normalMatrix, scene.modelMatrix(object, orbitDegrees));
    glUniform3fv(phong_.colour, 1, glm::value_ptr(object.colour));
    buffer->draw();
    ++counts.drawCalls;
    counts.triangles += buffer->triangleCount();
  }
  return counts;
}

PassCounts SceneRenderer::captureProbe(const Scene& scene, double orbitDegrees,
                                       const glm::vec3& lightingEye) {
  PassCounts counts;
  const std::optional<glm::vec3> centre = probeCentre(scene, orbitDegrees);
  if (!centre) return counts;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  const glm::mat4 projection = cubeFaceProjection(scene.capture.near, scene.capture.far);
  for (int face = 0; face < 6; ++face) {
    capture_.bindFace(face);
    clearTo(scene.clearColour);
    counts += drawPhongObjects(scene, orbitDegrees, projection * cubeFaceView(*centre, face),
                               lightingEye);
    ++counts.facesCaptured;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGlError("capture probe");
  return counts;
}

PassCounts SceneRenderer::drawMain(const Scene& scene, double orbitDegrees, const ViewParams& camera,
                                   GLuint framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides
  clearTo(scene.clearColour);
  const glm::mat4 viewProj = camera.projection * camera.view;
  PassCounts counts = drawPhongObjects(scene, orbitDegrees, viewProj, camera.eye);

  const int index = scene.reflectorIndex();
  if (index >= 0) {
    const SceneObject& reflector = scene.objects[static_cast<size_t>(index)];
    if (const MeshBuffer* buffer = mesh(reflector.mesh)) {
      glUseProgram(reflect_.program.id());
      glUniformMatrix4fv(reflect_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
      setObjectMatrices(reflect_.model, reflect_.normalMatrix,
                        scene.modelMatrix(reflector, orbitDegrees));
      glUniform3fv(reflect_.colour, 1, glm::value_ptr(reflector.colour));
      glUniform3fv(reflect_.viewPosition, 1, glm::value_ptr(camera.eye));
      glUniform1f(reflect_.reflectionWeight, reflector.reflectionWeight);
      glUniform1f(reflect_.baseWeight, reflector.baseWeight);
      glUniform1i(reflect_.environment, kEnvironmentTextureUnit);
      glActiveTexture(GL_TEXTURE0 + kEnvironmentTextureUnit);
      glBindTexture(GL_TEXTURE_CUBE_MAP, capture_.texture());
      buffer->draw();
      glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
      ++counts.drawCalls;
      counts.triangles += buffer->triangleCount();
    }
  }
  glBindVertexArray(0);
  checkGlError("main pass");
  return counts;
}

void SceneRenderer::abandon() {
  phong_.program.abandon();
  reflect_.program.abandon();
  capture_.abandon();
  for (auto& [name, buffer] : meshes_) buffer.abandon();
  meshes_.clear();
}

}  // namespace reflect
