#include "gfx/scene_renderer.h"

#include <algorithm>
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

Result<SceneRenderer> SceneRenderer::create() {
  Result<ShaderProgram> phong = ShaderProgram::build("mesh.vert", "phong.frag");
  if (!phong) return Result<SceneRenderer>::failure(phong.error());
  Result<ShaderProgram> mirror = ShaderProgram::build("mesh.vert", "reflect.frag");
  if (!mirror) return Result<SceneRenderer>::failure(mirror.error());

  const ShaderProgram& p = phong.value();
  PhongProgram phongProgram{ShaderProgram{},        p.uniform("u_viewProjection"),
                            p.uniform("u_model"),   p.uniform("u_normalMatrix"),
                            p.uniform("u_colour"),  p.uniform("u_lightPosition"),
                            p.uniform("u_viewPosition"), p.uniform("u_ambient"),
                            p.uniform("u_diffuse"), p.uniform("u_specular"),
                            p.uniform("u_shininess")};
  phongProgram.program = phong.take();
  const ShaderProgram& r = mirror.value();
  MirrorProgram mirrorProgram{ShaderProgram{},          r.uniform("u_viewProjection"),
                              r.uniform("u_model"),     r.uniform("u_normalMatrix"),
                              r.uniform("u_colour"),    r.uniform("u_viewPosition"),
                              r.uniform("u_reflectionWeight"), r.uniform("u_baseWeight"),
                              r.uniform("u_environment")};
  mirrorProgram.program = mirror.take();
  return SceneRenderer(std::move(phongProgram), std::move(mirrorProgram));
}

SceneRenderer::SceneRenderer(PhongProgram phong, MirrorProgram mirror)
    : phong_(std::move(phong)), mirror_(std::move(mirror)) {}

void SceneRenderer::setMesh(const std::string& name, int lod, const MeshData& mesh) {
  std::vector<MeshBuffer>& levels = meshes_[name];
  if (lod == 0) levels.clear();
  if (lod != static_cast<int>(levels.size())) return;  // levels arrive in order, 0 first
  levels.emplace_back(mesh);
}

const MeshBuffer* SceneRenderer::mesh(const std::string& name, int lod) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end() || it->second.empty()) return nullptr;
  const size_t level = std::min(static_cast<size_t>(std::max(lod, 0)), it->second.size() - 1);
  return &it->second[level];
}

GLuint SceneRenderer::environmentTexture(int reflector) const {
  auto owner = ownerOf_.find(reflector);
  auto it = probes_.find(owner == ownerOf_.end() ? reflector : owner->second);
  return it == probes_.end() ? 0 : it->second.texture();
}

