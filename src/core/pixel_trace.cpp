#include "core/pixel_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/glass_crossing.h"
#include "core/normal_matrix.h"
#include "core/trace_limits.h"

namespace reflect {

std::optional<TraceRay> pixelRay(const LookCamera& camera, int x, int y, int width, int height) {
  if (width < 1 || height < 1 || x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
  const glm::mat4 viewProj =
      camera.projection(static_cast<float>(width) / static_cast<float>(height)) * camera.view();
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProj));
  // GL's window y counts from the bottom, the image's rows from the top.
  const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
  const double ndcY = 1.0 - (y + 0.5) / height * 2.0;
  const glm::dvec4 nearPoint = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
  const glm::dvec4 farPoint = inverse * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  const glm::dvec3 from = glm::dvec3(nearPoint) / nearPoint.w;
  const glm::dvec3 to = glm::dvec3(farPoint) / farPoint.w;
  return TraceRay{glm::vec3(from), glm::vec3(glm::normalize(to - from))};
}

SceneBvh placeScene(const Scene& scene, double seconds, const MeshTreeLookup& trees) {
  std::vector<BvhInstance> instances;
  instances.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects) {
    BvhInstance instance;
    instance.mesh = trees(object.mesh);
    instance.model = scene.modelMatrix(object, seconds);
    instance.inverse = glm::inverse(instance.model);
    instances.push_back(std::move(instance));
  }
  return buildSceneBvh(std::move(instances));
}

SurfacePoint firstSurface(const SceneBvh& scene, const TraceRay& ray, float tMin, int skip,
                          int only) {
  const RayHit hit = intersectScene(scene, ray.origin, ray.direction, tMin,
                                    std::numeric_limits<float>::infinity(), skip, only);
  SurfacePoint s;
  if (hit.instance < 0) return s;
  const BvhInstance& instance = scene.instances[static_cast<size_t>(hit.instance)];
  const MeshBvh& mesh = *instance.mesh;
  const size_t slot = static_cast<size_t>(hit.slot);
  // The normal as the rasteriser interpolates it: barycentric over the corners' vertex normals.
  const glm::vec3 local = (1.0f - hit.u - hit.v) * mesh.corner(slot, 0).normal +
                          hit.u * mesh.corner(slot, 1).normal + hit.v * mesh.corner(slot, 2).normal;
  s.object = hit.instance;
  s.t = hit.t;
  s.position = ray.origin + hit.t * ray.direction;
  const glm::mat3 normals = normalMatrixOf(glm::mat3(instance.model));
  s.normal = glm::normalize(normals * local);
  for (int k = 0; k < 3; ++k) {
    const Vertex& v = mesh.corner(slot, k);
    s.cornerPositions[static_cast<size_t>(k)] =
        glm::vec3(instance.model * glm::vec4(v.position, 1));
    s.cornerNormals[static_cast<size_t>(k)] = glm::normalize(normals * v.normal);
  }
  s.weights = glm::vec3(1.0f - hit.u - hit.v, hit.u, hit.v);
  return s;
}

float selfEpsilon(const SceneBvh& scene, int object) {
  if (object < 0 || static_cast<size_t>(object) >= scene.instances.size()) return 1e-7f;
  const BvhInstance& instance = scene.instances[static_cast<size_t>(object)];
  if (!instance.mesh || instance.mesh->tree.nodes.empty()) return 1e-7f;
  const BvhNode& root = instance.mesh->tree.nodes[0];
  glm::vec3 lo(std::numeric_limits<float>::infinity());
  glm::vec3 hi(-std::numeric_limits<float>::infinity());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? root.max.x : root.min.x,
                      (corner & 2) ? root.max.y : root.min.y,
                      (corner & 4) ? root.max.z : root.min.z);
    const glm::vec3 world(instance.model * glm::vec4(p, 1.0f));
    lo = glm::min(lo, world);
    hi = glm::max(hi, world);
  }
  return std::max(1e-5f * glm::length(hi - lo), 1e-7f);
}

GlassRoute followGlass(const SceneBvh& scene, const SurfacePoint& entry, const glm::vec3& incoming,
                       float ior, bool twoSurfaces) {
  GlassRoute path;
  const glm::vec3 refracted = glm::refract(incoming, entry.normal, 1.0f / ior);
  path.exitPoint = entry.position;
  if (glm::dot(refracted, refracted) == 0.0f) {
    // Past the critical angle: the view ray is reflected and nothing enters.
    path.totalAtEntry = true;
    path.leaving = glm::reflect(incoming, entry.normal);
    return path;
  }
  path.inside = glm::normalize(refracted);
  path.leaving = path.inside;
  if (!twoSurfaces) return path;
  const float epsilon = selfEpsilon(scene, entry.object);
  const GlassCrossing crossing = crossGlassInterior(
      entry.position, path.inside, ior, [&](const glm::vec3& from, const glm::vec3& dir) {
        const SurfacePoint far = firstSurface(scene, {from, dir}, epsilon, -1, entry.object);
        return FarSurface{far.object >= 0, far.position, far.normal};
      });
  path.exitPoint = crossing.point;
  path.leaving = crossing.direction;
  path.exited = crossing.exited;
  path.internalReflections = crossing.internalReflections;
  return path;
}

double angleDegrees(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 u = glm::normalize(glm::dvec3(a));
  const glm::dvec3 v = glm::normalize(glm::dvec3(b));
  // atan2 of |u x v| and u.v: accurate at small angles, where acos of the dot product is not.
  return glm::degrees(std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v)));
}

}  // namespace reflect
