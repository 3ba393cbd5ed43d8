#include "reference/ray_query.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <string>

namespace reflect {

Result<std::vector<QueryHit>> embreeFirstHits(const Scene& scene, const MeshLookup& meshes,
                                              double seconds, const std::vector<QueryRay>& rays) {
  using Out = Result<std::vector<QueryHit>>;
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return Out::failure("Embree: rtcNewDevice failed");
  RTCScene world = rtcNewScene(device);
  rtcSetSceneFlags(world, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(world, RTC_BUILD_QUALITY_HIGH);
  std::string error;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const MeshData* mesh = meshes(scene.objects[i].mesh);
    if (!mesh) {
      error = "mesh " + scene.objects[i].mesh + " is not loaded";
      break;
    }
    const size_t triangles = mesh->triangleCount();
    if (triangles == 0) continue;
    const glm::mat4 model = scene.modelMatrix(scene.objects[i], seconds);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(float) * 3, mesh->vertices.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uint32_t) * 3, triangles));
    for (size_t v = 0; v < mesh->vertices.size(); ++v) {
      const glm::vec3 p(model * glm::vec4(mesh->vertices[v].position, 1.0f));
      vertices[v * 3 + 0] = p.x;
      vertices[v * 3 + 1] = p.y;
      vertices[v * 3 + 2] = p.z;
    }
    std::copy(mesh->indices.begin(), mesh->indices.begin() + static_cast<long>(triangles * 3),
              indices);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(world, geometry, static_cast<unsigned>(i));
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(world);
  std::vector<QueryHit> hits;
  if (error.empty()) {
    hits.reserve(rays.size());
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (const QueryRay& ray : rays) {
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
      hits.push_back(hit);
    }
  }
  rtcReleaseScene(world);
  rtcReleaseDevice(device);
  if (!error.empty()) return Out::failure(error);
  return hits;
}

}  // namespace reflect
