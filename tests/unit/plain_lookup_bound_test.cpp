// The planner's rule for skipping the search (plainLookupWithinHalfTexel, frame_planner.h): when
// every surface a probe sees is at least `nearest` from its centre and every reflector point is
// within `reach` of it, the plain lookup (the cube along the reflected direction d, ignoring
// where on the reflector the ray starts) is off by less than half a texel. Tested numerically:
//  - the lookup's angle: for random reflector points p (|p| <= reach), directions d and points
//    q = p + t d with |q| >= nearest, the angle between d and q is at most halfTexelAngle
//    whenever the rule says true; and just past the rule, the worst case exceeds it;
//  - the half texel: any direction within halfTexelAngle of a texel centre, anywhere on a face,
//    projects within half a texel of it along both of the face's axes; and at a face's corner a
//    slightly larger angle (the old constant, 0.4714 / N) does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/glm.hpp>

#include "core/frame_planner.h"

namespace reflect {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;

double angleBetween(const dvec3& a, const dvec3& b) {
  // atan2 of |a x b| and a.b: accurate for tiny angles, where acos is not.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

dvec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  dvec3 v;
  do {
    v = {normal(rng), normal(rng), normal(rng)};
  } while (glm::length(v) < 1e-6);
  return glm::normalize(v);
}

// A unit vector perpendicular to `v`, at a random angle about it.
dvec3 randomPerpendicular(const dvec3& v, std::mt19937& rng) {
  dvec3 w;
  do {
    w = glm::cross(glm::normalize(v), randomUnit(rng));
  } while (glm::length(w) < 1e-3);
  return glm::normalize(w);
}

// The face coordinates (s, t) of `v` on the +Z face's plane (z = 1); the face is [-1, 1]^2.
dvec2 onFace(const dvec3& v) {
  return {v.x / v.z, v.y / v.z};
}

// The worst (largest) angle between d and q over the rule's whole domain, sampled: random p in
// the ball of radius `reach`, random d, q = p + t d with t past the point where |q| = nearest.
double worstSampledAngle(double reach, double nearest, std::mt19937& rng, int samples) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::exponential_distribution<double> beyond(4.0);
  double worst = 0.0;
  for (int i = 0; i < samples; ++i) {
    // Half the samples on the ball's surface (where the worst case lies), half inside.
    const double radius = i % 2 == 0 ? reach : reach * std::cbrt(unit(rng));
    const dvec3 p = radius * randomUnit(rng);
    // Every fourth d perpendicular to p (the worst case's direction), else any.
    const dvec3 d = i % 4 == 1 ? randomPerpendicular(p, rng) : randomUnit(rng);
    // |p + t d| = nearest: t^2 + 2 (p.d) t + |p|^2 - nearest^2 = 0, one positive root.
    const double b = glm::dot(p, d);
    const double tNearest = -b + std::sqrt(b * b - glm::dot(p, p) + nearest * nearest);
    // Half on the sphere |q| = nearest (the worst case), half farther away.
    const double t = i % 3 == 0 ? tNearest : tNearest * (1.0 + beyond(rng));
    const dvec3 q = p + t * d;
    EXPECT_GE(glm::length(q), nearest * (1.0 - 1e-12));
    worst = std::max(worst, angleBetween(d, q));
  }
  return worst;
}

TEST(PlainLookupBound, TheAngleIsWithinHalfATexelWheneverTheRuleHolds) {
  std::mt19937 rng(11);
  for (int faceSize : {16, 64, 128, 256, 1024}) {
    const double halfTexel = halfTexelAngle(faceSize);
    for (double nearest : {1.0, 3.5, 100.0}) {
      // Just inside the rule (the largest reach it accepts, to float precision), and well inside.
      const double edge = nearest * std::sin(halfTexel);
      for (double fraction : {0.999, 0.5}) {
        const float reach = static_cast<float>(edge * fraction);
        ASSERT_TRUE(plainLookupWithinHalfTexel(reach, static_cast<float>(nearest), faceSize))
            << faceSize << " " << nearest << " " << fraction;
        const double worst = worstSampledAngle(reach, nearest, rng, 20000);
        // The bound is exact: the sampled worst is asin(reach / nearest) to within sampling.
        EXPECT_LE(worst, std::asin(reach / nearest) * (1.0 + 1e-9));
        EXPECT_GT(worst, 0.99 * std::asin(reach / nearest));
        EXPECT_LE(worst, halfTexel) << "face " << faceSize << " nearest " << nearest;
      }
      // Past the rule: it says false, and the worst case (|p| = reach, d perpendicular to p,
      // |q| = nearest) is past half a texel.
      const float past = static_cast<float>(edge * 1.01);
      EXPECT_FALSE(plainLookupWithinHalfTexel(past, static_cast<float>(nearest), faceSize));
      const dvec3 p(past, 0.0, 0.0), d(0.0, 0.0, 1.0);
      const dvec3 q = p + std::sqrt(nearest * nearest - double(past) * past) * d;
      EXPECT_NEAR(glm::length(q), nearest, 1e-9 * nearest);
      EXPECT_GT(angleBetween(d, q), halfTexel);
      EXPECT_GT(worstSampledAngle(past, nearest, rng, 4000), halfTexel);
    }
    std::printf("face %4d: half a texel %.6f rad (%.4f / N)\n", faceSize, halfTexel,
                halfTexel * faceSize);
  }
  // The edges of the domain: the sky alone (nearest infinite) always suffices; a reflector
  // reaching as far as the nearest surface never does.
  EXPECT_TRUE(plainLookupWithinHalfTexel(5.0f, INFINITY, 256));
  EXPECT_FALSE(plainLookupWithinHalfTexel(2.0f, 2.0f, 256));
  EXPECT_FALSE(plainLookupWithinHalfTexel(3.0f, 2.0f, 256));
}

