#include "core/probe_layout.h"

namespace reflect {

int nearestProbe(const std::vector<ProbeLayout>& probes, const glm::vec3& point) {
  int nearest = -1;
  float best = 0.0f;
  for (size_t i = 0; i < probes.size(); ++i) {
    const glm::vec3 d = probes[i].centre - point;
    const float distance = glm::dot(d, d);
    if (nearest < 0 || distance < best) {
      nearest = static_cast<int>(i);
      best = distance;
    }
  }
  return nearest;
}

std::vector<ProbeLayout> layoutProbes(const std::vector<ProbeCandidate>& objects) {
  std::vector<ProbeLayout> probes;
  for (size_t i = 0; i < objects.size(); ++i) {
    const ProbeCandidate& o = objects[i];
    if (!o.probed) continue;
    ProbeLayout* shared = nullptr;
    if (o.group >= 0) {
      for (ProbeLayout& p : probes) {
        if (objects[static_cast<size_t>(p.reflector)].group == o.group) shared = &p;
      }
    }
    if (shared) {
      shared->members.push_back(static_cast<int>(i));
    } else {
      probes.push_back(ProbeLayout{static_cast<int>(i), {static_cast<int>(i)}, glm::vec3(0.0f)});
    }
  }
  for (ProbeLayout& p : probes) {
    const ProbeCandidate& owner = objects[static_cast<size_t>(p.reflector)];
    if (owner.centre) {
      p.centre = *owner.centre;
      continue;
    }
    Bounds joint = owner.worldBounds;
    for (int m : p.members) {
      const Bounds& b = objects[static_cast<size_t>(m)].worldBounds;
      joint = Bounds{glm::min(joint.min, b.min), glm::max(joint.max, b.max)};
    }
    p.centre = joint.centre();
  }
  return probes;
}

std::optional<glm::vec3> capturePoint(const std::optional<glm::vec3>& sceneCentre,
                                      bool captureAtOrigin) {
  if (captureAtOrigin) return glm::vec3(0.0f);  // where the course captures
  return sceneCentre;
}

Scene sceneAsCaptured(Scene scene, bool captureAtOrigin) {
  for (SceneObject& o : scene.objects) {
    if (o.needsLiveProbe()) o.probeCentre = capturePoint(o.probeCentre, captureAtOrigin);
  }
  return scene;
}

}  // namespace reflect
