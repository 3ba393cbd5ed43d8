// The GGX (Trowbridge-Reitz) lobe of a rough mirror, in one place for every C++ user: the
// reference's Monte Carlo estimate (src/reference/), the planner's choice of filtered levels and
// the tests. shaders/ggx.glsl is the same functions, term by term and with the same names, for the
// probe's prefilter pass and the exact mode's lobe rays.
//
// What a rough mirror sees (docs/rough.md): the environment averaged over its GGX lobe, weighed by
// the Smith-GGX microfacet reflectance times the cosine, normalised so that a uniform environment
// is seen unchanged. Fresnel stays where it was (the course's mix, or Schlick at the view angle),
// so roughness 0 is the perfect mirror of before.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace reflect {

// The lobe's alpha from the material's roughness (0..1): roughness squared, as three.js, Filament
// and Unreal map it, so that equal roughness steps look like equal steps of blur.
inline float ggxAlpha(float roughness) {
  const float r = glm::clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

// Point i of the n-point Hammersley set: (i / n, the base-2 radical inverse of i). The exact mode
// and the prefilter pass use the same fixed set for every pixel (no noise; structured error).
glm::vec2 hammersley(uint32_t i, uint32_t n);

// A right-handed orthonormal frame around the unit vector n: columns tangent, bitangent, n.
glm::mat3 frameAround(const glm::vec3& n);

// The half vector for the uniform point u on the unit square, distributed as D(h) (n.h) around
// the unit normal n: phi = 2 pi u.x, cos(theta)^2 = (1 - u.y) / (1 + (alpha^2 - 1) u.y).
glm::vec3 ggxHalfVector(const glm::vec2& u, float alpha, const glm::vec3& n);

// GGX's normal distribution D(h) = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
float ggxDistribution(float nDotH, float alpha);

// Smith's masking for one direction: 2 c / (c + sqrt(alpha^2 + (1 - alpha^2) c^2)).
float smithG1(float cosine, float alpha);

// The weight of the lobe sample l = reflect(-v, h) whose h came from ggxHalfVector: the
// reflectance times the cosine over the sample's density, G1(v) G1(l) (v.h) / ((n.v) (n.h));
// 0 when l is below the surface. A rough mirror sees sum(w L(l)) / sum(w).
float lobeSampleWeight(float nDotV, float nDotL, float nDotH, float vDotH, float alpha);

// The prefilter pass's source level for one of `samples` lobe samples (filtered importance
// sampling, Colbert and Krivanek 2007): the mip whose texel covers the sample's share of the lobe,
// 1 / (samples pdf), with the lobe seen along its normal (v = n, so pdf = D / 4), plus one level
// to overlap neighbours. faceSize: the source's level 0.
float prefilterSourceLod(float nDotH, float alpha, int samples, int faceSize);

// The prefilter pass's lobe for one rough level, the same for every texel (the lobe is seen along
// its normal): per sample that lies above the surface, its direction with the normal along +z
// (the shader turns it to each texel's normal with frameAround; how the set is turned about the
// normal is immaterial, the lobe being isotropic) scaled to its share of the weights (n.l,
// normalised to sum 1), and in w its source level (prefilterSourceLod). `samples` is held to
// 1..kMaxFilterSamples.
inline constexpr int kMaxFilterSamples = 128;
std::vector<glm::vec4> prefilterLobe(float alpha, int samples, int faceSize);

// The prefiltered probe's levels (docs/rough.md): level m of `levels` holds roughness m / levels
// at face size faceSize >> m (at least 1); level 0 is the capture itself. A reader of roughness r
// reads level r * levels, between its two neighbours. The levels a reader needs: the two around
// r * levels, without 0; none for roughness 0.
struct RoughLevels {
  int lower = 0;  // 0: the capture itself
  int upper = 0;
};
RoughLevels roughLevelsFor(float roughness, int levels);
// The levels a probe of faceSize can hold: the setting, held to log2(faceSize) so that the last
// level has a texel (a mip chain ends there).
int usableRoughLevels(int roughLevels, int faceSize);

// Where a prefiltered lookup reads a rough mirror's lobe: the reflected direction r bent towards
// the normal n as the lobe widens (the microfacet lobe's mass sits between them, the more so the
// rougher and the more grazing): normalize(mix(n, r, s (sqrt(s) + alpha))), s = 1 - alpha, the
// fit Frostbite published (Lagarde and de Rousiers 2014). shaders/environment.frag uses it; the
// traced lobe needs no such fit.
glm::vec3 specularDominantDirection(const glm::vec3& n, const glm::vec3& r, float alpha);
float roughnessOfLevel(int level, int levels);

// Frosted glass (docs/rough.md): the roughness of the level a prefiltered lookup reads for the
// light that rough glass of index `ior` lets through. A microfacet tilted by t from the normal
// turns the refracted ray by about (1 - 1/n) t inside, and the polished far surface multiplies a
// small turn by about n on the way out: (n - 1) t in all, against a mirror's 2 t. So the light
// through is blurred about as a mirror of alpha x |n - 1| / 2 would blur it: roughness x
// sqrt(|n - 1| / 2), times kTransmissionLobeFit (0 for n = 1, where a rough surface bends
// nothing), held to 1. The fit: a sphere is a lens, not a slab; on frosted-glass (index 1.5,
// hierarchical search, 256x256) 0.75 of the estimate measured best at t = 2 and 5 s (factors 0
// to 2.2 of it tried) and, at the held-out times 0.5, 3.5 and 6.5 s, 30.91 dB against the
// estimate's own 29.44 dB (docs/rough.md). The traced lobe (the reference, the exact mode)
// needs no such estimate.
inline constexpr float kTransmissionLobeFit = 0.75f;
float transmissionRoughness(float roughness, float ior);

// A lobe wider than this GGX alpha (roughness 0.71) is wide: a quarter of its lobe taps spreads
// tens of degrees from the quarter's median ray, whose distance the taps take, so each tap also
// checks the central ray's distance against the probe's depths (shaders/environment_lookup.glsl,
// tapSeenChecked). Narrower lobes lost by it (docs/rough.md, "Each quarter searched").
inline constexpr float kWideLobeAlpha = 0.5f;

}  // namespace reflect
