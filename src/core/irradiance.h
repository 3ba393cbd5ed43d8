// Diffuse light from a live probe, the C++ side of shaders/irradiance.glsl: the order-2 real
// spherical harmonics, the cosine lobe's band factors, and a projection of a cube's faces on them
// as irradiance_project.vert does it on the GPU (solid-angle weights, scaled to 4 pi), so tests
// can hold the shader to it and check the basis on known environments.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "core/skybox_faces.h"

namespace reflect {

inline constexpr int kIrradianceCoefficients = 9;
// The face size of a probe-lit object's own probe (Ambient::OwnProbe): order 2 keeps nothing
// narrower than about a radian, so 32 texels a face (the projection reads 8 x 8) lose nothing it
// keeps (64 gave mario the same PSNR within 0.6 dB, ProbeLit.FiguresAgainstTheReference).
inline constexpr int kIrradianceFaceSize = 32;
using IrradianceCoefficients = std::array<glm::vec3, kIrradianceCoefficients>;

// Y_i(n), i = 0..8 in the order (l, m) = (0, 0), (1, -1), (1, 0), (1, 1), (2, -2), (2, -1),
// (2, 0), (2, 1), (2, 2); n unit.
float shBasis(const glm::vec3& n, int i);
// A_l / pi for coefficient i's band: 1, 2/3, 1/4.
float shBandFactor(int i);

// The light a white Lambertian surface of normal n sends back, E(n) / pi = sum c_i Y_i(n),
// clamped at 0 (phong.frag's probeAmbient).
glm::vec3 irradianceAt(const IrradianceCoefficients& c, const glm::vec3& n);

// The direction a probe-lit point reads its probe's irradiance along (phong.frag's
// irradianceDirection): its normal n when `radius` is 0; otherwise from the probe's centre to
// where the ray point + t n (t > 0) leaves the sphere of that radius about the centre, the
// surroundings taken to lie on it (SceneObject::ambientRadius). n unit; the result is unit.
glm::vec3 irradianceDirection(const glm::vec3& n, const glm::vec3& point, const glm::vec3& centre,
                              float radius);

// The coefficients of a cube given as six faces (GL order, sampled at their texel centres as
// cube_sampling.h reads them), each texel weighed by its solid angle.
IrradianceCoefficients projectIrradiance(const CubeFaces& faces);

// The irradiance cube: six faces of `size` texels whose texel in direction n is irradianceAt(c, n)
// (clamped to 1, rounded to bytes), the ambient light a probe-lit reader with that normal takes.
// The faces view shows it (FacesChannel::Irradiance).
CubeFaces irradianceCube(const IrradianceCoefficients& c, int size);

}  // namespace reflect
