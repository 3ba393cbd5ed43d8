// core/ggx, by hand and against an independent integral: the Hammersley points' exact values, the
// half vector of the square's corner (the lobe's centre), the weight's zero below the surface,
// and the mean of the lobe weights over many Hammersley points against the directional albedo of
// Smith-GGX without Fresnel integrated over a grid of directions from D and G1 alone.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ggx.h"

namespace reflect {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Ggx, HammersleyPointsAreExact) {
  EXPECT_EQ(hammersley(0, 4), glm::vec2(0.0f, 0.0f));
  EXPECT_EQ(hammersley(1, 4), glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(hammersley(2, 4), glm::vec2(0.5f, 0.25f));
  EXPECT_EQ(hammersley(3, 4), glm::vec2(0.75f, 0.75f));
  EXPECT_EQ(hammersley(5, 16), glm::vec2(0.3125f, 0.625f));  // 5 = 101b: 0.101b
}

TEST(Ggx, TheCornerOfTheSquareIsTheNormal) {
  for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
                             glm::normalize(glm::vec3(1, -2, 3))}) {
    for (float alpha : {0.01f, 0.25f, 1.0f}) {
      const glm::vec3 h = ggxHalfVector(glm::vec2(0.0f), alpha, n);
      EXPECT_NEAR(h.x, n.x, 1e-6f);
      EXPECT_NEAR(h.y, n.y, 1e-6f);
      EXPECT_NEAR(h.z, n.z, 1e-6f);
    }
  }
}

TEST(Ggx, NoWeightBelowTheSurface) {
  EXPECT_EQ(lobeSampleWeight(0.8f, -0.1f, 0.9f, 0.5f, 0.5f), 0.0f);
  EXPECT_EQ(lobeSampleWeight(0.8f, 0.0f, 0.9f, 0.5f, 0.5f), 0.0f);
  EXPECT_EQ(lobeSampleWeight(-0.2f, 0.5f, 0.9f, 0.5f, 0.5f), 0.0f);
  // Above it, at the lobe's centre seen head-on: G1(1) G1(1) 1 / (1 1) = 1.
  EXPECT_NEAR(lobeSampleWeight(1.0f, 1.0f, 1.0f, 1.0f, 0.5f), 1.0f, 1e-6f);
}

// The mean lobe weight over n Hammersley points, for the viewer at `degrees` from the normal.
double meanWeight(double degrees, float alpha, uint32_t n) {
  const glm::vec3 normal(0, 0, 1);
  const float a = static_cast<float>(degrees * kPi / 180.0);
  const glm::vec3 v(std::sin(a), 0.0f, std::cos(a));
  double sum = 0.0;
  for (uint32_t k = 0; k < n; ++k) {
    const glm::vec3 h = ggxHalfVector(hammersley(k, n), alpha, normal);
    const glm::vec3 l = glm::reflect(-v, h);
    sum += lobeSampleWeight(v.z, l.z, h.z, glm::dot(v, h), alpha);
  }
  return sum / n;
}

// The same albedo, integral of D(h) G1(v) G1(l) / (4 n.v) over the directions l above the
// surface (the BRDF D G / (4 n.v n.l) times n.l), by the midpoint rule on a grid of cos(theta)
// and phi: no sampling, no half vector sampling formula.
double gridAlbedo(double degrees, float alpha) {
  const double a = degrees * kPi / 180.0;
  const glm::dvec3 v(std::sin(a), 0.0, std::cos(a));
  constexpr int kRows = 1000, kColumns = 1000;
  double sum = 0.0;
  for (int i = 0; i < kRows; ++i) {
    const double cosTheta = (i + 0.5) / kRows;
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    for (int j = 0; j < kColumns; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kColumns;
      const glm::dvec3 l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
      const glm::dvec3 h = glm::normalize(v + l);
      const double d = ggxDistribution(static_cast<float>(h.z), alpha);
      const double g =
          smithG1(static_cast<float>(v.z), alpha) * smithG1(static_cast<float>(cosTheta), alpha);
      sum += d * g / (4.0 * v.z);
    }
  }
  return sum * (2.0 * kPi / kColumns) / kRows;  // d(omega) = d(cos theta) d(phi)
}

TEST(Ggx, MeanWeightIsTheDirectionalAlbedo) {
  // Head-on, a nearly smooth lobe reflects nearly everything.
  const double smooth = meanWeight(0.0, 0.02f, 1024);
  EXPECT_GT(smooth, 0.995);
  EXPECT_LE(smooth, 1.0 + 1e-6);
  for (double degrees : {0.0, 45.0, 70.0}) {
    for (float alpha : {0.25f, 0.5f, 1.0f}) {
      const double sampled = meanWeight(degrees, alpha, 4096);
      const double grid = gridAlbedo(degrees, alpha);
      EXPECT_GT(sampled, 0.0) << degrees << " " << alpha;
      EXPECT_LE(sampled, 1.0 + 1e-6) << degrees << " " << alpha;
      // The grid's own error at alpha 0.25 (the narrowest lobe here) is some 1e-3.
      EXPECT_NEAR(sampled, grid, 5e-3) << degrees << " degrees, alpha " << alpha;
    }
  }
  // Rougher loses more to masking and shadowing.
  EXPECT_GT(meanWeight(45.0, 0.25f, 4096), meanWeight(45.0, 1.0f, 4096));
}

// The light through frosted glass is read at a narrower level than its reflection (core/ggx.h
// says why): roughness x 0.75 x sqrt(|n - 1| / 2), none at n = 1, held to 1.
TEST(Ggx, TheLightThroughFrostedGlassReadsANarrowerLevel) {
  EXPECT_FLOAT_EQ(transmissionRoughness(1.0f, 1.5f), 0.375f);
  EXPECT_FLOAT_EQ(transmissionRoughness(0.4f, 1.5f), 0.15f);
  EXPECT_FLOAT_EQ(transmissionRoughness(0.0f, 1.5f), 0.0f);
  EXPECT_FLOAT_EQ(transmissionRoughness(1.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(transmissionRoughness(1.0f, 3.0f), 0.75f);
  EXPECT_FLOAT_EQ(transmissionRoughness(2.0f, 4.0f), 0.75f * std::sqrt(1.5f));  // roughness held
}

}  // namespace
}  // namespace reflect
