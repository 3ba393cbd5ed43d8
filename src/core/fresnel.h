// Schlick's F0 from a material's index of refraction, in one place for every C++ user: the
// renderer hands it to environment.frag (u_fresnelF0), and the reference shades with it
// (core/reference_shading.h). shaders/shading.glsl's fresnelF0() is the same expression,
// for the exact tracer, which reads each object's index from its scene texture.
#pragma once

#include <algorithm>

namespace reflect {

// Indices at or below 0 are held at 1e-3 (a scene file may say anything; the shaders divide by
// the index).
inline float clampedIor(float ior) {
  return std::max(ior, 1e-3f);
}

// ((n - 1) / (n + 1))^2: the share reflected at normal incidence.
inline float fresnelF0(float ior) {
  const float n = clampedIor(ior);
  return ((n - 1.0f) / (n + 1.0f)) * ((n - 1.0f) / (n + 1.0f));
}

}  // namespace reflect
