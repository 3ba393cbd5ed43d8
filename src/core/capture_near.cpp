#include "core/capture_near.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/frustum.h"

namespace reflect {

namespace {

std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", static_cast<double>(value));
  return text;
}

}  // namespace

std::string captureNearNotice(const Scene& scene, const MeshBoundsLookup& boundsOf) {
  std::vector<size_t> outside;
  std::vector<std::string> meshes;
  float nearest = scene.capture.near;  // the nearest side of their boxes to their centres
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const bool reflector = o.material == Material::Mirror || o.material == Material::Glass;
    // A shared probe, or one at a point the file sets, is not at the object's centre; a figure
    // lit by a probe of its own ("own-probe") has one there.
    const bool ownProbe = reflector && o.needsLiveProbe() && o.probeGroup < 0 && !o.probeCentre;
    if (!ownProbe && !o.ownsLightProbe()) continue;
    const Bounds* local = boundsOf(o.mesh);
    if (!local) continue;
    const Bounds world = transformBounds(*local, scene.modelMatrix(o, 0.0));
    const glm::vec3 half = 0.5f * (world.max - world.min);
    const float inside = std::min({half.x, half.y, half.z});
    if (inside >= scene.capture.near) continue;
    outside.push_back(i);
    if (std::find(meshes.begin(), meshes.end(), o.mesh) == meshes.end()) meshes.push_back(o.mesh);
    nearest = std::min(nearest, inside);
  }
  if (outside.empty()) return {};
  std::string list;
  for (size_t k = 0; k < outside.size(); ++k) {
    list += (k == 0 ? "" : k + 1 == outside.size() ? " and " : ", ") + std::to_string(outside[k]);
  }
  std::string names;
  for (const std::string& m : meshes) names += (names.empty() ? "" : ", ") + m;
  const bool one = outside.size() == 1;
  return scene.name + ": capture.near " + number(scene.capture.near) + " lies outside object" +
         (one ? " " : "s ") + list + " (" + names + "), whose box" +
         (one ? " reaches" : "es reach") + " as near as " + number(nearest) + " to " +
         (one ? "its centre" : "their centres") +
         ": a probe's captures leave out what passes nearer its centre than the near plane; "
         "set capture.near to at most " +
         number(nearest);
}

}  // namespace reflect
