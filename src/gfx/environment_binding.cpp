#include "gfx/environment_binding.h"

#include <algorithm>

#include "core/bvh.h"
#include "core/fresnel.h"
#include "core/ggx.h"
#include "gfx/probe_capture.h"
#include "gfx/probe_irradiance.h"
#include "gfx/scene_renderer_detail.h"

namespace reflect {
using renderer_detail::bindTexture;
using renderer_detail::sphereRadiusIn;

namespace {

// A traced rough mirror or frosted glass seen in another probe's capture is a second bounce, seen
// small and blurred: it traces its lobe's centre alone, through the Phong objects (what mirrors
// show in it is a third bounce; glass leaves a sphere in closed form). On rough-spheres that kept
// the other spheres within 0.05 dB and cut the capture from 70 to 41 ms (docs/rough.md, "Narrow
// lobes: traced").
bool lobeCentreAlone(const ProgramKey& key) {
  return key.capture && key.rough;
}

}  // namespace

ProgramKey EnvironmentBinding::keyFor(const Scene& scene, const FramePlan& plan,
                                      const DrawItem& item, const CaptureState& pass) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(item.object)];
  ProgramKey key;
  key.capture = pass.layer != 0;
  if (object.material == Material::Phong) {
    // Probe light is one bounce: captures (and so reflections) show the constant ambient.
    key.probeLight = !key.capture && plan.irradianceOf(item.object) != nullptr;
    return key;
  }
  if (object.material == Material::CubeTextured) {
    key.look = Look::CubeTextured;
    return key;
  }
  key.look = Look::Environment;
  key.refracts = object.material == Material::Glass;
  key.rough = object.rough();
  if (plan.traces(item.object)) {
    key.search = Search::Exact;
    // The planner's rule, costed there, but for a rough mirror's lobe centre in a capture.
    key.traceGeneral = plan.tracesGeneral(item.object) && !lobeCentreAlone(key);
    key.traceStack =
        traceStackFor(scene.objects.size(), s_.exact ? s_.exact->deepestMesh() : kBvhMaxDepth);
    return key;
  }
  // A mirror seen in another probe's capture looks its own cube up plainly: that view is a
  // second bounce, seen small and from the previous frame, and a search in every texel of it cost
  // more than the rest of the frame (two-mirrors: 8.2x -> 3.7x the course's frame, -0.2 dB, +1
  // pixel off by more than 32 levels a frame; tools/scene_accuracy.sh).
  const bool searches = pass.layer == 0 && searchesFor(scene, plan, item.object);
  key.search = searches ? capturedSearch(s_.accuracy.search) : Search::Plain;
  // The static sky has no box chain: its rough readers read its prefiltered levels.
  key.roughTaps = key.rough && s_.accuracy.lobeTaps > 0 &&
                  object.environment != Environment::Skybox && plan.probeOf(item.object) != nullptr;
  key.glassExit = key.refracts && s_.glass.exitOf(object, plan.modelOf(item.object), s_.meshes,
                                                  s_.accuracy) != nullptr;
  return key;
}

bool EnvironmentBinding::searchesFor(const Scene& scene, const FramePlan& plan, int index) const {
  const Search search = capturedSearch(s_.accuracy.search);
  if (search == Search::Plain || search == Search::Exact) return false;
  if (scene.objects[static_cast<size_t>(index)].environment == Environment::Skybox) return false;
  const ProbePlan* probe = plan.probeOf(index);
  return probe && !probe->plainLookupSuffices && s_.probes.target(probe->reflector) != nullptr;
}

void EnvironmentBinding::bindTracer(const EnvironmentUniforms& u, const ProgramKey& key) const {
  if (key.search == Search::Exact && s_.exact) s_.exact->bind(u.exact, key.traceGeneral);
}

void EnvironmentBinding::setForObject(const PhongUniforms& u, const ProgramKey& key,
                                      const Scene& scene, const FramePlan& plan, int object) const {
  if (!key.probeLight) return;
  s_.irradiance.bindFor(plan, object);
  const ProbePlan* light = plan.irradianceOf(object);
  // A radius set in the scene for phong.frag; or none, and parallaxFor's taps read the
  // probe's own distances.
  const std::optional<float> set = scene.objects[static_cast<size_t>(object)].ambientRadius;
  const glm::vec3 centre = light ? light->centre : glm::vec3(0.0f);
  u.irradianceProxy.set(glm::vec4(centre, light && set ? *set : 0.0f));
}

GLuint EnvironmentBinding::parallaxFor(const Scene& scene, const FramePlan& plan, int object,
                                       const MeshBuffer& mesh) const {
  const ProbePlan* light = plan.irradianceOf(object);
  if (!light || scene.objects[static_cast<size_t>(object)].ambientRadius) return 0;
  const CubeCaptureTarget* target = s_.probes.target(light->reflector);
  if (!target) return 0;
  return s_.irradiance.feedParallax(object, mesh.vertexArray(), mesh.vertexCount(),
                                    plan.modelOf(object), target->texture(0), target->faceSize(),
                                    light->centre, scene.capture.near);
}

