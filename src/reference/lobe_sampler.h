// The reference's random points on the unit square for a rough mirror's lobe (core/ggx.h): the
// Hammersley set, shifted by a random offset (Cranley-Patterson rotation) that a hash of the seed
// and the shading point picks. Every point is uniform on the square, so each lobe estimate is
// unbiased term by term, and the shifted set covers the square evenly, so it is far less noisy
// than as many independent points. No state: a pixel's points depend on the seed and on where its
// rays meet surfaces, never on the thread or the order the pixels are traced in.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace reflect {

class LobeSampler {
 public:
  // The points for the shading point `position` seen along -toViewer, from `seed`.
  LobeSampler(uint32_t seed, const glm::vec3& position, const glm::vec3& toViewer);

  // Point k of `count` (k < count): hammersley(k, count) shifted, wrapped into [0, 1)^2.
  glm::vec2 point(uint32_t k, uint32_t count) const;

 private:
  glm::vec2 shift_{0.0f};
};

// The lobe's directional albedo without Fresnel, E[lobeSampleWeight] over the GGX half vectors
// (in (0, 1]), for the unit normal's cosine with the viewer nDotV > 0, from `count` fixed
// Hammersley points: what a few traced lobe samples' mean w L is divided by to estimate the lobe
// average without a ratio (the nested estimator of reference_tracer.cpp).
float lobeAlbedo(float nDotV, float alpha, uint32_t count);

// lobeAlbedo for one alpha, tabulated once (kLobeAlbedoPoints points at kLobeAlbedoRows cosines)
// and read by linear interpolation. Against 65,536 points: within 1e-3 for views steeper than
// n.v = 0.1, within some 2% at grazing views of the smoothest lobes (where the part of the lobe
// below the surface makes the integrand a step that fixed points converge on slowly).
class LobeAlbedoTable {
 public:
  LobeAlbedoTable() = default;  // empty: at() is 1
  explicit LobeAlbedoTable(float alpha);
  float at(float nDotV) const;

 private:
  std::vector<float> rows_;  // row i: nDotV = (i + 1) / rows
};

}  // namespace reflect
