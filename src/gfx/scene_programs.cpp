#include "gfx/scene_programs.h"

#include "gfx/probe_irradiance.h"

#include <cstdio>

#include "core/cube_faces.h"

namespace reflect {
namespace {

// The faces' view directions as the capture renders them (cubeFaceView's lookAt): right, up and
// look direction per face, for the hierarchical search's projection onto each face.
void setFaceFrames(const EnvironmentUniforms& u) {
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

// What a program sets once, when it is built (into the program in use): its texture units, and
// for the hierarchical search the faces' frames.
void setOnce(const PhongUniforms& u, const ProgramKey&) {
  u.mesh.capture.setUnits();
}

void setOnce(const CubeTexturedUniforms& u, const ProgramKey&) {
  u.mesh.capture.setUnits();
  u.environment.set(kEnvironmentUnit);
}

void setOnce(const EnvironmentUniforms& u, const ProgramKey& key) {
  u.mesh.capture.setUnits();
  u.environment.set(kEnvironmentUnit);
  u.environment2.set(kEnvironment2Unit);
  u.pyramid.set(kPyramidUnit);
  u.prefiltered.set(kPrefilteredUnit);
  u.lobeSource.set(kLobeUnit);
  if (key.search == Search::Hierarchical) setFaceFrames(u);
  if (key.glassExit) u.glassExit.setUnits();
}

template <typename Program>
Result<SceneProgram> buildAs(const ProgramKey& key, bool mediump) {
  const std::string precision = mediump ? "#define REFLECT_MEDIUMP 1\n" : "";
  Result<Program> built =
      Program::build("mesh.vert", key.fragmentFile(), mediump, precision + key.defines());
  if (!built) return Result<SceneProgram>::failure(built.error());
  glUseProgram(built.value().id());
  setOnce(built.value().u(), key);
  glUseProgram(0);
  if (key.probeLight) {
    // The probe's irradiance buffer is bound there for each probe-lit draw (probe_irradiance.h).
    const GLuint id = built.value().id();
    glUniformBlockBinding(id, glGetUniformBlockIndex(id, "ProbeIrradiance"), kIrradianceBinding);
  }
  return SceneProgram{key, built.take()};
}

Result<SceneProgram> build(const ProgramKey& key, bool mediumpAsked) {
  const bool mediump = mediumpAsked && key.allowsMediump();
  switch (key.look) {
    case Look::Environment:
      return buildAs<EnvironmentProgram>(key, mediump);
    case Look::CubeTextured:
      return buildAs<CubeTexturedProgram>(key, mediump);
    case Look::Phong:
      break;
  }
  return buildAs<PhongProgram>(key, mediump);
}

}  // namespace

void PhongUniforms::setLight(const PhongLight& light) const {
  lightPosition.set(light.position);
  ambient.set(light.ambient);
  diffuse.set(light.diffuse);
  specular.set(light.specular);
  shininess.set(light.shininess);
}

GLuint SceneProgram::id() const {
  return std::visit([](const auto& p) { return p.id(); }, program);
}

const MeshPassUniforms& SceneProgram::mesh() const {
  return std::visit([](const auto& p) -> const MeshPassUniforms& { return p.u().mesh; }, program);
}

std::vector<std::string> SceneProgram::unlisted() const {
  return std::visit([](const auto& p) { return p.unlisted(); }, program);
}

const SceneProgram* ProgramCache::get(const ProgramKey& key) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return &it->second;
  if (failed_.count(key)) return nullptr;
  Result<SceneProgram> built = build(key, mediump_);
  if (!built) {
    failed_.insert(key);
    error_ = key.describe() + ": " + built.error();
    std::fprintf(stderr, "%s\n", error_.c_str());
    return nullptr;
  }
  return &programs_.emplace(key, built.take()).first->second;
}

std::vector<std::string> ProgramCache::unsetUniforms() const {
  std::vector<std::string> out;
  for (const auto& [key, p] : programs_) {
    for (const std::string& name : p.unlisted()) out.push_back(key.describe() + ": " + name);
  }
  return out;
}

}  // namespace reflect