void EnvironmentBinding::setForObject(const EnvironmentUniforms& u, const ProgramKey& key,
                                      const Scene& scene, const FramePlan& plan, int index) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(index)];
  const glm::mat4& model = plan.modelOf(index);
  u.reflectionWeight.set(object.reflection);
  u.baseWeight.set(object.base);
  u.eta.set(1.0f / clampedIor(object.ior));
  u.fresnelF0.set(fresnelF0(object.ior));
  u.fresnel.set(object.fresnel);
  if (key.refracts) {
    // Glass leaves through its far side: where the mesh is a sphere (uniformly scaled) in closed
    // form, otherwise through its interior map, with the GLASS_EXIT programs.
    const MeshBuffer* full = s_.meshes ? s_.meshes->find(object.mesh, 0) : nullptr;
    const float radius = sphereRadiusIn(full, model);
    const GlassInteriorMap* interior =
        key.glassExit ? s_.glass.exitOf(object, model, s_.meshes, s_.accuracy) : nullptr;
    if (interior) u.glassExit.set(*interior, model);
    u.twoSurfaces.set(s_.accuracy.glassSurfaces == 2 && (radius > 0.0f || interior));
    const glm::vec3 centre(model * glm::vec4(full ? full->bounds().centre() : glm::vec3(0), 1));
    u.glassSphere.set(glm::vec4(centre, radius));
  }
  bind(u, key, scene, object, texturesOf(scene, plan, index));
  if (key.search == Search::Exact && s_.exact) {
    const int rays = lobeCentreAlone(key) ? 1 : std::max(plan.lobeRaysOf(index), 1);
    s_.exact->bindObject(u.exact, index, rays);
  }
}

void EnvironmentBinding::setForObject(const CubeTexturedUniforms&, const ProgramKey&,
                                      const Scene& scene, const FramePlan& plan, int index) const {
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, texturesOf(scene, plan, index).colour);
  glActiveTexture(GL_TEXTURE0);
}

EnvironmentBinding::Textures EnvironmentBinding::texturesOf(const Scene& scene,
                                                            const FramePlan& plan,
                                                            int index) const {
  const SceneObject& object = scene.objects[static_cast<size_t>(index)];
  Textures b;
  b.pyramid = s_.probes.emptyPyramid();
  if (const ProbeLayout* layout = plan.layoutOf(index)) b.centre = layout->centre;
  if (object.environment == Environment::Skybox) {
    b.colour = s_.sky ? s_.sky->texture() : 0;
    b.prefiltered = s_.rough.skyTexture();
    b.filteredFaceSize = s_.sky ? s_.sky->faceSize() : 1;
  } else if (const ProbePlan* probe = plan.probeOf(index)) {
    if (const CubeCaptureTarget* t = s_.probes.target(probe->reflector)) {
      b.colour = t->texture(0);
      b.layers = t->format().layers;
      b.colour2 = b.layers == 2 ? t->texture(1) : b.colour;
      if (t->format().depthChain) b.pyramid = t->pyramid();
      b.faceSize = t->faceSize();
      b.filteredFaceSize = b.faceSize;
      b.topLevel = t->topLevel();
    }
    if (GLuint filtered = s_.rough.probeTexture(probe->reflector)) b.prefiltered = filtered;
  }
  return b;
}

void EnvironmentBinding::bind(const EnvironmentUniforms& u, const ProgramKey& key,
                              const Scene& scene, const SceneObject& object,
                              const Textures& t) const {
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, t.colour);
  bindTexture(kEnvironment2Unit, GL_TEXTURE_CUBE_MAP, t.colour2 ? t.colour2 : t.colour);
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, t.pyramid);
  if (key.roughTaps) {
    bindTexture(kLobeUnit, GL_TEXTURE_CUBE_MAP, t.colour);
    glBindSampler(kLobeUnit, s_.probes.lobeSampler());
    u.lobeTaps.set(s_.accuracy.lobeTaps);
    u.lobeQuarters.set(s_.accuracy.lobeQuarters);
    u.roughAlpha.set(ggxAlpha(object.roughness));
    u.refractAlpha.set(ggxAlpha(transmissionRoughness(object.roughness, object.ior)));
  } else if (key.rough) {
    bindTexture(kPrefilteredUnit, GL_TEXTURE_CUBE_MAP, t.prefiltered);
    const float levels =
        static_cast<float>(usableRoughLevels(s_.accuracy.roughLevels, t.filteredFaceSize));
    u.roughLod.set(std::clamp(object.roughness, 0.0f, 1.0f) * levels);
    u.refractLod.set(transmissionRoughness(object.roughness, object.ior) * levels);
    u.roughAlpha.set(ggxAlpha(object.roughness));
  }
  glActiveTexture(GL_TEXTURE0);
  u.probeCentre.set(t.centre);
  u.distanceUnit.set(scene.capture.near);
  u.layers.set(t.layers);
  u.faceSize.set(t.faceSize);
  u.topLevel.set(t.topLevel);
  u.pyramidTile.set(1 << t.topLevel);
}

}  // namespace reflect