void SceneRenderer::usePhong(const Scene& scene, const glm::mat4& viewProj,
                             const glm::vec3& viewPosition) {
  glUseProgram(phong_.program.id());
  glUniformMatrix4fv(phong_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
  glUniform3fv(phong_.lightPosition, 1, glm::value_ptr(scene.light.position));
  glUniform3fv(phong_.viewPosition, 1, glm::value_ptr(viewPosition));
  glUniform1f(phong_.ambient, scene.light.ambient);
  glUniform1f(phong_.diffuse, scene.light.diffuse);
  glUniform1f(phong_.specular, scene.light.specular);
  glUniform1f(phong_.shininess, scene.light.shininess);
}

void SceneRenderer::useMirror(const glm::mat4& viewProj, const glm::vec3& viewPosition) {
  glUseProgram(mirror_.program.id());
  glUniformMatrix4fv(mirror_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
  glUniform3fv(mirror_.viewPosition, 1, glm::value_ptr(viewPosition));
  glUniform1i(mirror_.environment, kEnvironmentTextureUnit);
}

PassCounts SceneRenderer::drawObject(const Scene& scene, const DrawItem& item,
                                     double orbitDegrees) {
  const SceneObject& object = scene.objects[static_cast<size_t>(item.object)];
  const MeshBuffer* buffer = mesh(object.mesh, item.lod);
  if (!buffer) return {};
  const glm::mat4 model = scene.modelMatrix(object, orbitDegrees);
  if (object.reflective) {
    setObjectMatrices(mirror_.model, mirror_.normalMatrix, model);
    glUniform3fv(mirror_.colour, 1, glm::value_ptr(object.colour));
    glUniform1f(mirror_.reflectionWeight, object.reflectionWeight);
    glUniform1f(mirror_.baseWeight, object.baseWeight);
    glActiveTexture(GL_TEXTURE0 + kEnvironmentTextureUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, environmentTexture(item.object));
  } else {
    setObjectMatrices(phong_.model, phong_.normalMatrix, model);
    glUniform3fv(phong_.colour, 1, glm::value_ptr(object.colour));
  }
  buffer->draw(item.ranges);
  const size_t triangles = item.ranges.empty() ? buffer->triangleCount() : item.triangles;
  return {static_cast<int>(std::max<size_t>(item.ranges.size(), 1)), triangles};
}

Result<PassCounts> SceneRenderer::capture(const Scene& scene, double orbitDegrees,
                                          const FramePlan& plan, const glm::vec3& lightingEye) {
  PassCounts counts;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  const glm::mat4 projection = cubeFaceProjection(scene.capture.near, scene.capture.far);
  ownerOf_.clear();
  for (const ProbePlan& probe : plan.probes) {
    for (int member : probe.members) ownerOf_[member] = probe.reflector;
  }
  for (const ProbePlan& probe : plan.probes) {
    if (probe.faces.empty()) continue;
    auto target = probes_.find(probe.reflector);
    if (target == probes_.end() || target->second.faceSize() != scene.capture.faceSize) {
      Result<CubeCaptureTarget> created = CubeCaptureTarget::create(scene.capture.faceSize);
      if (!created) return Result<PassCounts>::failure(created.error());
      probes_.erase(probe.reflector);
      target = probes_.emplace(probe.reflector, created.take()).first;
    }
    for (const FacePlan& face : probe.faces) {
      target->second.bindFace(face.face);
      clearTo(scene.clearColour);
      const glm::mat4 viewProj = projection * cubeFaceView(probe.centre, face.face);
      // Phong objects first, then other mirrors (with their cube as it was before this frame's
      // capture of them: one bounce). Program switches stay at two per face.
      usePhong(scene, viewProj, lightingEye);
      for (const DrawItem& d : face.draws) {
        if (!scene.objects[static_cast<size_t>(d.object)].reflective)
          counts += drawObject(scene, d, orbitDegrees);
      }
      bool mirrorInUse = false;
      for (const DrawItem& d : face.draws) {
        if (!scene.objects[static_cast<size_t>(d.object)].reflective) continue;
        if (!mirrorInUse) useMirror(viewProj, probe.centre);
        mirrorInUse = true;
        counts += drawObject(scene, d, orbitDegrees);
      }
    }
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGlError("capture");
  return counts;
}

PassCounts SceneRenderer::drawMain(const Scene& scene, double orbitDegrees, const ViewParams& camera,
                                   unsigned framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides
  clearTo(scene.clearColour);
  const glm::mat4 viewProj = camera.projection * camera.view;
  PassCounts counts;
  usePhong(scene, viewProj, camera.eye);
  const int objectCount = static_cast<int>(scene.objects.size());
  for (int i = 0; i < objectCount; ++i) {
    if (!scene.objects[static_cast<size_t>(i)].reflective) {
      counts += drawObject(scene, DrawItem{i, 0, {}, 0}, orbitDegrees);
    }
  }
  useMirror(viewProj, camera.eye);
  for (int i = 0; i < objectCount; ++i) {
    if (scene.objects[static_cast<size_t>(i)].reflective) {
      counts += drawObject(scene, DrawItem{i, 0, {}, 0}, orbitDegrees);
    }
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  checkGlError("main pass");
  return counts;
}

void SceneRenderer::abandon() {
  phong_.program.abandon();
  mirror_.program.abandon();
  for (auto& [index, target] : probes_) target.abandon();
  probes_.clear();
  ownerOf_.clear();
  for (auto& [name, levels] : meshes_) {
    for (MeshBuffer& level : levels) level.abandon();
  }
  meshes_.clear();
}

}  // namespace reflect
