#include "gfx/exact_tracer.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>

#include "core/frustum.h"

namespace reflect {
namespace {

// RGBA32F texels, kBvhTextureWidth a row (at least one row, so every sampler has a texture).
int uploadTexels(GLuint texture, const std::vector<float>& texels) {
  const size_t count = texels.size() / 4;
  const int rows = static_cast<int>(
      std::max<size_t>(1, (count + kBvhTextureWidth - 1) / static_cast<size_t>(kBvhTextureWidth)));
  std::vector<float> padded(static_cast<size_t>(rows) * kBvhTextureWidth * 4, 0.0f);
  std::copy(texels.begin(), texels.end(), padded.begin());
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kBvhTextureWidth, rows, 0, GL_RGBA, GL_FLOAT,
               padded.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  return rows;
}

void bindUnit(GLint unit, GLenum target, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target, texture);
}

}  // namespace

Result<ExactTracer> ExactTracer::create() {
  ExactTracer t;
  t.nodes_ = TextureHandle(genTexture());
  t.positions_ = TextureHandle(genTexture());
  t.normals_ = TextureHandle(genTexture());
  t.scene_ = TextureHandle(genTexture());
  uploadTexels(t.scene_.id(), {});
  t.uploadAtlas();
  if (!checkGlError("create exact tracer")) {
    return Result<ExactTracer>::failure("GL error while creating the exact mode's textures");
  }
  return t;
}

void ExactTracer::setMesh(const std::string& name, std::shared_ptr<const MeshBvh> bvh) {
  meshes_[name] = std::move(bvh);
  atlasDirty_ = true;
}

std::string ExactTracer::setSkybox(const CubeFaces* faces) {
  sky_.reset();
  if (!faces) return {};
  Result<SkyboxPass> pass = SkyboxPass::create(*faces);
  if (!pass) return pass.error();
  sky_ = std::make_unique<SkyboxPass>(pass.take());
  return {};
}

void ExactTracer::uploadAtlas() {
  BvhAtlas atlas;
  for (const auto& [name, bvh] : meshes_) {
    if (bvh) atlas.add(name, *bvh);
  }
  uploadTexels(nodes_.id(), atlas.nodes);
  uploadTexels(positions_.id(), atlas.positions);
  uploadTexels(normals_.id(), atlas.normals);
  roots_ = std::move(atlas.roots);
  atlasDirty_ = false;
}

void ExactTracer::prepare(const Scene& scene, double seconds, const FramePlan& plan,
                          const glm::vec3& eye) {
  if (atlasDirty_) uploadAtlas();
  std::vector<BvhInstance> instances(scene.objects.size());
  std::vector<int> roots(scene.objects.size(), -1);
  std::vector<glm::vec3> centres(scene.objects.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    BvhInstance& instance = instances[i];
    instance.model = scene.modelMatrix(o, seconds);
    instance.inverse = glm::inverse(instance.model);
    auto mesh = meshes_.find(o.mesh);
    auto root = roots_.find(o.mesh);
    if (mesh != meshes_.end() && mesh->second && !mesh->second->tree.nodes.empty() &&
        root != roots_.end()) {
      instance.mesh = mesh->second;
      roots[i] = static_cast<int>(root->second);
      const BvhNode& box = mesh->second->tree.nodes[0];
      centres[i] = transformBounds({box.min, box.max}, instance.model).centre();
    }
    if (const ProbePlan* probe = plan.probeOf(static_cast<int>(i))) centres[i] = probe->centre;
  }
  const SceneBvh bvh = buildSceneBvh(std::move(instances));
  packed_ = packScene(scene, bvh, roots, centres);
  sceneRows_ = uploadTexels(scene_.id(), packed_.texels);
  clear_ = scene.clearColour;
  light_ = scene.light.position;
  phong_ = {scene.light.ambient, scene.light.diffuse, scene.light.specular, scene.light.shininess};
  eye_ = eye;
}

void ExactTracer::bind(GLuint program) const {
  bindUnit(kExactNodesUnit, GL_TEXTURE_2D, nodes_.id());
  bindUnit(kExactPositionsUnit, GL_TEXTURE_2D, positions_.id());
  bindUnit(kExactNormalsUnit, GL_TEXTURE_2D, normals_.id());
  bindUnit(kExactSceneUnit, GL_TEXTURE_2D, scene_.id());
  bindUnit(kExactSkyUnit, GL_TEXTURE_CUBE_MAP, sky_ ? sky_->texture() : 0);
  glActiveTexture(GL_TEXTURE0);
  const auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
  glUniform1i(at("u_exactNodes"), kExactNodesUnit);
  glUniform1i(at("u_exactPositions"), kExactPositionsUnit);
  glUniform1i(at("u_exactNormals"), kExactNormalsUnit);
  glUniform1i(at("u_exactScene"), kExactSceneUnit);
  glUniform1i(at("u_exactSky"), kExactSkyUnit);
  glUniform1i(at("u_exactHasSky"), sky_ ? 1 : 0);
  glUniform3f(at("u_exactClear"), clear_.r, clear_.g, clear_.b);
  glUniform1i(at("u_exactTopNodes"), packed_.topNodes);
  glUniform1i(at("u_exactTopOrder"), packed_.topOrder);
  glUniform1i(at("u_exactEmpty"), packed_.empty ? 1 : 0);
  glUniform3f(at("u_exactLight"), light_.x, light_.y, light_.z);
  glUniform4f(at("u_exactPhong"), phong_.x, phong_.y, phong_.z, phong_.w);
  glUniform3f(at("u_exactEye"), eye_.x, eye_.y, eye_.z);
  glUniform1i(at("u_exactMark"), mark_ ? 1 : 0);
}

void ExactTracer::bindObject(GLuint program, int object) const {
  glUniform1i(glGetUniformLocation(program, "u_exactSelf"), object);
}

void ExactTracer::abandon() {
  nodes_.abandon();
  positions_.abandon();
  normals_.abandon();
  scene_.abandon();
  if (sky_) sky_->abandon();
  sky_.reset();
}

}  // namespace reflect
