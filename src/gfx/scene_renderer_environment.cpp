// SceneRenderer's environment binding: which program variant (program_key.h) draws an object in a
// pass, and what a reflector's draw binds: its probe's colour cubes and depth pyramid (or the
// sky), and the search's per-draw uniforms. The programs themselves are scene_programs.h's; the
// captures are in scene_renderer_capture.cpp, the draws in scene_renderer.cpp.
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"
#include "core/ggx.h"
#include "gfx/scene_renderer.h"
#include "gfx/scene_renderer_detail.h"

namespace reflect {
using renderer_detail::bindTexture;
using renderer_detail::sphereRadiusIn;

std::vector<std::string> SceneRenderer::unsetUniforms() const {
  std::vector<std::string> out = programs_.unsetUniforms();
  if (skybox_) {
    for (const std::string& name : skybox_->unlisted()) out.push_back("skybox: " + name);
  }
  for (const std::string& name : pyramid_.unlisted()) out.push_back("depth pyramid: " + name);
  return out;
}

ProgramKey SceneRenderer::keyFor(const Scene& scene, const FramePlan& plan, const DrawItem& item,
                                 const CaptureState& pass) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(item.object)];
  ProgramKey key;
  key.capture = pass.layer != 0;
  if (object.material == Material::Phong) return key;
  if (object.material == Material::CubeTextured) {
    key.look = Look::CubeTextured;
    return key;
  }
  key.look = Look::Environment;
  key.refracts = object.material == Material::Glass;
  key.rough = object.rough();
  if (plan.traces(item.object)) {
    key.search = Search::Exact;
    // Rays that can meet another mirror, glass or cube-textured object (or glass's own far
    // side) need the general tracer; the rest meet Phong surfaces or the sky.
    key.traceGeneral = key.refracts;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      key.traceGeneral |=
          i != static_cast<size_t>(item.object) && scene.objects[i].material != Material::Phong;
    }
    return key;
  }
  // A mirror seen in another probe's capture looks its own cube up plainly: that view is a
  // second bounce, seen small and from the previous frame, and a search in every texel of it cost
  // more than the rest of the frame (two-mirrors: 8.2x -> 3.7x the course's frame, -0.2 dB, +1
  // pixel off by more than 32 levels a frame; tools/scene_accuracy.sh).
  const bool searches = pass.layer == 0 && searchesFor(scene, plan, item.object);
  key.search = searches ? capturedSearch(accuracy_.search) : Search::Plain;
  key.glassExit = key.refracts && glassExitOf(object, plan.modelOf(item.object)) != nullptr;
  return key;
}

bool SceneRenderer::searchesFor(const Scene& scene, const FramePlan& plan, int index) const {
  const Search search = capturedSearch(accuracy_.search);
  if (search == Search::Plain || search == Search::Exact) return false;
  if (scene.objects[static_cast<size_t>(index)].environment == Environment::Skybox) return false;
  const ProbePlan* probe = plan.probeOf(index);
  return probe && !probe->plainLookupSuffices && probes_.count(probe->reflector) > 0;
}

void SceneRenderer::prepareGlassExits(const Scene& scene, const FramePlan& plan) {
  if (accuracy_.glassSurfaces != 2 || accuracy_.search == Search::Exact) return;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material != Material::Glass) continue;
    const MeshBuffer* full = mesh(object.mesh, 0);
    if (!full || sphereRadiusIn(full, plan.modelOf(static_cast<int>(i))) > 0.0f) {
      continue;  // no mesh yet, or a sphere: its exit has a closed form
    }
    glassInteriors_.mapFor(object.mesh, *full);
  }
}

const GlassInteriorMap* SceneRenderer::glassExitOf(const SceneObject& object,
                                                   const glm::mat4& model) const {
  if (accuracy_.glassSurfaces != 2 || object.material != Material::Glass) return nullptr;
  const MeshBuffer* full = mesh(object.mesh, 0);
  if (!full || sphereRadiusIn(full, model) > 0.0f) return nullptr;
  return glassInteriors_.find(object.mesh);
}

SceneRenderer::EnvironmentBinding SceneRenderer::environmentOf(const Scene& scene,
                                                               const FramePlan& plan,
                                                               int index) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(index)];
  EnvironmentBinding b;
  b.pyramid = emptyPyramid_.id();
  if (const ProbeLayout* layout = plan.layoutOf(index)) b.centre = layout->centre;
  if (object.environment == Environment::Skybox) {
    b.colour = skybox_ ? skybox_->texture() : 0;
    b.prefiltered = skyPrefilteredTexture();
    b.filteredFaceSize = skybox_ ? skybox_->faceSize() : 1;
  } else if (const ProbePlan* probe = plan.probeOf(index)) {
    auto it = probes_.find(probe->reflector);
    if (it != probes_.end()) {
      const CubeCaptureTarget& t = it->second;
      b.colour = t.texture(0);
      b.layers = t.format().layers;
      b.colour2 = b.layers == 2 ? t.texture(1) : b.colour;
      if (t.format().depthChain) b.pyramid = t.pyramid();
      b.faceSize = t.faceSize();
      b.filteredFaceSize = b.faceSize;
      b.topLevel = t.topLevel();
    }
    auto filtered = prefiltered_.find(probe->reflector);
    if (filtered != prefiltered_.end()) b.prefiltered = filtered->second.texture();
  }
  return b;
}

void SceneRenderer::bindEnvironment(const EnvironmentUniforms& u, const ProgramKey& key,
                                    const Scene& scene, const SceneObject& object,
                                    const EnvironmentBinding& b) const {
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, b.colour);
  bindTexture(kEnvironment2Unit, GL_TEXTURE_CUBE_MAP, b.colour2 ? b.colour2 : b.colour);
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, b.pyramid);
  if (key.rough) {
    bindTexture(kPrefilteredUnit, GL_TEXTURE_CUBE_MAP, b.prefiltered);
    const float levels =
        static_cast<float>(usableRoughLevels(accuracy_.roughLevels, b.filteredFaceSize));
    u.roughLod.set(std::clamp(object.roughness, 0.0f, 1.0f) * levels);
    u.refractLod.set(transmissionRoughness(object.roughness, object.ior) * levels);
    u.roughAlpha.set(ggxAlpha(object.roughness));
  }
  glActiveTexture(GL_TEXTURE0);
  u.probeCentre.set(b.centre);
  u.distanceUnit.set(scene.capture.near);
  u.layers.set(b.layers);
  u.faceSize.set(b.faceSize);
  u.topLevel.set(b.topLevel);
  u.pyramidTile.set(1 << b.topLevel);
}

}  // namespace reflect
