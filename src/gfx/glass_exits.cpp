#include "gfx/glass_exits.h"

#include "gfx/scene_renderer_detail.h"

namespace reflect {
using renderer_detail::sphereRadiusIn;

namespace {

const MeshBuffer* fullDetail(const MeshBuffers* meshes, const std::string& name) {
  return meshes ? meshes->find(name, 0) : nullptr;
}

}  // namespace

void GlassExits::update(const Scene& scene, const FramePlan& plan, const MeshBuffers* meshes,
                        const AccuracySettings& accuracy) {
  for (const SceneObject& object : scene.objects) {
    if (object.material != Material::Glass) continue;
    const uint64_t serial = meshes ? meshes->serial(object.mesh) : 0;
    uint64_t& seen = serials_[object.mesh];
    if (seen != serial) maps_.forget(object.mesh);
    seen = serial;
  }
  if (accuracy.glassSurfaces != 2 || accuracy.search == Search::Exact) return;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    if (object.material != Material::Glass) continue;
    const MeshBuffer* full = fullDetail(meshes, object.mesh);
    if (!full || sphereRadiusIn(full, plan.modelOf(static_cast<int>(i))) > 0.0f) {
      continue;  // no mesh yet, or a sphere: its exit has a closed form
    }
    maps_.mapFor(object.mesh, *full);
  }
}

const GlassInteriorMap* GlassExits::exitOf(const SceneObject& object, const glm::mat4& model,
                                           const MeshBuffers* meshes,
                                           const AccuracySettings& accuracy) const {
  if (accuracy.glassSurfaces != 2 || object.material != Material::Glass) return nullptr;
  const MeshBuffer* full = fullDetail(meshes, object.mesh);
  if (!full || sphereRadiusIn(full, model) > 0.0f) return nullptr;
  return maps_.find(object.mesh);
}

}  // namespace reflect
