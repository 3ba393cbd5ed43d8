// The reference's Embree scene (embree_scene.h).
#include "reference/embree_scene.h"

#include <algorithm>

#include "core/frustum.h"
#include "core/normal_matrix.h"

namespace reflect {
namespace {

void onEmbreeError(void* user, RTCError code, const char* message) {
  auto* log = static_cast<EmbreeErrors*>(user);
  std::lock_guard<std::mutex> lock(log->mutex);
  if (log->first.empty()) {
    log->first = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                 (message ? message : "(no message)");
  }
}

}  // namespace

Result<WorldMesh> placeMesh(const MeshData& mesh, const glm::mat4& model, bool objectPositions) {
  for (uint32_t index : mesh.indices) {
    if (index >= mesh.vertices.size()) {
      return Result<WorldMesh>::failure("reference: mesh " + mesh.name +
                                        " has an index out of range");
    }
  }
  const glm::mat3 normalMatrix = normalMatrixOf(glm::mat3(model));
  WorldMesh w;
  w.indices = &mesh.indices;
  w.positions.reserve(mesh.vertices.size());
  w.normals.reserve(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) {
    w.positions.push_back(glm::vec3(model * glm::vec4(v.position, 1.0f)));
    w.normals.push_back(normalMatrix * v.normal);
    if (objectPositions) w.objectPositions.push_back(v.position);
  }
  const Bounds world = transformBounds(mesh.bounds, model);
  w.selfEpsilon = std::max(1e-5f * glm::length(world.max - world.min), 1e-7f);
  return w;
}

EmbreeWorld::~EmbreeWorld() {
  for (RTCScene s : scenes_) rtcReleaseScene(s);
  if (device_) rtcReleaseDevice(device_);
}

std::string EmbreeWorld::build(const std::vector<WorldMesh>& meshes,
                               const std::vector<int>& reflectors, const std::vector<int>& glass) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) return "Embree: rtcNewDevice failed";
  rtcSetDeviceErrorFunction(device_, onEmbreeError, &errors_);
  all_ = newScene(meshes, [](int) { return true; });
  for (int r : reflectors) excluding_[r] = newScene(meshes, [r](int i) { return i != r; });
  for (int g : glass) only_[g] = newScene(meshes, [g](int i) { return i == g; });
  return error();
}

std::string EmbreeWorld::error() {
  std::lock_guard<std::mutex> lock(errors_.mutex);
  return errors_.first;
}

RTCScene EmbreeWorld::excluding(int object) const {
  auto it = excluding_.find(object);
  return it == excluding_.end() ? all_ : it->second;
}

RTCScene EmbreeWorld::only(int object) const {
  auto it = only_.find(object);
  return it == only_.end() ? nullptr : it->second;
}

template <typename Keep>
RTCScene EmbreeWorld::newScene(const std::vector<WorldMesh>& meshes, Keep keep) {
  RTCScene scene = rtcNewScene(device_);
  scenes_.push_back(scene);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < meshes.size(); ++i) {
    if (!keep(static_cast<int>(i))) continue;
    const WorldMesh& m = meshes[i];
    const size_t triangles = m.indices->size() / 3;
    if (triangles == 0) continue;
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // New (Embree-owned, padded) buffers rather than shared ones: Embree may read past the
    // last vertex with 16-byte loads.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(float) * 3, m.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uint32_t) * 3, triangles));
    if (vertices && indices) {
      for (size_t v = 0; v < m.positions.size(); ++v) {
        vertices[v * 3 + 0] = m.positions[v].x;
        vertices[v * 3 + 1] = m.positions[v].y;
        vertices[v * 3 + 2] = m.positions[v].z;
      }
      std::copy(m.indices->begin(), m.indices->begin() + static_cast<std::ptrdiff_t>(triangles * 3),
                indices);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, static_cast<unsigned>(i));
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene);
  return scene;
}

// The first surface along org + t dir for t in [tnear, tfar].
Hit trace(RTCScene scene, const std::vector<WorldMesh>& meshes, const glm::vec3& org,
          const glm::vec3& dir, float tnear, float tfar) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = org.x;
  rh.ray.org_y = org.y;
  rh.ray.org_z = org.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.time = 0.0f;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.object = static_cast<int>(rh.hit.geomID);
  const WorldMesh& m = meshes[rh.hit.geomID];
  const uint32_t* tri = m.indices->data() + static_cast<size_t>(rh.hit.primID) * 3;
  // Embree's barycentrics: p = (1 - u - v) p0 + u p1 + v p2, what the rasteriser interpolates.
  const float u = rh.hit.u;
  const float v = rh.hit.v;
  const float w = 1.0f - u - v;
  hit.position = w * m.positions[tri[0]] + u * m.positions[tri[1]] + v * m.positions[tri[2]];
  hit.normal =
      glm::normalize(w * m.normals[tri[0]] + u * m.normals[tri[1]] + v * m.normals[tri[2]]);
  if (!m.objectPositions.empty()) {
    hit.objectPosition = w * m.objectPositions[tri[0]] + u * m.objectPositions[tri[1]] +
                         v * m.objectPositions[tri[2]];
  }
  return hit;
}

}  // namespace reflect
