#include "gfx/exact_tracer.h"

#include <algorithm>
#include <functional>
#include <glm/gtc/matrix_inverse.hpp>

#include "core/frustum.h"
#include "core/ggx.h"

namespace reflect {
namespace {

int rowsFor(size_t texels) {
  return static_cast<int>((texels + kBvhTextureWidth - 1) / static_cast<size_t>(kBvhTextureWidth));
}

// RGBA32F texels, kBvhTextureWidth a row, `rows` rows (at least one, so every sampler has a
// texture); `texels` fill the first rows, the rest are zero.
void allocateTexels(GLuint texture, const std::vector<float>& texels, int rows) {
  rows = std::max({rows, rowsFor(texels.size() / 4), 1});
  std::vector<float> padded(static_cast<size_t>(rows) * kBvhTextureWidth * 4, 0.0f);
  std::copy(texels.begin(), texels.end(), padded.begin());
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kBvhTextureWidth, rows, 0, GL_RGBA, GL_FLOAT,
               padded.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
}

// A texture of `rows` rows filled a block of rows at a time by `write(firstTexel, texels, out)`,
// so no copy of the whole atlas is ever held (WebAssembly's heap keeps its largest size).
void allocateRows(GLuint texture, int rows,
                  const std::function<void(size_t, size_t, float*)>& write) {
  constexpr int kBlockRows = 64;
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kBvhTextureWidth, rows, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  std::vector<float> block(static_cast<size_t>(kBlockRows) * kBvhTextureWidth * 4);
  for (int row = 0; row < rows; row += kBlockRows) {
    const int count = std::min(kBlockRows, rows - row);
    write(static_cast<size_t>(row) * kBvhTextureWidth,
          static_cast<size_t>(count) * kBvhTextureWidth, block.data());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, row, kBvhTextureWidth, count, GL_RGBA, GL_FLOAT,
                    block.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
}

// Rewrites whole rows from `firstRow` on with `texels` (zero past their end).
void replaceRows(GLuint texture, int firstRow, const std::vector<float>& texels) {
  const int rows = std::max(rowsFor(texels.size() / 4), 1);
  std::vector<float> padded(static_cast<size_t>(rows) * kBvhTextureWidth * 4, 0.0f);
  std::copy(texels.begin(), texels.end(), padded.begin());
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, firstRow, kBvhTextureWidth, rows, GL_RGBA, GL_FLOAT,
                  padded.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

void bindUnit(GLint unit, GLenum target, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target, texture);
}

}  // namespace

Result<ExactTracer> ExactTracer::create() {
  ExactTracer t;
  t.atlas_ = TextureHandle(genTexture());
  t.normals_ = TextureHandle(genTexture());
  t.scene_ = TextureHandle(genTexture());
  allocateTexels(t.scene_.id(), {}, 1);
  t.uploadAtlas(1);
  if (!checkGlError("create exact tracer")) {
    return Result<ExactTracer>::failure("GL error while creating the exact mode's textures");
  }
  return t;
}

void ExactTracer::setMesh(const std::string& name, std::shared_ptr<const MeshBvh> bvh) {
  meshes_[name] = std::move(bvh);
  atlasDirty_ = true;
}

int ExactTracer::deepestMesh() const {
  int deepest = 1;
  for (const auto& [name, bvh] : meshes_) {
    if (bvh) deepest = std::max(deepest, bvh->tree.depth);
  }
  return deepest;
}

std::string ExactTracer::setSkybox(const CubeFaces* faces) {
  sky_.reset();
  if (!faces) return {};
  Result<SkyboxPass> pass = SkyboxPass::create(*faces);
  if (!pass) return pass.error();
  sky_ = std::make_unique<SkyboxPass>(pass.take());
  return {};
}

void ExactTracer::uploadAtlas(int frameRows) {
  BvhAtlas atlas;
  for (const auto& [name, bvh] : meshes_) atlas.add(name, bvh);
  // The meshes' rows, then the rows each frame rewrites (the top level and the placements).
  meshRows_ = rowsFor(atlas.texelCount());
  frameRows_ = std::max(frameRows, 1);
  allocateRows(atlas_.id(), meshRows_ + frameRows_, [&](size_t first, size_t count, float* out) {
    atlas.writeTexels(first, count, out);
  });
  allocateRows(
      normals_.id(), std::max(rowsFor(atlas.normalTexelCount()), 1),
      [&](size_t first, size_t count, float* out) { atlas.writeNormals(first, count, out); });
  roots_ = atlas.roots();
  atlasDirty_ = false;
}

void ExactTracer::prepare(const Scene& scene, const FramePlan& plan, const glm::vec3& eye) {
  if (atlasDirty_) uploadAtlas(frameRows_);
  std::vector<BvhInstance> instances(scene.objects.size());
  std::vector<PackedRef> roots(scene.objects.size(), PackedRef{-1, 0});
  std::vector<glm::vec3> centres(scene.objects.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    BvhInstance& instance = instances[i];
    instance.model = plan.modelOf(static_cast<int>(i));
    instance.inverse = glm::inverse(instance.model);
    auto mesh = meshes_.find(o.mesh);
    auto root = roots_.find(o.mesh);
    if (mesh != meshes_.end() && mesh->second && !mesh->second->tree.nodes.empty() &&
        root != roots_.end()) {
      instance.mesh = mesh->second;
      roots[i] = root->second.ref;
      centres[i] = transformBounds(root->second.box, instance.model).centre();
    }
    if (const ProbeLayout* probe = plan.layoutOf(static_cast<int>(i))) centres[i] = probe->centre;
  }
  const SceneBvh bvh = buildSceneBvh(std::move(instances));
  packed_ = packScene(scene, bvh, roots, centres, meshRows_ * kBvhTextureWidth);
  const int needed = rowsFor(packed_.traversal.size() / 4);
  if (needed > frameRows_) uploadAtlas(2 * needed);  // the mesh rows stay where they are
  replaceRows(atlas_.id(), meshRows_, packed_.traversal);
  allocateTexels(scene_.id(), packed_.shading, 1);
  clear_ = scene.clearColour;
  far_ = scene.capture.far;
  light_ = scene.light.position;
  phong_ = {scene.light.ambient, scene.light.diffuse, scene.light.specular, scene.light.shininess};
  eye_ = eye;
  lobeAlphas_.clear();
  for (const SceneObject& o : scene.objects) lobeAlphas_.push_back(ggxAlpha(o.roughness));
}

void ExactTracer::bind(const ExactUniforms& u, bool general) const {
  bindUnit(kExactAtlasUnit, GL_TEXTURE_2D, atlas_.id());
  bindUnit(kExactNormalsUnit, GL_TEXTURE_2D, normals_.id());
  bindUnit(kExactSceneUnit, GL_TEXTURE_2D, scene_.id());
  bindUnit(kExactSkyUnit, GL_TEXTURE_CUBE_MAP, sky_ ? sky_->texture() : 0);
  glActiveTexture(GL_TEXTURE0);
  u.atlas.set(kExactAtlasUnit);
  u.normals.set(kExactNormalsUnit);
  u.scene.set(kExactSceneUnit);
  u.sky.set(kExactSkyUnit);
  u.hasSky.set(sky_ != nullptr);
  u.clear.set(clear_);
  u.header.set(general ? packed_.header : packed_.phongHeader);
  u.empty.set(general ? packed_.empty : packed_.phongEmpty);
  u.light.set(light_);
  u.phong.set(phong_);
  u.eye.set(eye_);
  u.far.set(far_);
  u.mark.set(mark_);
}

void ExactTracer::bindObject(const ExactUniforms& u, int object, int lobeRays) const {
  u.self.set(object);
  u.lobeRays.set(lobeRays);  // rough mirrors' programs (ROUGH 1) alone
  const size_t i = static_cast<size_t>(object);
  u.alpha.set(i < lobeAlphas_.size() ? lobeAlphas_[i] : 0.0f);
}

}  // namespace reflect
