#include "gfx/scene_renderer.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"
#include "core/normal_matrix.h"

namespace reflect {
namespace {

constexpr GLint kEnvironmentTextureUnit = 0;

void setObjectMatrices(GLint model, GLint normalMatrix, const glm::mat4& m) {
  glUniformMatrix4fv(model, 1, GL_FALSE, glm::value_ptr(m));
  const glm::mat3 normal = normalMatrixOf(glm::mat3(m));
  glUniformMatrix3fv(normalMatrix, 1, GL_FALSE, glm::value_ptr(normal));
}

void clearTo(const glm::vec3& colour, float alpha = 1.0f) {
  glClearColor(colour.r, colour.g, colour.b, alpha);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace

Result<SceneRenderer> SceneRenderer::create(const AccuracySettings& accuracy) {
  const bool mediump = accuracy.mediump;
  Result<ShaderProgram> phong = ShaderProgram::build("mesh.vert", "phong.frag", mediump);
  if (!phong) return Result<SceneRenderer>::failure(phong.error());
  const std::string lookup =
      "#define DISTANCE_ITERATIONS " + std::to_string(accuracy.distanceIterations) + "\n";
  Result<ShaderProgram> environment =
      ShaderProgram::build("mesh.vert", "environment.frag", mediump, lookup);
  if (!environment) return Result<SceneRenderer>::failure(environment.error());
  Result<ShaderProgram> cubeTextured =
      ShaderProgram::build("mesh.vert", "cube_textured.frag", mediump);
  if (!cubeTextured) return Result<SceneRenderer>::failure(cubeTextured.error());

  const ShaderProgram& p = phong.value();
  PhongProgram phongProgram{ShaderProgram{},
                            p.uniform("u_viewProjection"),
                            p.uniform("u_model"),
                            p.uniform("u_normalMatrix"),
                            p.uniform("u_colour"),
                            p.uniform("u_lightPosition"),
                            p.uniform("u_viewPosition"),
                            p.uniform("u_ambient"),
                            p.uniform("u_diffuse"),
                            p.uniform("u_specular"),
                            p.uniform("u_shininess"),
                            p.uniform("u_storeDistance"),
                            p.uniform("u_probeCentre"),
                            p.uniform("u_distanceUnit")};
  phongProgram.program = phong.take();
  const ShaderProgram& e = environment.value();
  EnvironmentProgram environmentProgram{ShaderProgram{},
                                        e.uniform("u_viewProjection"),
                                        e.uniform("u_model"),
                                        e.uniform("u_normalMatrix"),
                                        e.uniform("u_colour"),
                                        e.uniform("u_viewPosition"),
                                        e.uniform("u_reflectionWeight"),
                                        e.uniform("u_baseWeight"),
                                        e.uniform("u_refracts"),
                                        e.uniform("u_eta"),
                                        e.uniform("u_fresnelF0"),
                                        e.uniform("u_fresnel"),
                                        e.uniform("u_environment"),
                                        e.optionalUniform("u_probeCentre"),
                                        e.optionalUniform("u_distanceUnit"),
                                        e.uniform("u_outputDirection")};
  environmentProgram.program = environment.take();
  const ShaderProgram& c = cubeTextured.value();
  CubeTexturedProgram cubeTexturedProgram{ShaderProgram{}, c.uniform("u_viewProjection"),
                                          c.uniform("u_model"), c.optionalUniform("u_normalMatrix"),
                                          c.uniform("u_environment")};
  cubeTexturedProgram.program = cubeTextured.take();
  return SceneRenderer(std::move(phongProgram), std::move(environmentProgram),
                       std::move(cubeTexturedProgram), accuracy);
}

SceneRenderer::SceneRenderer(PhongProgram phong, EnvironmentProgram environment,
                             CubeTexturedProgram cubeTextured, const AccuracySettings& accuracy)
    : phong_(std::move(phong)),
      environment_(std::move(environment)),
      cubeTextured_(std::move(cubeTextured)),
      accuracy_(accuracy) {}

void SceneRenderer::setMesh(const std::string& name, int lod, const MeshData& mesh) {
  std::vector<MeshBuffer>& levels = meshes_[name];
  if (lod == 0) levels.clear();
  if (lod != static_cast<int>(levels.size())) return;  // levels arrive in order, 0 first
  levels.emplace_back(mesh);
}

std::string SceneRenderer::setSkybox(const CubeFaces& faces) {
  Result<SkyboxPass> pass = SkyboxPass::create(faces);
  if (!pass) return pass.error();
  skybox_ = std::make_unique<SkyboxPass>(pass.take());
  return {};
}

const MeshBuffer* SceneRenderer::mesh(const std::string& name, int lod) const {
  auto it = meshes_.find(name);
  if (it == meshes_.end() || it->second.empty()) return nullptr;
  const size_t level = std::min(static_cast<size_t>(std::max(lod, 0)), it->second.size() - 1);
  return &it->second[level];
}

GLuint SceneRenderer::environmentTexture(const Scene& scene, const FramePlan& plan,
                                         int index) const {
  const SceneObject& object = scene.objects.at(static_cast<size_t>(index));
  if (object.environment == Environment::Skybox) return skybox_ ? skybox_->texture() : 0;
  const ProbePlan* probe = plan.probeOf(index);
  return probe ? probeTexture(probe->reflector) : 0;
}

GLuint SceneRenderer::probeTexture(int owner) const {
  auto it = probes_.find(owner);
  return it == probes_.end() ? 0 : it->second.texture();
}

void SceneRenderer::use(ProgramKind kind, const Scene& scene, const glm::mat4& viewProj,
                        const glm::vec3& viewPosition, const glm::vec3* distanceCentre,
                        bool outputDirections) {
  current_ = kind;
  switch (kind) {
    case ProgramKind::Phong:
      glUseProgram(phong_.program.id());
      glUniformMatrix4fv(phong_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
      glUniform3fv(phong_.lightPosition, 1, glm::value_ptr(scene.light.position));
      glUniform3fv(phong_.viewPosition, 1, glm::value_ptr(viewPosition));
      glUniform1f(phong_.ambient, scene.light.ambient);
      glUniform1f(phong_.diffuse, scene.light.diffuse);
      glUniform1f(phong_.specular, scene.light.specular);
      glUniform1f(phong_.shininess, scene.light.shininess);
      glUniform1i(phong_.storeDistance, distanceCentre ? 1 : 0);
      if (distanceCentre) glUniform3fv(phong_.probeCentre, 1, glm::value_ptr(*distanceCentre));
      glUniform1f(phong_.distanceUnit, scene.capture.near);
      break;
    case ProgramKind::Environment:
      glUseProgram(environment_.program.id());
      glUniformMatrix4fv(environment_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
      glUniform3fv(environment_.viewPosition, 1, glm::value_ptr(viewPosition));
      glUniform1i(environment_.environment, kEnvironmentTextureUnit);
      glUniform1i(environment_.outputDirection, outputDirections ? 1 : 0);
      break;
    case ProgramKind::CubeTextured:
      glUseProgram(cubeTextured_.program.id());
      glUniformMatrix4fv(cubeTextured_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProj));
      glUniform1i(cubeTextured_.environment, kEnvironmentTextureUnit);
      break;
  }
}

PassCounts SceneRenderer::drawObject(const Scene& scene, const FramePlan& plan,
                                     const DrawItem& item, double seconds) {
  const SceneObject& object = scene.objects[static_cast<size_t>(item.object)];
  const MeshBuffer* buffer = mesh(object.mesh, item.lod);
  if (!buffer) return {};
  const glm::mat4 model = scene.modelMatrix(object, seconds);
  switch (current_) {
    case ProgramKind::Phong:
      setObjectMatrices(phong_.model, phong_.normalMatrix, model);
      glUniform3fv(phong_.colour, 1, glm::value_ptr(object.colour));
      break;
    case ProgramKind::Environment: {
      setObjectMatrices(environment_.model, environment_.normalMatrix, model);
      glUniform3fv(environment_.colour, 1, glm::value_ptr(object.colour));
      glUniform1f(environment_.reflection, object.reflection);
      glUniform1f(environment_.base, object.base);
      glUniform1i(environment_.refracts, object.material == Material::Glass ? 1 : 0);
      const float n = std::max(object.ior, 1e-3f);
      glUniform1f(environment_.eta, 1.0f / n);
      glUniform1f(environment_.fresnelF0, ((n - 1.0f) / (n + 1.0f)) * ((n - 1.0f) / (n + 1.0f)));
      glUniform1i(environment_.fresnel, object.fresnel ? 1 : 0);
      // Only a live probe has distances (and a centre); the skybox is at infinity.
      const bool live = object.environment == Environment::LiveProbe;
      // A skybox is at infinity: its lookups stay plain (a far probe centre makes the search
      // return the ray direction itself).
      const ProbePlan* probe = plan.probeOf(item.object);
      const glm::vec3 centre = probe ? probe->centre : glm::vec3(0.0f);
      glUniform3fv(environment_.probeCentre, 1, glm::value_ptr(centre));
      glUniform1f(environment_.distanceUnit, live ? scene.capture.near : 1e30f);
      break;
    }
    case ProgramKind::CubeTextured:
      setObjectMatrices(cubeTextured_.model, cubeTextured_.normalMatrix, model);
      break;
  }
  if (object.usesEnvironment()) {
    glActiveTexture(GL_TEXTURE0 + kEnvironmentTextureUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, environmentTexture(scene, plan, item.object));
  }
  buffer->draw(item.ranges);
  const size_t triangles = item.ranges.empty() ? buffer->triangleCount() : item.triangles;
  return {static_cast<int>(std::max<size_t>(item.ranges.size(), 1)), triangles};
}

PassCounts SceneRenderer::drawItems(const Scene& scene, double seconds, const FramePlan& plan,
                                    const std::vector<DrawItem>& draws, const glm::mat4& viewProj,
                                    const glm::vec3& viewPosition,
                                    const glm::vec3& environmentViewPosition,
                                    const glm::vec3* distanceCentre, bool outputDirections) {
  PassCounts counts;
  // One program switch per material kind present: Phong first, then the environment users.
  for (ProgramKind kind :
       {ProgramKind::Phong, ProgramKind::Environment, ProgramKind::CubeTextured}) {
    bool inUse = false;
    for (const DrawItem& d : draws) {
      const Material m = scene.objects[static_cast<size_t>(d.object)].material;
      const ProgramKind wanted = m == Material::Phong          ? ProgramKind::Phong
                                 : m == Material::CubeTextured ? ProgramKind::CubeTextured
                                                               : ProgramKind::Environment;
      if (wanted != kind) continue;
      if (!inUse) {
        use(kind, scene, viewProj,
            kind == ProgramKind::Phong ? viewPosition : environmentViewPosition, distanceCentre,
            outputDirections);
      }
      inUse = true;
      counts += drawObject(scene, plan, d, seconds);
    }
  }
  return counts;
}

Result<PassCounts> SceneRenderer::capture(const Scene& scene, double seconds, const FramePlan& plan,
                                          const glm::vec3& lightingEye) {
  PassCounts counts;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  const glm::mat4 projection = cubeFaceProjection(scene.capture.near, scene.capture.far);
  const CaptureFormat format{scene.capture.faceSize, accuracy_.usesHalfFloat(), accuracy_.depthBits,
                             accuracy_.mipmaps};
  const bool storeDistance = accuracy_.distanceIterations > 0;
  // d / (d + 1) at the far plane, d in units of the near plane.
  const float farAlpha = scene.capture.far / (scene.capture.far + scene.capture.near);
  for (const ProbePlan& probe : plan.probes) {
    if (probe.faces.empty()) continue;
    auto target = probes_.find(probe.reflector);
    if (target == probes_.end() || !(target->second.format() == format)) {
      Result<CubeCaptureTarget> created = CubeCaptureTarget::create(format);
      if (!created) return Result<PassCounts>::failure(created.error());
      probes_.erase(probe.reflector);
      target = probes_.emplace(probe.reflector, created.take()).first;
    }
    for (const FacePlan& face : probe.faces) {
      target->second.bindFace(face.face);
      // Where nothing is drawn the stored distance is the far plane's: the world ends there, as
      // it does for the main camera. (Measured on the default scene, this beats an infinite
      // distance by 2 dB: a search that ends short of it looks up from its last point, beside
      // the figures, not along its own direction, behind which a figure may stand.) A skybox is
      // drawn over it with alpha 1, infinitely far, and is seen along the ray's direction.
      clearTo(scene.clearColour, storeDistance ? farAlpha : 1.0f);
      const glm::mat4 view = cubeFaceView(probe.centre, face.face);
      // Other mirrors in view use their cube as it was before this frame's capture of them
      // (one bounce); they are seen from the probe centre.
      counts += drawItems(scene, seconds, plan, face.draws, projection * view, lightingEye,
                          probe.centre, storeDistance ? &probe.centre : nullptr, false);
      if (skybox_) skybox_->draw(projection, view);
    }
    target->second.finish();
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGlError("capture");
  return counts;
}

PassCounts SceneRenderer::drawMain(const Scene& scene, double seconds, const FramePlan& plan,
                                   const ViewParams& camera, const std::vector<DrawItem>& draws,
                                   unsigned framebuffer, int width, int height,
                                   bool outputDirections) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides
  clearTo(scene.clearColour);
  PassCounts counts = drawItems(scene, seconds, plan, draws, camera.projection * camera.view,
                                camera.eye, camera.eye, nullptr, outputDirections);
  if (skybox_) skybox_->draw(camera.projection, camera.view);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  checkGlError("main pass");
  return counts;
}

void SceneRenderer::abandon() {
  phong_.program.abandon();
  environment_.program.abandon();
  cubeTextured_.program.abandon();
  if (skybox_) skybox_->abandon();
  skybox_.reset();
  for (auto& [index, target] : probes_) target.abandon();
  probes_.clear();
  for (auto& [name, levels] : meshes_) {
    for (MeshBuffer& level : levels) level.abandon();
  }
  meshes_.clear();
}

}  // namespace reflect
