// SceneRenderer's programs and its reflectors: the shader variants by key (program_key.h), built
// the first time a draw needs one; which variant draws an object in a pass; and what a
// reflector's draw binds: its probe's colour cubes and depth pyramid, and the search's per-draw
// uniforms. The captures are in scene_renderer_capture.cpp, the draws in scene_renderer.cpp.
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"
#include "core/ggx.h"
#include "gfx/scene_renderer.h"
#include "gfx/scene_renderer_detail.h"

namespace reflect {
namespace {

// The faces' view directions as the capture renders them (cubeFaceView's lookAt): right, up and
// look direction per face, for the search's projection onto each face.
template <typename Uniforms>
void setFaceFrames(const Uniforms& u) {
  glm::vec3 right[6], up[6], axis[6];
  for (size_t f = 0; f < 6; ++f) {
    const glm::mat4 view = cubeFaceView(glm::vec3(0.0f), static_cast<int>(f));
    right[f] = glm::vec3(view[0][0], view[1][0], view[2][0]);
    up[f] = glm::vec3(view[0][1], view[1][1], view[2][1]);
    axis[f] = -glm::vec3(view[0][2], view[1][2], view[2][2]);
  }
  u.faceRight.set(right, 6);
  u.faceUp.set(up, 6);
  u.faceAxis.set(axis, 6);
}

}  // namespace

using renderer_detail::bindTexture;
using renderer_detail::sphereRadiusIn;

Result<SceneRenderer::Program> SceneRenderer::buildProgram(const ProgramKey& key,
                                                           bool mediumpAsked) {
  const bool mediump = mediumpAsked && key.allowsMediump();
  const std::string precision = mediump ? "#define REFLECT_MEDIUMP 1\n" : "";
  auto built = TabledProgram<ProgramUniforms>::build("mesh.vert", key.fragmentFile(), mediump,
                                                     precision + key.defines());
  if (!built) return Result<Program>::failure(built.error());
  Program out{key, built.take()};
  const ProgramUniforms& u = out.program.u();
  glUseProgram(out.program.id());
  u.capture.setUnits();
  u.environment.set(kEnvironmentUnit);
  u.environment2.set(kEnvironment2Unit);
  u.pyramid.set(kPyramidUnit);
  u.prefiltered.set(kPrefilteredUnit);
  if (key.search == Search::Hierarchical) setFaceFrames(u);
  if (key.glassExit) u.glassExit.setUnits();
  glUseProgram(0);
  return out;
}

const SceneRenderer::Program* SceneRenderer::program(const ProgramKey& key) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return &it->second;
  if (failedPrograms_.count(key)) return nullptr;
  Result<Program> built = buildProgram(key, accuracy_.mediump);
  if (!built) {
    failedPrograms_.insert(key);
    programError_ = key.describe() + ": " + built.error();
    std::fprintf(stderr, "%s\n", programError_.c_str());
    return nullptr;
  }
  return &programs_.emplace(key, built.take()).first->second;
}

std::vector<std::string> SceneRenderer::unsetUniforms() const {
  std::vector<std::string> out;
  for (const auto& [key, p] : programs_) {
    for (const std::string& name : p.program.unlisted()) {
      out.push_back(key.describe() + ": " + name);
    }
  }
  if (skybox_) {
    for (const std::string& name : skybox_->unlisted()) out.push_back("skybox: " + name);
  }
  for (const std::string& name : pyramid_.unlisted()) out.push_back("depth pyramid: " + name);
  return out;
}

ProgramKey SceneRenderer::keyFor(const Scene& scene, const FramePlan& plan, const DrawItem& item,
                                 const CaptureState& pass, double seconds) const {
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
  key.glassExit =
      key.refracts && glassExitOf(object, scene.modelMatrix(object, seconds)) != nullptr;
  return key;
}

bool SceneRenderer::searchesFor(const Scene& scene, const FramePlan& plan, int index) const {
  const Search search = capturedSearch(accuracy_.search);
  if (search == Search::Plain || search == Search::Exact) return false;
  if (scene.objects[static_cast<size_t>(index)].environment == Environment::Skybox) return false;
  const ProbePlan* probe = plan.probeOf(index);
  return probe && !probe->plainLookupSuffices && probes_.count(probe->reflector) > 0;
}

void SceneRenderer::prepareGlassExits(const Scene& scene, double seconds) {
  if (accuracy_.glassSurfaces != 2 || accuracy_.search == Search::Exact) return;
  for (const SceneObject& object : scene.objects) {
    if (object.material != Material::Glass) continue;
    const MeshBuffer* full = mesh(object.mesh, 0);
    if (!full || sphereRadiusIn(full, scene.modelMatrix(object, seconds)) > 0.0f) {
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

void SceneRenderer::bindEnvironment(const Scene& scene, const FramePlan& plan, int index) {
  const SceneObject& object = scene.objects[static_cast<size_t>(index)];
  GLuint colour = 0, colour2 = 0;
  GLuint pyramid = emptyPyramid_.id();
  int layers = 1, faceSize = 1, topLevel = 0;
  GLuint prefiltered = 0;
  int filteredFaceSize = 1;  // the face size of the cube the rough levels were filtered from
  glm::vec3 centre(0.0f);
  if (const ProbeLayout* layout = plan.layoutOf(index)) centre = layout->centre;
  if (object.environment == Environment::Skybox) {
    colour = skybox_ ? skybox_->texture() : 0;
    prefiltered = skyPrefilteredTexture();
    filteredFaceSize = skybox_ ? skybox_->faceSize() : 1;
  } else if (const ProbePlan* probe = plan.probeOf(index)) {
    auto it = probes_.find(probe->reflector);
    if (it != probes_.end()) {
      const CubeCaptureTarget& t = it->second;
      colour = t.texture(0);
      layers = t.format().layers;
      colour2 = layers == 2 ? t.texture(1) : colour;
      if (t.format().depthChain) {
        pyramid = t.pyramid();
      }
      faceSize = t.faceSize();
      filteredFaceSize = faceSize;
      topLevel = t.topLevel();
    }
    auto filtered = prefiltered_.find(probe->reflector);
    if (filtered != prefiltered_.end()) prefiltered = filtered->second.texture();
  }
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, colour);
  if (current_->key.look == Look::CubeTextured) return;
  bindTexture(kEnvironment2Unit, GL_TEXTURE_CUBE_MAP, colour2 ? colour2 : colour);
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, pyramid);
  const ProgramUniforms& u = current_->program.u();
  if (current_->key.rough) {
    bindTexture(kPrefilteredUnit, GL_TEXTURE_CUBE_MAP, prefiltered);
    const float levels =
        static_cast<float>(usableRoughLevels(accuracy_.roughLevels, filteredFaceSize));
    u.roughLod.set(std::clamp(object.roughness, 0.0f, 1.0f) * levels);
    u.refractLod.set(transmissionRoughness(object.roughness, object.ior) * levels);
    u.roughAlpha.set(ggxAlpha(object.roughness));
  }
  glActiveTexture(GL_TEXTURE0);
  u.probeCentre.set(centre);
  u.distanceUnit.set(scene.capture.near);
  u.layers.set(layers);
  u.faceSize.set(faceSize);
  u.topLevel.set(topLevel);
  u.pyramidTile.set(1 << topLevel);
}

}  // namespace reflect
