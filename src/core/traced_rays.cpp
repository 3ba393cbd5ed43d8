#include "core/traced_rays.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "core/frustum.h"

namespace reflect {
namespace {

// What a path's walk needs besides the ray.
struct Walk {
  const Scene& scene;
  const SceneBvh& placed;
  std::vector<glm::vec3> centres;  // per object: where the far test measures from
};

// Each object's centre as the tracer's scene texture holds it for a reflector without a probe
// (gfx/exact_tracer.cpp: its tree's root box placed in the world). A probed reflector's is its
// probe's centre there; it only moves the far test, which nothing within 100 units reaches.
std::vector<glm::vec3> objectCentres(const SceneBvh& placed) {
  std::vector<glm::vec3> centres(placed.instances.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < placed.instances.size(); ++i) {
    const BvhInstance& instance = placed.instances[i];
    if (!instance.mesh || instance.mesh->tree.nodes.empty()) continue;
    const BvhNode& root = instance.mesh->tree.nodes[0];
    centres[i] = transformBounds(Bounds{root.min, root.max}, instance.model).centre();
  }
  return centres;
}

// exact_shade.glsl's exactBeyondFar: the world a reflector sees ends at its capture's far planes.
bool beyondFar(const Walk& walk, const SurfacePoint& met, int leaving) {
  const glm::vec3 away = glm::abs(met.position - walk.centres[static_cast<size_t>(leaving)]);
  return std::max({away.x, away.y, away.z}) > walk.scene.capture.far;
}

// The rays cast from mirror surface `surface`, met along `incoming` (unit): its reflected ray and
// every ray followed after it (exactRadiance's loop). nullopt: the path meets a surface this
// count does not follow.
std::optional<int> raysFrom(const Walk& walk, SurfacePoint surface, glm::vec3 incoming) {
  for (int rays = 1;; ++rays) {
    const TraceRay ray{surface.position, glm::reflect(incoming, surface.normal)};
    const SurfacePoint met = firstSurface(walk.placed, ray, 0.0f, surface.object);
    if (met.object < 0 || beyondFar(walk, met, surface.object)) return rays;  // the sky
    const SceneObject& object = walk.scene.objects[static_cast<size_t>(met.object)];
    if (object.material == Material::Phong) return rays;  // shaded where it lands
    // This ray has left `rays` surfaces: past kMaxBounces it shows the background instead.
    if (rays > kMaxBounces) return rays;
    if (object.material != Material::Mirror) return std::nullopt;
    surface = met;
    incoming = ray.direction;
  }
}

}  // namespace

TracedRayCount countTracedRays(const Scene& scene, double seconds, const MeshTreeLookup& trees,
                               const LookCamera& camera, int width, int height,
                               const TracedObject& traced) {
  const SceneBvh placed = placeScene(scene, seconds, trees);
  const Walk walk{scene, placed, objectCentres(placed)};
  TracedRayCount count;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::optional<TraceRay> view = pixelRay(camera, x, y, width, height);
      if (!view) continue;
      const SurfacePoint surface = firstSurface(placed, *view);
      if (surface.object < 0) continue;
      const SceneObject& object = scene.objects[static_cast<size_t>(surface.object)];
      if (!object.usesEnvironment() || !traced(surface.object)) continue;
      const std::optional<int> rays = object.material == Material::Mirror && !object.rough()
                                          ? raysFrom(walk, surface, view->direction)
                                          : std::nullopt;
      if (!rays) {
        ++count.unmodelled;
        continue;
      }
      ++count.mirrorPixels;
      count.rays += *rays;
      ++count.pixelsWithRays[static_cast<size_t>(*rays)];
    }
  }
  return count;
}

}  // namespace reflect
