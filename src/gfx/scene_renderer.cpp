#include "gfx/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/fresnel.h"
#include "core/frustum.h"
#include "core/normal_matrix.h"
#include "gfx/exact_tracer.h"
#include "gfx/scene_renderer_detail.h"

namespace reflect {
using renderer_detail::bindTexture;
using renderer_detail::sphereRadiusIn;

Result<SceneRenderer> SceneRenderer::create(const AccuracySettings& accuracy) {
  Result<DepthPyramidPrograms> pyramid = DepthPyramidPrograms::create();
  if (!pyramid) return Result<SceneRenderer>::failure(pyramid.error());

  SceneRenderer r;
  r.accuracy_ = accuracy;
  r.programs_ = ProgramCache(accuracy.mediump);
  // The programs every scene's main pass needs are built now, so a shader that does not build
  // fails here, loudly; the other variants when a draw first needs them.
  for (const ProgramKey& key : {ProgramKey{}, ProgramKey{Look::Environment}}) {
    if (!r.programs_.get(key)) return Result<SceneRenderer>::failure(r.programs_.lastError());
  }

  r.pyramid_ = pyramid.take();

  r.emptyDepths_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_2D_ARRAY, r.emptyDepths_.id());
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG16UI, 1, 1, 6);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  r.emptyPyramid_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_2D, r.emptyPyramid_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RG16UI, 1, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  for (GLint unit : {kPeelDepthsUnit, kPeelBacksUnit}) {
    bindTexture(unit, GL_TEXTURE_2D_ARRAY, r.emptyDepths_.id());
  }
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, r.emptyPyramid_.id());
  glActiveTexture(GL_TEXTURE0);
  r.emptyVertexArray_ = VertexArrayHandle(genVertexArray());
  if (!checkGlError("create scene renderer")) {
    return Result<SceneRenderer>::failure("GL error while creating the scene renderer");
  }
  return r;
}

void SceneRenderer::forgetReplacedGlassMeshes(const Scene& scene) {
  for (const SceneObject& object : scene.objects) {
    if (object.material != Material::Glass) continue;
    const uint64_t serial = meshes_ ? meshes_->serial(object.mesh) : 0;
    uint64_t& seen = glassMeshSerials_[object.mesh];
    if (seen != serial) glassInteriors_.forget(object.mesh);
    seen = serial;
  }
}

std::string SceneRenderer::setSkybox(const CubeFaces& faces) {
  Result<SkyboxPass> pass = SkyboxPass::create(faces);
  if (!pass) return pass.error();
  skybox_ = std::make_unique<SkyboxPass>(pass.take());
  skyPrefiltered_.reset();  // the old sky's levels: the next capture filters the new one
  return {};
}

const MeshBuffer* SceneRenderer::mesh(const std::string& name, int lod) const {
  return meshes_ ? meshes_->find(name, lod) : nullptr;
}

GLuint SceneRenderer::probeTexture(int owner) const {
  auto it = probes_.find(owner);
  return it == probes_.end() ? 0 : it->second.texture();
}

const CubeCaptureTarget* SceneRenderer::probeTarget(int owner) const {
  auto it = probes_.find(owner);
  return it == probes_.end() ? nullptr : &it->second;
}

void SceneRenderer::setForPass(const PhongUniforms& u, const ProgramKey&,
                               const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.lightingEye);
  u.setLight(pass.scene.light);
}

void SceneRenderer::setForPass(const EnvironmentUniforms& u, const ProgramKey& key,
                               const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.environmentEye);
  u.outputDirection.set(pass.outputDirections);
  if (key.search == Search::Exact && exact_) exact_->bind(u.exact, accuracy_.lobeRays);
}

void SceneRenderer::setForPass(const CubeTexturedUniforms& u, const ProgramKey&,
                               const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.environmentEye);
}

