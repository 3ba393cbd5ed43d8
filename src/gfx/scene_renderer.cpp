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
  // The programs every scene's main pass needs are built now, so a shader that does not build
  // fails here, loudly; the other variants when a draw first needs them.
  for (const ProgramKey& key : {ProgramKey{}, ProgramKey{Look::Environment}}) {
    if (!r.program(key)) return Result<SceneRenderer>::failure(r.programError_);
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

void SceneRenderer::use(const Program& p, const Scene& scene, const glm::mat4& viewProj,
                        const glm::vec3& viewPosition, const CaptureState& pass,
                        int outputDirections) {
  current_ = &p;
  glUseProgram(p.program.id());
  const ProgramUniforms& u = p.program.u();
  u.capture.set(pass);
  u.viewProjection.set(viewProj);
  u.viewPosition.set(viewPosition);
  switch (p.key.look) {
    case Look::Phong:
      u.lightPosition.set(scene.light.position);
      u.ambient.set(scene.light.ambient);
      u.diffuse.set(scene.light.diffuse);
      u.specular.set(scene.light.specular);
      u.shininess.set(scene.light.shininess);
      break;
    case Look::Environment:
      u.outputDirection.set(outputDirections);
      if (p.key.search == Search::Exact && exact_) exact_->bind(u.exact, accuracy_.lobeRays);
      break;
    case Look::CubeTextured:
      break;
  }
}

PassCounts SceneRenderer::drawObject(const Scene& scene, const FramePlan& plan,
                                     const DrawItem& item, double seconds) {
  const SceneObject& object = scene.objects[static_cast<size_t>(item.object)];
  const MeshBuffer* buffer = mesh(object.mesh, item.lod);
  if (!buffer) return {};
  const Program& p = *current_;
  const ProgramUniforms& u = p.program.u();
  const glm::mat4 model = scene.modelMatrix(object, seconds);
  u.model.set(model);
  u.normalMatrix.set(normalMatrixOf(glm::mat3(model)));
  // The object's size, for the third capture pass (capture_output.glsl).
  const Bounds world = transformBounds(buffer->bounds(), model);
  u.capture.extent.set(glm::length(world.max - world.min) / scene.capture.near);
  u.colour.set(object.colour);
  switch (p.key.look) {
    case Look::Phong:
      break;
    case Look::Environment: {
      u.reflectionWeight.set(object.reflection);
      u.baseWeight.set(object.base);
      u.eta.set(1.0f / clampedIor(object.ior));
      u.fresnelF0.set(fresnelF0(object.ior));
      u.fresnel.set(object.fresnel);
      if (p.key.refracts) {
        // Glass leaves through its far side: where the mesh is a sphere (uniformly scaled) in
        // closed form, otherwise through its interior map, with the GLASS_EXIT programs.
        const MeshBuffer* full = mesh(object.mesh, 0);
        const float radius = sphereRadiusIn(full, model);
        const GlassInteriorMap* interior = p.key.glassExit ? glassExitOf(object, model) : nullptr;
        if (interior) u.glassExit.set(*interior, model);
        const bool twoSurfaces = accuracy_.glassSurfaces == 2 && (radius > 0.0f || interior);
        u.twoSurfaces.set(twoSurfaces);
        const glm::vec3 centre(model * glm::vec4(full ? full->bounds().centre() : glm::vec3(0), 1));
        u.glassSphere.set(glm::vec4(centre, radius));
      }
      bindEnvironment(scene, plan, item.object);
      if (p.key.search == Search::Exact && exact_) {
        exact_->bindObject(u.exact, item.object);
      }
      break;
    }
    case Look::CubeTextured:
      bindEnvironment(scene, plan, item.object);
      break;
  }
  buffer->draw(item.ranges);
  const size_t triangles = item.ranges.empty() ? buffer->triangleCount() : item.triangles;
  return {static_cast<int>(std::max<size_t>(item.ranges.size(), 1)), triangles};
}

PassCounts SceneRenderer::drawItems(const Scene& scene, double seconds, const FramePlan& plan,
                                    const std::vector<DrawItem>& draws, const glm::mat4& viewProj,
                                    const glm::vec3& viewPosition,
                                    const glm::vec3& environmentViewPosition,
                                    const CaptureState& pass, int outputDirections) {
  // One program switch per variant present, in the keys' order (Phong first).
  std::vector<std::pair<ProgramKey, const DrawItem*>> keyed;
  keyed.reserve(draws.size());
  for (const DrawItem& d : draws) keyed.emplace_back(keyFor(scene, plan, d, pass, seconds), &d);
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  PassCounts counts;
  for (size_t i = 0; i < keyed.size();) {
    size_t end = i;
    while (end < keyed.size() && keyed[end].first == keyed[i].first) ++end;
    ProgramKey key = keyed[i].first;
    const Program* p = program(key);
    if (!p && key.glassExit) {  // no interior-map program: glass leaves at one surface
      key.glassExit = false;
      p = program(key);
    }
    if (p) {
      use(*p, scene, viewProj, key.look == Look::Phong ? viewPosition : environmentViewPosition,
          pass, outputDirections);
      for (size_t k = i; k < end; ++k) counts += drawObject(scene, plan, *keyed[k].second, seconds);
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
  prepareGlassExits(scene, seconds);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides
  glClearColor(scene.clearColour.r, scene.clearColour.g, scene.clearColour.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const CaptureState pass;  // the main pass: colour only
  PassCounts counts = drawItems(scene, seconds, plan, draws, camera.projection * camera.view,
                                camera.eye, camera.eye, pass, outputDirections);
  if (skybox_) skybox_->draw(camera.projection, camera.view, pass);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  checkGlError("main pass");
  return counts;
}

}  // namespace reflect
