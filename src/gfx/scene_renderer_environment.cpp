// SceneRenderer's programs and its reflectors: the shader variants by key (program_key.h), built
// the first time a draw needs one; which variant draws an object in a pass; and what a
// reflector's draw binds: its probe's colour cubes and depth pyramid, and the search's per-draw
// uniforms. The captures and draws are in scene_renderer.cpp.
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
void setFaceFrames(const ShaderProgram& p) {
  glm::vec3 right[6], up[6], axis[6];
  for (size_t f = 0; f < 6; ++f) {
    const glm::mat4 view = cubeFaceView(glm::vec3(0.0f), static_cast<int>(f));
    right[f] = glm::vec3(view[0][0], view[1][0], view[2][0]);
    up[f] = glm::vec3(view[0][1], view[1][1], view[2][1]);
    axis[f] = -glm::vec3(view[0][2], view[1][2], view[2][2]);
  }
  glUniform3fv(p.uniform("u_faceRight"), 6, glm::value_ptr(right[0]));
  glUniform3fv(p.uniform("u_faceUp"), 6, glm::value_ptr(up[0]));
  glUniform3fv(p.uniform("u_faceAxis"), 6, glm::value_ptr(axis[0]));
}

}  // namespace

using renderer_detail::bindTexture;
using renderer_detail::sphereRadiusIn;

Result<SceneRenderer::Program> SceneRenderer::buildProgram(const ProgramKey& key,
                                                           bool mediumpAsked) {
  const bool mediump = mediumpAsked && key.allowsMediump();
  const std::string precision = mediump ? "#define REFLECT_MEDIUMP 1\n" : "";
  Result<ShaderProgram> built =
      ShaderProgram::build("mesh.vert", key.fragmentFile(), mediump, precision + key.defines());
  if (!built) return Result<Program>::failure(built.error());
  const ShaderProgram& p = built.value();
  Program out;
  out.key = key;
  out.capture = CaptureUniforms::of(p);
  out.viewProjection = p.uniform("u_viewProjection");
  out.model = p.uniform("u_model");
  out.normalMatrix = p.optionalUniform("u_normalMatrix");
  out.viewPosition = p.optionalUniform("u_viewPosition");
  glUseProgram(p.id());
  switch (key.look) {
    case Look::Phong:
      out.phong = PhongUniforms{p.uniform("u_colour"),   p.uniform("u_lightPosition"),
                                p.uniform("u_ambient"),  p.uniform("u_diffuse"),
                                p.uniform("u_specular"), p.uniform("u_shininess")};
      break;
    case Look::Environment: {
      const auto at = [&p](const char* name) { return p.optionalUniform(name); };
      out.environment =
          EnvironmentUniforms{at("u_colour"),       at("u_reflectionWeight"), at("u_baseWeight"),
                              at("u_eta"),          at("u_fresnelF0"),        at("u_fresnel"),
                              at("u_twoSurfaces"),  at("u_glassSphere"),      at("u_probeCentre"),
                              at("u_distanceUnit"), at("u_outputDirection"),  at("u_layers"),
                              at("u_faceSize"),     at("u_topLevel"),         at("u_pyramidTile"),
                              at("u_roughLod"),     at("u_roughAlpha")};
      glUniform1i(at("u_environment"), kEnvironmentUnit);
      glUniform1i(at("u_environment2"), kEnvironment2Unit);
      glUniform1i(at("u_pyramid"), kPyramidUnit);
      if (key.rough) glUniform1i(at("u_prefiltered"), kPrefilteredUnit);
      if (key.search == Search::Hierarchical) setFaceFrames(p);
      if (key.glassExit) out.glassExit = GlassExitUniforms::of(p);
      break;
    }
    case Look::CubeTextured:
      glUniform1i(p.uniform("u_environment"), kEnvironmentUnit);
      break;
  }
  glUseProgram(0);
  out.program = built.take();
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
  key.rough = object.rough() && object.environment == Environment::LiveProbe;
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
  glm::vec3 centre(0.0f);
  if (const ProbeLayout* layout = plan.layoutOf(index)) centre = layout->centre;
  if (object.environment == Environment::Skybox) {
    colour = skybox_ ? skybox_->texture() : 0;
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
      topLevel = t.topLevel();
    }
  }
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, colour);
  if (current_->key.look == Look::CubeTextured) return;
  bindTexture(kEnvironment2Unit, GL_TEXTURE_CUBE_MAP, colour2 ? colour2 : colour);
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, pyramid);
  const EnvironmentUniforms& env = current_->environment;
  if (current_->key.rough) {
    const ProbePlan* probe = plan.probeOf(index);
    auto filtered = probe ? prefiltered_.find(probe->reflector) : prefiltered_.end();
    bindTexture(kPrefilteredUnit, GL_TEXTURE_CUBE_MAP,
                filtered != prefiltered_.end() ? filtered->second.texture() : 0);
    glUniform1f(env.roughLod,
                std::clamp(object.roughness, 0.0f, 1.0f) *
                    static_cast<float>(usableRoughLevels(accuracy_.roughLevels, faceSize)));
    glUniform1f(env.roughAlpha, ggxAlpha(object.roughness));
  }
  glActiveTexture(GL_TEXTURE0);
  glUniform3fv(env.probeCentre, 1, glm::value_ptr(centre));
  glUniform1f(env.distanceUnit, scene.capture.near);
  glUniform1i(env.layers, layers);
  glUniform1i(env.faceSize, faceSize);
  glUniform1i(env.topLevel, topLevel);
  glUniform1i(env.pyramidTile, 1 << topLevel);
}

}  // namespace reflect
