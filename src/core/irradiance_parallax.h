// Diffuse light's parallax, the C++ side of shaders/irradiance_parallax.glsl (docs/rough.md,
// "Parallax from the probe's distances"): what a point of a probe-lit object sees about its normal
// less what its probe's centre sees about the same normal, from eight cosine-weighted taps of the
// probe's blurred colours, each tap's ray from the point followed to the surface the probe's
// stored distances put it on. Added to the order-2 harmonics read at the centre, it moves the
// light to where the point sees it; the taps' own error is made on both sides and mostly cancels.
#pragma once

#include <glm/glm.hpp>

#include "core/skybox_faces.h"

namespace reflect {

inline constexpr int kParallaxTaps = 8;
inline constexpr int kParallaxSteps = 3;  // fixed-point steps of each tap's distance search

// The mip levels the taps read a probe of faceSize texels at: its colours where a face is 2 to 4
// texels across (about a tap's share of the hemisphere), its distances at 16 texels.
struct ParallaxLevels {
  float colour = 0.0f;
  float distance = 0.0f;
};
ParallaxLevels parallaxLevels(int faceSize);

// E / pi at `point` less E / pi at `centre`, both for unit normal n, from the probe's level-0 faces
// (colours in rgb, d / (d + 1) in alpha with d in units of the capture's near plane `near`, the
// sky's 255), read through their box mip chain as the GPU's trilinear sampler reads it.
glm::vec3 irradianceParallax(const CubeFaces& faces, const glm::vec3& point,
                             const glm::vec3& centre, const glm::vec3& n, float near);

}  // namespace reflect
