// The shading terms of shaders/shading.glsl in C++, for the reference and for pick a pixel's exact
// colour (app/pixel_explain.h; here in core so the page has it too): each function here is the
// GLSL function of the same name, term by term and in the same order, so that the reference and
// the raster shade what they meet alike (tests/reference/shading_equivalence_test.cpp runs both
// on the same inputs and holds them equal). A change to one is a change to the other.
#pragma once

#include <glm/glm.hpp>

#include "core/fresnel.h"  // fresnelF0: shading.glsl's fresnelF0, the renderer's u_fresnelF0

namespace reflect {

// shading.glsl's phongLit: colour * (ambient + diffuse max(N.L, 0)) + (N.L > 0 ? specular
// pow(clamp(R.V, 0, 1), shininess) : 0), `ambient` per channel. `terms` = (ambient (unused),
// diffuse, specular, shininess).
glm::vec3 phongLit(const glm::vec3& colour, const glm::vec3& p, const glm::vec3& n,
                   const glm::vec3& light, const glm::vec3& eye, const glm::vec3& ambient,
                   const glm::vec4& terms);

// shading.glsl's phongShade: phongLit with the constant ambient terms.x.
glm::vec3 phongShade(const glm::vec3& colour, const glm::vec3& p, const glm::vec3& n,
                     const glm::vec3& light, const glm::vec3& eye, const glm::vec4& terms);

// shading.glsl's schlickWeight: F0 + (1 - F0) (1 - clamp(V.N, 0, 1))^5.
float schlickWeight(float f0, const glm::vec3& toViewer, const glm::vec3& normal);

// shading.glsl's Blend: a reflector's colour is add + weight * what its ray sees.
struct Blend {
  glm::vec3 add{0.0f};
  float weight = 1.0f;
};

glm::vec3 blended(const Blend& b, const glm::vec3& seen);

// shading.glsl's courseMix: reflectionWeight x seen + baseWeight x colour.
Blend courseMix(const glm::vec3& colour, float reflectionWeight, float baseWeight);

// shading.glsl's mirrorBlend: with Fresnel mix(colour, seen, schlick), else the course's mix.
Blend mirrorBlend(const glm::vec3& colour, float reflectionWeight, float baseWeight, bool fresnel,
                  float schlick);

// shading.glsl's glassBlend, applied to what the refracted ray sees (the reflected ray's, at
// total internal reflection): with Fresnel mix(refracted, reflected, schlick), or all of the
// reflection where it is total; else the course's mix.
Blend glassBlend(const glm::vec3& colour, const glm::vec3& reflected, bool total,
                 float reflectionWeight, float baseWeight, bool fresnel, float schlick);

}  // namespace reflect
