// SceneRenderer's reflector half: the environment programs (one per search, built when the
// renderer is made; the glass-exit variants when a non-sphere glass mesh first needs them), which
// one is active, and what a reflector's draw binds: its probe's colour cubes and depth pyramid,
// and the search's per-draw uniforms. The captures and draws are in scene_renderer.cpp.
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "core/cube_faces.h"
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

// The reflectors' program with the search SEARCH (environment.frag) and its uniforms.
Result<SceneRenderer::EnvironmentProgram> SceneRenderer::buildEnvironment(
    int search, bool mediump, const std::string& precision, bool glassExit) {
  const std::string lookup = precision + "#define SEARCH " + std::to_string(search) +
                             "\n#define DISTANCE_ITERATIONS 2\n#define GLASS_EXIT " +
                             (glassExit ? "1" : "0") + "\n";
  Result<ShaderProgram> built =
      ShaderProgram::build("mesh.vert", "environment.frag", mediump, lookup);
  if (!built) return Result<EnvironmentProgram>::failure(built.error());
  const ShaderProgram& e = built.value();
  EnvironmentProgram env{ShaderProgram{},
                         CaptureUniforms::of(e),
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
                         e.optionalUniform("u_twoSurfaces"),
                         e.optionalUniform("u_glassSphere"),
                         e.optionalUniform("u_probeCentre"),
                         e.optionalUniform("u_distanceUnit"),
                         e.optionalUniform("u_search"),
                         e.uniform("u_outputDirection"),
                         e.optionalUniform("u_layers"),
                         e.optionalUniform("u_faceSize"),
                         e.optionalUniform("u_topLevel"),
                         e.optionalUniform("u_pyramidTile"),
                         GlassExitUniforms{}};
  glUseProgram(e.id());
  glUniform1i(e.optionalUniform("u_environment"), kEnvironmentUnit);
  glUniform1i(e.optionalUniform("u_environment2"), kEnvironment2Unit);
  glUniform1i(e.optionalUniform("u_pyramid"), kPyramidUnit);
  if (search == static_cast<int>(Search::Hierarchical)) setFaceFrames(e);
  if (glassExit) env.glassExit = GlassExitUniforms::of(e);
  env.program = built.take();
  return env;
}

bool SceneRenderer::searchesFor(const Scene& scene, const FramePlan& plan, int index) const {
  if (accuracy_.search == Search::Plain) return false;
  if (scene.objects[static_cast<size_t>(index)].environment == Environment::Skybox) return false;
  const ProbePlan* probe = plan.probeOf(index);
  return probe && !probe->plainLookupSuffices && probes_.count(probe->reflector) > 0;
}

const SceneRenderer::EnvironmentProgram& SceneRenderer::activeEnvironment() const {
  switch (current_) {
    case ProgramKind::PlainEnvironment:
      return plainEnvironment_;
    case ProgramKind::GlassEnvironment:
      return glassEnvironment_;
    case ProgramKind::PlainGlassEnvironment:
      return plainGlassEnvironment_;
    default:
      return environment_;
  }
}

void SceneRenderer::prepareGlassExits(const Scene& scene, double seconds) {
  if (accuracy_.glassSurfaces != 2 || accuracy_.search == Search::Exact || glassExitFailed_) {
    return;
  }
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material != Material::Glass) continue;
    const MeshBuffer* full = mesh(object.mesh, 0);
    if (!full || sphereRadiusIn(full, scene.modelMatrix(object, seconds)) > 0.0f) {
      continue;  // no mesh yet, or a sphere: its exit has a closed form
    }
    if (!glassInteriors_.mapFor(object.mesh, *full)) continue;
    if (glassEnvironment_.program.id()) continue;
    const bool mediump = accuracy_.mediump;
    const std::string precision = mediump ? "#define REFLECT_MEDIUMP 1\n" : "";
    Result<EnvironmentProgram> built =
        buildEnvironment(static_cast<int>(accuracy_.search), mediump, precision, true);
    const bool searches = plainEnvironment_.program.id() != 0;
    Result<EnvironmentProgram> plain =
        searches ? buildEnvironment(static_cast<int>(Search::Plain), mediump, precision, true)
                 : Result<EnvironmentProgram>(EnvironmentProgram{});
    if (!built || !plain) {
      std::fprintf(stderr, "glass exit: %s\n", (built ? plain : built).error().c_str());
      glassExitFailed_ = true;  // do not try again every frame
      return;
    }
    glassEnvironment_ = built.take();
    plainGlassEnvironment_ = plain.take();
  }
}

const GlassInteriorMap* SceneRenderer::glassExitOf(const SceneObject& object,
                                                   const glm::mat4& model) const {
  if (!glassEnvironment_.program.id() || object.material != Material::Glass) return nullptr;
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
  if (object.environment == Environment::Skybox) {
    colour = skybox_ ? skybox_->texture() : 0;
  } else if (const ProbePlan* probe = plan.probeOf(index)) {
    centre = probe->centre;
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
  if (current_ == ProgramKind::CubeTextured) {
    bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, colour);
    return;
  }
  bindTexture(kEnvironmentUnit, GL_TEXTURE_CUBE_MAP, colour);
  bindTexture(kEnvironment2Unit, GL_TEXTURE_CUBE_MAP, colour2 ? colour2 : colour);
  bindTexture(kPyramidUnit, GL_TEXTURE_2D, pyramid);
  glActiveTexture(GL_TEXTURE0);
  const EnvironmentProgram& env = activeEnvironment();
  glUniform3fv(env.probeCentre, 1, glm::value_ptr(centre));
  glUniform1f(env.distanceUnit, scene.capture.near);
  glUniform1i(env.search, searchesFor(scene, plan, index) ? 1 : 0);
  glUniform1i(env.layers, layers);
  glUniform1i(env.faceSize, faceSize);
  glUniform1i(env.topLevel, topLevel);
  glUniform1i(env.pyramidTile, 1 << topLevel);
}

}  // namespace reflect
