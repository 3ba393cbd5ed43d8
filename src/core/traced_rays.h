// How many rays the exact mode's tracer casts for one frame, counted on the CPU: what
// `reflect bench --growth` divides its frame times by, so a cost per ray can be read beside them.
// It walks the rays shaders/exact_shade.glsl walks, with core's BVH (pixel_trace.h) on the same
// level-0 trees the shader's atlas holds:
//  - each pixel's camera ray (pixelRay); where it first meets a traced mirror, that mirror's
//    reflected ray (about the interpolated vertex normal, as environment.frag reflects) is ray 1;
//  - a ray never meets the object it leaves (the shader skips it; no epsilon), and a hit farther
//    than the capture's far distance along an axis from the leaving object's centre is a miss
//    (exactBeyondFar);
//  - a ray that meets another mirror is followed (one more ray) unless it has already left
//    kMaxBounces surfaces: at most kMaxTracedRays = kMaxBounces + 1 rays a pixel, the pixel's own
//    reflection and kMaxBounces followed ones (exactRadiance's `depth > kExactMaxBounces`, the
//    reference's `path.depth > kMaxBounces`).
// Not modelled: glass and cube-textured surfaces (their rays branch, cross interiors or start
// again from a probe centre) and a rough mirror's lobe of rays at the pixel (a rough mirror met
// further on reflects as a perfect one in the shader, and here); a pixel whose path meets one is
// counted in `unmodelled`, not in the rays.
// The count is per visible pixel: the GPU also runs the shader on mirror fragments that a nearer
// one later covers (the main pass has no depth pre-pass and draws back faces), which this does
// not see.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "core/camera.h"
#include "core/pixel_trace.h"
#include "core/scene.h"
#include "core/trace_limits.h"

namespace reflect {

inline constexpr int kMaxTracedRays = kMaxBounces + 1;

struct TracedRayCount {
  int64_t mirrorPixels = 0;  // pixels whose camera ray first meets a traced mirror
  int64_t rays = 0;          // the rays cast for them, bounces included
  int64_t unmodelled = 0;    // traced pixels whose path this count does not follow
  // pixelsWithRays[n]: mirror pixels that cast n rays (n = 1 .. kMaxTracedRays).
  std::array<int64_t, kMaxTracedRays + 1> pixelsWithRays{};
};

// Whether object `object`'s pixels are traced this frame (FramePlan::traces).
using TracedObject = std::function<bool(int object)>;

// The rays for a width x height frame of `scene` at `seconds` seen by `camera`, each object traced
// on its tree from `trees` (null: neither drawn by the tracer nor met by its rays).
TracedRayCount countTracedRays(const Scene& scene, double seconds, const MeshTreeLookup& trees,
                               const LookCamera& camera, int width, int height,
                               const TracedObject& traced);

}  // namespace reflect