void SceneRenderer::setForObject(const EnvironmentUniforms& u, const ProgramKey& key,
                                 const DrawPass& pass, const DrawItem& item,
                                 const glm::mat4& model) const {
  const SceneObject& object = pass.scene.objects[static_cast<size_t>(item.object)];
  u.reflectionWeight.set(object.reflection);
  u.baseWeight.set(object.base);
  u.eta.set(1.0f / clampedIor(object.ior));
  u.fresnelF0.set(fresnelF0(object.ior));
  u.fresnel.set(object.fresnel);
  if (key.refracts) {
    // Glass leaves through its far side: where the mesh is a sphere (uniformly scaled) in closed
    // form, otherwise through its interior map, with the GLASS_EXIT programs.
    const MeshBuffer* full = mesh(object.mesh, 0);
    const float radius = sphereRadiusIn(full, model);
    const GlassInteriorMap* interior = key.glassExit ? glassExitOf(object, model) : nullptr;
    if (interior) u.glassExit.set(*interior, model);
    u.twoSurfaces.set(accuracy_.glassSurfaces == 2 && (radius > 0.0f || interior));
    const glm::vec3 centre(model * glm::vec4(full ? full->bounds().centre() : glm::vec3(0), 1));
    u.glassSphere.set(glm::vec4(centre, radius));
  }
  bindEnvironment(u, key, pass.scene, object, environmentOf(pass.scene, pass.plan, item.object));
  if (key.search == Search::Exact && exact_) exact_->bindObject(u.exact, item.object);
}

void SceneRenderer::setForObject(const CubeTexturedUniforms&, const ProgramKey&,
                                 const DrawPass& pass, const DrawItem& item,
                                 const glm::mat4&) const {
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP,
              environmentOf(pass.scene, pass.plan, item.object).colour);
  glActiveTexture(GL_TEXTURE0);
}

template <typename Uniforms>
PassCounts SceneRenderer::drawObject(const Uniforms& u, const ProgramKey& key, const DrawPass& pass,
                                     const DrawItem& item) const {
  const SceneObject& object = pass.scene.objects[static_cast<size_t>(item.object)];
  const MeshBuffer* buffer = mesh(object.mesh, item.lod);
  if (!buffer) return {};
  const glm::mat4& model = pass.plan.modelOf(item.object);
  u.mesh.model.set(model);
  u.mesh.normalMatrix.set(normalMatrixOf(glm::mat3(model)));
  // The object's size, for the third capture pass (capture_output.glsl).
  const Bounds world = transformBounds(buffer->bounds(), model);
  u.mesh.capture.extent.set(glm::length(world.max - world.min) / pass.scene.capture.near);
  u.mesh.colour.set(object.colour);
  setForObject(u, key, pass, item, model);
  buffer->draw(item.ranges);
  const size_t triangles = item.ranges.empty() ? buffer->triangleCount() : item.triangles;
  return {static_cast<int>(std::max<size_t>(item.ranges.size(), 1)), triangles};
}

PassCounts SceneRenderer::drawItems(const DrawPass& pass, const std::vector<DrawItem>& draws) {
  // One program switch per variant present, in the keys' order (Phong first).
  std::vector<std::pair<ProgramKey, const DrawItem*>> keyed;
  keyed.reserve(draws.size());
  for (const DrawItem& d : draws) {
    keyed.emplace_back(keyFor(pass.scene, pass.plan, d, pass.capture), &d);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  PassCounts counts;
  for (size_t i = 0; i < keyed.size();) {
    size_t end = i;
    while (end < keyed.size() && keyed[end].first == keyed[i].first) ++end;
    ProgramKey key = keyed[i].first;
    const SceneProgram* p = programs_.get(key);
    if (!p && key.glassExit) {  // no interior-map program: glass leaves at one surface
      key.glassExit = false;
      p = programs_.get(key);
    }
    if (p) {
      glUseProgram(p->id());
      const MeshPassUniforms& mesh = p->mesh();
      mesh.capture.set(pass.capture);
      mesh.viewProjection.set(pass.viewProjection);
      // The program's own type from here on: each setter reaches its own table alone.
      std::visit(
          [&](const auto& program) {
            setForPass(program.u(), key, pass);
            for (size_t k = i; k < end; ++k) {
              counts += drawObject(program.u(), key, pass, *keyed[k].second);
            }
          },
          p->program);
    }
    i = end;
  }
  return counts;
}

PassCounts SceneRenderer::drawMain(const Scene& scene, double seconds, const FramePlan& plan,
                                   const ViewParams& camera, const std::vector<DrawItem>& draws,
                                   unsigned framebuffer, int width, int height,
                                   int outputDirections) {
  forgetReplacedGlassMeshes(scene);
  prepareGlassExits(scene, plan);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides
  glClearColor(scene.clearColour.r, scene.clearColour.g, scene.clearColour.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const DrawPass pass{scene,      seconds,    plan, camera.projection * camera.view,
                      camera.eye, camera.eye, {},   outputDirections};  // colour only
  PassCounts counts = drawItems(pass, draws);
  if (skybox_) skybox_->draw(camera.projection, camera.view, pass.capture);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  checkGlError("main pass");
  return counts;
}

}  // namespace reflect