// The largest offset along either face axis, in texels (2 / N of s), of a direction at `angle`
// from `centre` (a direction on the +Z face), over `steps` directions around it.
double largestOffsetTexels(const dvec3& centre, double angle, int faceSize, int steps) {
  const dvec3 v = glm::normalize(centre);
  const dvec3 e1 = glm::normalize(glm::cross(v, dvec3(0.0, 1.0, 0.0)));
  const dvec3 e2 = glm::cross(v, e1);
  const dvec2 st = onFace(v);
  double largest = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double phi = 2.0 * kPi * k / steps;
    const dvec3 w =
        std::cos(angle) * v + std::sin(angle) * (std::cos(phi) * e1 + std::sin(phi) * e2);
    const dvec2 offset = glm::abs(onFace(w) - st) * (0.5 * faceSize);
    largest = std::max({largest, offset.x, offset.y});
  }
  return largest;
}

TEST(PlainLookupBound, HalfATexelsAngleIsALowerBoundAnywhereOnAFace) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> texel(0, 1 << 30);
  for (int faceSize : {16, 64, 128, 256, 1024}) {
    const double halfTexel = halfTexelAngle(faceSize);
    double worst = 0.0;
    // Every texel centre of the face's corner region and random ones elsewhere: a direction
    // within halfTexel of the centre stays within half a texel (1 / N of s and t) of it.
    auto check = [&](int i, int j) {
      const dvec3 centre(-1.0 + (2.0 * i + 1.0) / faceSize, -1.0 + (2.0 * j + 1.0) / faceSize, 1.0);
      const double offset = largestOffsetTexels(centre, halfTexel, faceSize, 64);
      worst = std::max(worst, offset);
      EXPECT_LE(offset, 0.5) << "face " << faceSize << " texel " << i << "," << j;
    };
    for (int j = faceSize - 4; j < faceSize; ++j) {
      for (int i = faceSize - 4; i < faceSize; ++i) check(i, j);
    }
    for (int k = 0; k < 500; ++k) check(texel(rng) % faceSize, texel(rng) % faceSize);
    std::printf("face %4d: within %.6f rad of a texel centre, off by at most %.4f texels\n",
                faceSize, halfTexel, worst);
    // At the corner texel, 0.4714 / N (the angle's rate along s alone, sqrt(2) / 3 per unit of
    // s, which the rule once used) reaches past half a texel: diagonally the angle grows
    // slower. The true bound there: asin(1 / (sqrt(1 + 1) sqrt(1 + 2 (1 - 1/N)^2) N)).
    const dvec3 corner(1.0 - 1.0 / faceSize, 1.0 - 1.0 / faceSize, 1.0);
    const double atCorner = largestOffsetTexels(corner, 0.4714 / faceSize, faceSize, 720);
    std::printf("face %4d: at 0.4714 / N from the corner texel's centre: off by %.4f texels\n",
                faceSize, atCorner);
    EXPECT_GT(atCorner, 0.55);
    const double c = 1.0 - 1.0 / faceSize;
    const double exact =
        std::asin(1.0 / (std::sqrt(2.0) * std::sqrt(1.0 + 2.0 * c * c) * faceSize));
    EXPECT_LT(halfTexel, exact);
    // and the constant is tight: within 0.1% of the corner's limit 1 / (sqrt(6) N).
    EXPECT_GT(halfTexel, 0.999 / (std::sqrt(6.0) * faceSize));
  }
}

}  // namespace
}  // namespace reflect
