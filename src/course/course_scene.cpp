// Which scenes the course's frame (course_frame.cpp) can draw: the course's kind, and no other.
#include "course/course_frame.h"

namespace reflect {

std::string CourseFrame::whyNot(const Scene& scene) {
  if (!scene.skybox.empty()) return "the scene has a skybox";
  int mirrors = 0;
  for (const SceneObject& o : scene.objects) {
    if (o.probeLit()) return "an object takes its ambient light from the probe";
    if (o.material == Material::Phong) continue;
    if (o.material != Material::Mirror || !o.needsLiveProbe()) {
      return "not every reflector is a live-probe mirror";
    }
    if (o.fresnel || o.roughness > 0.0f) return "a mirror uses Fresnel or roughness";
    ++mirrors;
  }
  return mirrors == 1 ? "" : "the scene has " + std::to_string(mirrors) + " mirrors, not one";
}

}  // namespace reflect
