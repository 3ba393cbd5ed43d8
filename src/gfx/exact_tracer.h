// The exact mode's scene on the GPU (search: exact; shaders/exact_trace.glsl): every mesh's BVH
// (core/bvh.h, built once when the mesh loads) in one atlas of float textures, uploaded when the
// set of meshes changes; the top level over the placed objects, rebuilt and uploaded every frame
// (prepare), so a moving figure costs no rebuild of its mesh's tree; and the sky the rays see
// where they meet nothing. The scene renderer binds it with the environment program.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/bvh.h"
#include "core/frame_planner.h"
#include "core/result.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/capture_state.h"
#include "gfx/gl_handle.h"
#include "gfx/skybox_pass.h"
#include "gfx/uniform_table.h"

namespace reflect {

// Texture units of the exact mode's samplers (after capture_state.h's).
inline constexpr GLint kExactAtlasUnit = kPeelBacksUnit + 1;
inline constexpr GLint kExactNormalsUnit = kExactAtlasUnit + 1;
inline constexpr GLint kExactSceneUnit = kExactAtlasUnit + 2;
inline constexpr GLint kExactSkyUnit = kExactAtlasUnit + 3;
// WebGL2 and GL ES 3.0 promise 16 units to a fragment shader.
static_assert(kExactSkyUnit < 16,
              "the exact mode's samplers must fit the 16 units ES 3.0 promises");

// exact_trace.glsl's and exact_shade.glsl's uniforms, entries of their program's table
// (uniform_table.h); -1 in the variants that do not trace.
struct ExactUniforms {
  UniformTable& table;
  Uniform<int> atlas{table, "u_exactAtlas"};
  Uniform<int> normals{table, "u_exactNormals"};
  Uniform<int> scene{table, "u_exactScene"};
  Uniform<int> sky{table, "u_exactSky"};
  Uniform<bool> hasSky{table, "u_exactHasSky"};
  Uniform<glm::vec3> clear{table, "u_exactClear"};
  Uniform<int> header{table, "u_exactHeader"};
  Uniform<bool> empty{table, "u_exactEmpty"};
  Uniform<glm::vec3> light{table, "u_exactLight"};
  Uniform<glm::vec4> phong{table, "u_exactPhong"};
  Uniform<glm::vec3> eye{table, "u_exactEye"};
  Uniform<float> far{table, "u_exactFar"};
  Uniform<bool> mark{table, "u_exactMark"};
  Uniform<int> lobeRays{table, "u_exactLobeRays"};
  Uniform<int> self{table, "u_exactSelf"};
  Uniform<float> alpha{table, "u_exactAlpha"};
};

class ExactTracer {
 public:
  static Result<ExactTracer> create();

  // Mesh `name`'s tree (level 0, object space); replaces the one it had.
  void setMesh(const std::string& name, std::shared_ptr<const MeshBvh> bvh);
  // The most levels of any mesh's tree held (for core/bvh.h traceStackFor; 1 with none).
  int deepestMesh() const;
  // The sky a ray that meets nothing sees (null: the clear colour). Returns "" or a message.
  std::string setSkybox(const CubeFaces* faces);
  // The frame's placement: the top level over `scene`'s objects placed by `plan`'s model
  // matrices, probe centres from `plan`, lit as seen from `eye`. Uploads the atlas first if a mesh
  // changed.
  void prepare(const Scene& scene, const FramePlan& plan, const glm::vec3& eye);
  // The error view's exact pass marks its pixels (alpha 0) while this is on.
  void setMark(bool on) { mark_ = on; }

  // For the environment program in use: the textures and the frame's uniforms; then, per draw,
  // which object it is (its rays never meet itself, and glass is crossed inside it) and the rays
  // a pixel of it traces in its lobe, if rough (FramePlan::lobeRaysOf; 1 in a capture).
  // `general`: the program's tracer (ProgramKey::traceGeneral); without it the rays walk the
  // Phong objects' top level alone (PackedScene::phongHeader).
  void bind(const ExactUniforms& u, bool general) const;
  void bindObject(const ExactUniforms& u, int object, int lobeRays) const;

 private:
  ExactTracer() = default;
  // Every mesh's tree, then `frameRows` rows for what prepare() writes each frame.
  void uploadAtlas(int frameRows);

  TextureHandle atlas_, normals_, scene_;
  std::unique_ptr<SkyboxPass> sky_;
  std::map<std::string, std::shared_ptr<const MeshBvh>> meshes_;
  std::map<std::string, BvhAtlas::Root> roots_;
  bool atlasDirty_ = true;
  int meshRows_ = 0;   // the atlas's rows of mesh trees
  int frameRows_ = 1;  // the rows after them, rewritten each frame

  PackedScene packed_;
  std::vector<float> lobeAlphas_;  // per object: ggxAlpha of its roughness (prepare)
  glm::vec3 clear_{0.0f}, light_{0.0f}, eye_{0.0f};
  float far_ = 100.0f;
  glm::vec4 phong_{0.0f};
  bool mark_ = false;
};

}  // namespace reflect
