// What a reflector costs each frame by either of the two ways it can be drawn, so the frame
// planner can pick the cheaper one (search: planned):
//  - traced: every mirror pixel's ray walks the scene's BVH (exact);
//  - captured: the probe's faces are drawn (when what they show changed) and every mirror pixel
//    searches them (the hierarchical search, two layers where something hides something).
// The model is linear in counts the planner knows: mirror pixels on screen, BVH levels, faces,
// triangles and texels drawn into them. Its coefficients are milliseconds, fitted to one
// renderer's measurements (docs/accuracy.md, "How the planner picks"); a test holds the choice
// for given costs, and the sweep and the page's bench measure what it picked.
#pragma once

#include <cstddef>

namespace reflect {

enum class Method {
  Trace,    // the rays are traced: no probe, no faces
  Capture,  // a probe is captured and searched
};
const char* methodName(Method method);

struct TraceWork {
  double pixels = 0.0;     // mirror pixels on screen (the reflectors' projected discs)
  double triangles = 0.0;  // the scene's triangles (the BVH's depth grows with their log)
  bool general = false;    // rays may meet other mirrors or glass (the general tracer)
  // Of `pixels`, those of rough mirrors: each traces `lobeRays` rays (accuracy.lobeRays).
  double lobePixels = 0.0;
  double lobeRays = 1.0;
};

struct CaptureWork {
  double faces = 0.0;      // faces redrawn a frame, as the scene moves
  double triangles = 0.0;  // triangles drawn into them a frame, every pass
  double texels = 0.0;     // face texels drawn a frame, every pass
  double pixels = 0.0;     // mirror pixels on screen that search the probe
  // Rough readers: the prefilter pass's texels times its samples a frame (all six faces of each
  // level kept, when a face was redrawn).
  double filterSamples = 0.0;
  // Rough readers with lobe taps: their pixels times the taps each reads a frame.
  double lobeTaps = 0.0;
  // Rough mirrors and frosted glass whose lobes' quarters (glass: its light through's) each run a
  // short search of their own (AccuracySettings::lobeQuarters): their pixels times kLobeQuarters.
  double lobeSearches = 0.0;
};

// The short searches a rough mirror's lobe, or frosted glass's light through, runs besides its
// central ray's, one per quarter of the lobe by azimuth (shaders/environment_lookup.glsl,
// lobeDistances and transmittedDistances).
inline constexpr int kLobeQuarters = 4;

struct MethodCosts {
  double tracePixel = 0.0;       // ms per traced pixel
  double tracePixelLevel = 0.0;  // ms per traced pixel per level (log2 of the triangles)
  double generalFactor = 1.0;    // the general tracer's cost over the Phong-only one
  double face = 0.0;             // ms per face redrawn (targets, state, the pyramid's levels)
  double triangle = 0.0;         // ms per triangle drawn into a face
  double texel = 0.0;            // ms per face texel drawn
  double searchPixel = 0.0;      // ms per mirror pixel's search
  double filterSample = 0.0;     // ms per filtered texel per GGX sample (the prefilter pass)
  double lobeTap = 0.0;          // ms per lobe tap a rough pixel reads
  double lobeSearch = 0.0;       // ms per quarter of a rough lobe searched
  // Switch methods only when the other is cheaper by this factor, so a reflector near the
  // balance does not flip (and recapture) from frame to frame.
  double hysteresis = 1.2;

  // Fitted to llvmpipe (Mesa 22.3.6, 2 cores) on the default scene and its heavy figure; see
  // docs/accuracy.md for the measurements and the fit.
  static MethodCosts softwareRenderer();
};

double traceCost(const TraceWork& work, const MethodCosts& costs);
double captureCost(const CaptureWork& work, const MethodCosts& costs);

// The cheaper method; `current` (what the reflector used last frame) is kept unless the other is
// cheaper by costs.hysteresis.
Method chooseMethod(double trace, double capture, Method current, const MethodCosts& costs);

}  // namespace reflect
