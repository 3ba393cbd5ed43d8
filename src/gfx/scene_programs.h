// The scene's programs, one class each, with its own table of typed uniforms (uniform_table.h):
// Phong (phong.frag), the environment lookup of mirrors and glass (environment.frag, every
// search, the exact tracer among them) and Ex12-1's cube-textured material
// (cube_textured.frag). All three draw meshes through mesh.vert and write through
// capture_output.glsl, whose uniforms each table holds as its first entries (MeshPassUniforms).
// A value set for one program cannot reach another's table: each draw is handed the program's
// own type. ProgramCache builds each variant (program_key.h) the first time a draw needs it.
#pragma once

#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "core/scene.h"
#include "gfx/capture_state.h"
#include "gfx/exact_tracer.h"
#include "gfx/glass_interior_map.h"
#include "gfx/program_key.h"
#include "gfx/uniform_table.h"

namespace reflect {

// mesh.vert's and capture_output.glsl's uniforms: entries of each scene program's table.
struct MeshPassUniforms {
  UniformTable& table;
  CaptureUniforms capture{table};
  Uniform<glm::mat4> viewProjection{table, "u_viewProjection"};
  Uniform<glm::mat4> model{table, "u_model"};
  Uniform<glm::mat3> normalMatrix{table, "u_normalMatrix"};
  Uniform<glm::vec3> viewPosition{table, "u_viewPosition"};
  Uniform<glm::vec3> colour{table, "u_colour"};
};

struct PhongUniforms : UniformTable {
  MeshPassUniforms mesh{*this};
  Uniform<glm::vec3> lightPosition{*this, "u_lightPosition"};
  Uniform<float> ambient{*this, "u_ambient"};
  Uniform<float> diffuse{*this, "u_diffuse"};
  Uniform<float> specular{*this, "u_specular"};
  Uniform<float> shininess{*this, "u_shininess"};
  // A probe-lit object's probe centre and ambientRadius (0 where none is set: phong.frag's
  // irradianceDirection).
  Uniform<glm::vec4> irradianceProxy{*this, "u_irradianceProxy"};
  void setLight(const PhongLight& light) const;
};

struct CubeTexturedUniforms : UniformTable {
  MeshPassUniforms mesh{*this};
  Uniform<int> environment{*this, "u_environment"};
};

struct EnvironmentUniforms : UniformTable {
  MeshPassUniforms mesh{*this};
  // The material.
  Uniform<float> reflectionWeight{*this, "u_reflectionWeight"};
  Uniform<float> baseWeight{*this, "u_baseWeight"};
  Uniform<float> eta{*this, "u_eta"};
  Uniform<float> fresnelF0{*this, "u_fresnelF0"};
  Uniform<bool> fresnel{*this, "u_fresnel"};
  Uniform<bool> twoSurfaces{*this, "u_twoSurfaces"};
  Uniform<glm::vec4> glassSphere{*this, "u_glassSphere"};
  Uniform<float> roughLod{*this, "u_roughLod"};
  Uniform<float> refractLod{*this, "u_refractLod"};
  Uniform<float> roughAlpha{*this, "u_roughAlpha"};
  Uniform<float> refractAlpha{*this, "u_refractAlpha"};
  Uniform<int> lobeTaps{*this, "u_lobeTaps"};
  Uniform<bool> lobeQuarters{*this, "u_lobeQuarters"};
  // The probe and its search.
  Uniform<glm::vec3> probeCentre{*this, "u_probeCentre"};
  Uniform<float> distanceUnit{*this, "u_distanceUnit"};
  Uniform<int> outputDirection{*this, "u_outputDirection"};
  Uniform<int> layers{*this, "u_layers"};
  Uniform<int> faceSize{*this, "u_faceSize"};
  Uniform<int> topLevel{*this, "u_topLevel"};
  Uniform<int> pyramidTile{*this, "u_pyramidTile"};
  UniformArray<glm::vec3> faceRight{*this, "u_faceRight"};
  UniformArray<glm::vec3> faceUp{*this, "u_faceUp"};
  UniformArray<glm::vec3> faceAxis{*this, "u_faceAxis"};
  // Texture units, set once when the program is built.
  Uniform<int> environment{*this, "u_environment"};
  Uniform<int> environment2{*this, "u_environment2"};
  Uniform<int> pyramid{*this, "u_pyramid"};
  Uniform<int> prefiltered{*this, "u_prefiltered"};
  Uniform<int> lobeSource{*this, "u_lobeSource"};
  GlassExitUniforms glassExit{*this};
  ExactUniforms exact{*this};
};

using PhongProgram = TabledProgram<PhongUniforms>;
using EnvironmentProgram = TabledProgram<EnvironmentUniforms>;
using CubeTexturedProgram = TabledProgram<CubeTexturedUniforms>;

// One variant: its key and the program of its look's type.
struct SceneProgram {
  ProgramKey key;
  std::variant<PhongProgram, EnvironmentProgram, CubeTexturedProgram> program;

  GLuint id() const;
  const MeshPassUniforms& mesh() const;
  std::vector<std::string> unlisted() const;
};

// Each variant built once, the first time a draw asks for it.
class ProgramCache {
 public:
  explicit ProgramCache(bool mediump) : mediump_(mediump) {}
  // The program of `key`; null when it does not build (the error goes to stderr once, and to
  // lastError()).
  const SceneProgram* get(const ProgramKey& key);
  const std::string& lastError() const { return error_; }
  size_t size() const { return programs_.size(); }
  // "<variant>: <name>" for each active uniform of a built program that no entry sets.
  std::vector<std::string> unsetUniforms() const;

 private:
  bool mediump_;
  std::map<ProgramKey, SceneProgram> programs_;
  std::set<ProgramKey> failed_;
  std::string error_;
};

}  // namespace reflect
