// Each function mirrors shaders/shading.glsl's of the same name (see reference_shading.h).
#include "core/reference_shading.h"

#include <algorithm>
#include <cmath>

namespace reflect {

glm::vec3 phongShade(const glm::vec3& colour, const glm::vec3& p, const glm::vec3& n,
                     const glm::vec3& light, const glm::vec3& eye, const glm::vec4& terms) {
  return phongLit(colour, p, n, light, eye, glm::vec3(terms.x), terms);
}

glm::vec3 phongLit(const glm::vec3& colour, const glm::vec3& p, const glm::vec3& n,
                   const glm::vec3& light, const glm::vec3& eye, const glm::vec3& ambient,
                   const glm::vec4& terms) {
  const glm::vec3 l = glm::normalize(light - p);
  const glm::vec3 v = glm::normalize(eye - p);
  const float nDotL = std::max(glm::dot(n, l), 0.0f);
  glm::vec3 c = colour * (ambient + terms.y * nDotL);
  if (nDotL > 0.0f) {
    const glm::vec3 r = glm::reflect(-l, n);
    c += glm::vec3(terms.z * std::pow(std::clamp(glm::dot(r, v), 0.0f, 1.0f), terms.w));
  }
  return c;
}

float schlickWeight(float f0, const glm::vec3& toViewer, const glm::vec3& normal) {
  return f0 +
         (1.0f - f0) * std::pow(1.0f - std::clamp(glm::dot(toViewer, normal), 0.0f, 1.0f), 5.0f);
}

glm::vec3 blended(const Blend& b, const glm::vec3& seen) {
  return b.add + b.weight * seen;
}

Blend courseMix(const glm::vec3& colour, float reflectionWeight, float baseWeight) {
  return Blend{baseWeight * colour, reflectionWeight};
}

Blend mirrorBlend(const glm::vec3& colour, float reflectionWeight, float baseWeight, bool fresnel,
                  float schlick) {
  if (fresnel) return Blend{(1.0f - schlick) * colour, schlick};
  return courseMix(colour, reflectionWeight, baseWeight);
}

Blend glassBlend(const glm::vec3& colour, const glm::vec3& reflected, bool total,
                 float reflectionWeight, float baseWeight, bool fresnel, float schlick) {
  if (!fresnel) return courseMix(colour, reflectionWeight, baseWeight);
  if (total) return Blend{glm::vec3(0.0f), 1.0f};
  return Blend{schlick * reflected, 1.0f - schlick};
}

}  // namespace reflect
