#include "core/method_cost.h"

#include <algorithm>
#include <cmath>

namespace reflect {

const char* methodName(Method method) {
  return method == Method::Trace ? "trace" : "capture";
}

// Fitted to `reflect bench --costs` (docs/bench/costs.txt: llvmpipe, 512x512, the default scene
// with its own models and with the 157k-triangle figure, faces of 128, 256 and 512, and
// two-mirrors for the general tracer):
//  - a traced pixel cost 3.3e-6 ms a level with the scene's 13k triangles and 6.6e-6 with 163k:
//    it grows faster than the tree's depth (the rays near the dense figure visit more of it).
//    Per level only, at the heavy scene's rate: the light scene's trace is overestimated about
//    twice, which only makes the planner slower to trace;
//  - the general tracer (mirrors that see each other) 2.5 times the Phong-only one;
//  - a searched pixel 1.8e-4 to 3.5e-4 ms;
//  - a frame's capture grew with the faces' texels (6.5, 17 and 45 ms at 128, 256, 512: about
//    1.5e-5 ms a texel, every pass counted) and little with the triangles (capture LOD keeps them
//    at 41k to 47k a frame whatever the figure): 1e-4 ms a triangle, 0.3 ms a face besides.
// Against those runs the model is within 20% of each capture + search. SwiftShader was not fitted:
// in the page both the search and the capture cost it relatively more than the trace (README's
// page bench), so these weigh against tracing there if anything.
MethodCosts MethodCosts::softwareRenderer() {
  MethodCosts c;
  c.tracePixel = 0.0;
  c.tracePixelLevel = 6.6e-6;
  c.generalFactor = 2.5;
  c.face = 0.3;
  c.triangle = 1.0e-4;
  c.texel = 1.5e-5;
  c.searchPixel = 2.7e-4;
  // The prefilter pass: 43.9 ms for the 1.2 million samples a frame of rough-spheres' four rough
  // probes (128-texel faces, 32 samples; `reflect bench --sweep --scene rough-spheres`, its
  // filter table; docs/bench/sweep-rough.txt).
  c.filterSample = 3.6e-5;
  // A lobe tap is the same trilinear cube read and GGX weight as a filter sample, paid per
  // pixel instead of per texel. (Fitting it from the sweep's main passes was within this
  // machine's noise: 1.3e-4 from one run, which changed no choice in the rough scenes.)
  c.lobeTap = 3.6e-5;
  // A quarter's search: at most 16 steps, on coarse levels. The default's frame less the same
  // frame with one lobe distance (lobeQuarters off) on rough-spheres at 512x512, the held-out
  // times: a median of 18.7 ms over the six runs in docs/bench/sweep-rough-tap-check*.txt (5.6
  // to 20.8 ms: the machine's noise), for the planner's ~55k pixels of the three captured rough
  // mirrors (`reflect bench --costs --scene rough-spheres`: 91.6k mirror pixels over five
  // spheres of one size) times four quarters: 8.5e-5 ms a search, about 0.3x a pixel's full
  // search. It changes no choice in the shipped scenes: a rough mirror traced costs its 16
  // lobe rays, several times this.
  c.lobeSearch = 8.5e-5;
  return c;
}

double traceCost(const TraceWork& work, const MethodCosts& costs) {
  const double levels = std::log2(std::max(work.triangles, 1.0));
  const double perPixel = costs.tracePixel + costs.tracePixelLevel * levels;
  const double rays = work.pixels + work.lobePixels * (work.lobeRays - 1.0);
  return rays * perPixel * (work.general ? costs.generalFactor : 1.0);
}

double captureCost(const CaptureWork& work, const MethodCosts& costs) {
  return work.faces * costs.face + work.triangles * costs.triangle + work.texels * costs.texel +
         work.pixels * costs.searchPixel + work.filterSamples * costs.filterSample +
         work.lobeTaps * costs.lobeTap + work.lobeSearches * costs.lobeSearch;
}

Method chooseMethod(double trace, double capture, Method current, const MethodCosts& costs) {
  if (current == Method::Trace)
    return capture * costs.hysteresis < trace ? Method::Capture : current;
  return trace * costs.hysteresis < capture ? Method::Trace : current;
}

}  // namespace reflect
