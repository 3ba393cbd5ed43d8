// The knobs that trade speed for accuracy in the capture and the lookup (measured by
// `reflect bench --sweep` against the ray-traced reference).
#pragma once

#include <string>

namespace reflect {

struct AccuracySettings {
  bool captureAtOrigin = false;  // the course's capture point (0,0,0), not the reflector's centre
  // 0: plain lookup along R (the course). k > 0: distance-corrected lookup, the "distance
  // impostor" of Szirmay-Kalos et al. (2005): the capture stores each texel's distance from the
  // probe centre (alpha, as d / (d + 1)), and the reflected ray from the surface point is
  // intersected with that depth (a linear search, then k secant steps) before the lookup.
  // The shipped default (2) is the Pareto-best setting of `reflect bench --sweep` within 1.1x
  // the course's frame time; see README.
  int distanceIterations = 2;
  int depthBits = 24;      // capture depth buffer: 16 or 24
  bool mipmaps = false;    // trilinear lookup from a mip chain rebuilt after each capture
  bool halfFloat = false;  // RGBA16F capture colour instead of RGBA8
  bool mediump = false;    // fragment shaders at mediump instead of highp

  bool usesHalfFloat() const { return halfFloat; }
  bool operator==(const AccuracySettings& o) const {
    return captureAtOrigin == o.captureAtOrigin && distanceIterations == o.distanceIterations &&
           depthBits == o.depthBits && mipmaps == o.mipmaps && halfFloat == o.halfFloat &&
           mediump == o.mediump;
  }
  bool operator!=(const AccuracySettings& o) const { return !(*this == o); }
  // e.g. "centre, distance x2, depth 24, linear, RGBA16F, highp"
  std::string describe() const;
};

// The inverse of describe(), for the rows of the measured sweep (their `setting` column): each
// comma-separated part sets one setting, parts it does not name keep their default. False (and
// `settings` unchanged) when a part is not one describe() writes.
bool parseAccuracyDescription(const std::string& text, AccuracySettings* settings);

}  // namespace reflect
