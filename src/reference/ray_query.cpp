#include "reference/ray_query.h"

#include <limits>
#include <string>

#include "reference/embree_scene.h"

namespace reflect {
namespace {

// The first hit along `ray` in `world`: its object (the geometry's id is the object's index),
// triangle and distance.
QueryHit firstHit(RTCScene world, const QueryRay& ray) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = ray.tNear;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(world, &context, &rh);
  QueryHit hit;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.object = static_cast<int>(rh.hit.geomID);
    hit.triangle = static_cast<int>(rh.hit.primID);
    hit.t = rh.ray.tfar;
  }
  return hit;
}

}  // namespace

Result<std::vector<QueryHit>> embreeFirstHits(const Scene& scene, const MeshLookup& meshes,
                                              double seconds, const std::vector<QueryRay>& rays) {
  using Out = Result<std::vector<QueryHit>>;
  // The objects placed as the reference places them (embree_scene.h), in one world.
  std::vector<WorldMesh> placed;
  placed.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects) {
    const MeshData* mesh = meshes(object.mesh);
    if (!mesh) return Out::failure("mesh " + object.mesh + " is not loaded");
    Result<WorldMesh> world = placeMesh(*mesh, scene.modelMatrix(object, seconds), false);
    if (!world) return Out::failure(world.error());
    placed.push_back(world.take());
  }
  EmbreeWorld embree;
  const std::string error = embree.build(placed, {}, {});
  if (!error.empty()) return Out::failure(error);
  std::vector<QueryHit> hits;
  hits.reserve(rays.size());
  for (const QueryRay& ray : rays) hits.push_back(firstHit(embree.all(), ray));
  return hits;
}

}  // namespace reflect
