// Where glass leaves: the interior maps (glass_interior_map.h) of the glass meshes that are not
// spheres, made the first time a pass needs them and dropped when their mesh is replaced. A
// sphere (uniformly scaled) needs none: its far side has a closed form. One job: the renderer's
// draws ask it which map, if any, an object leaves through.
#pragma once

#include <map>
#include <string>

#include <glm/glm.hpp>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/scene.h"
#include "gfx/glass_interior_map.h"
#include "gfx/mesh_buffer.h"

namespace reflect {

class GlassExits {
 public:
  // Before a pass: forgets the maps of meshes replaced since they were made, then makes those the
  // scene's glass needs (glassSurfaces 2, a captured or searched lookup; the exact tracer follows
  // the mesh itself).
  void update(const Scene& scene, const FramePlan& plan, const MeshBuffers* meshes,
              const AccuracySettings& accuracy);
  // The map `object`, placed by `model`, leaves through (nullptr: a sphere, no glass, one
  // surface, or no map).
  const GlassInteriorMap* exitOf(const SceneObject& object, const glm::mat4& model,
                                 const MeshBuffers* meshes, const AccuracySettings& accuracy) const;
  // Maps made so far (one per non-sphere glass mesh in use), for tests.
  size_t count() const { return maps_.count(); }

 private:
  GlassInteriorMaps maps_;
  std::map<std::string, uint64_t> serials_;  // each glass mesh's serial when last seen
};

}  // namespace reflect
