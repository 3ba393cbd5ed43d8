#include "core/method_cost.h"

#include <algorithm>
#include <cmath>

namespace reflect {

const char* methodName(Method method) {
  return method == Method::Trace ? "trace" : "capture";
}

MethodCosts MethodCosts::softwareRenderer() {
  MethodCosts c;
  c.tracePixel = 2.0e-4;
  c.tracePixelLevel = 2.0e-5;
  c.generalFactor = 1.6;
  c.face = 0.3;
  c.triangle = 2.0e-5;
  c.texel = 4.0e-6;
  c.searchPixel = 4.0e-4;
  return c;
}

double traceCost(const TraceWork& work, const MethodCosts& costs) {
  const double levels = std::log2(std::max(work.triangles, 1.0));
  const double perPixel = costs.tracePixel + costs.tracePixelLevel * levels;
  return work.pixels * perPixel * (work.general ? costs.generalFactor : 1.0);
}

double captureCost(const CaptureWork& work, const MethodCosts& costs) {
  return work.faces * costs.face + work.triangles * costs.triangle + work.texels * costs.texel +
         work.pixels * costs.searchPixel;
}

Method chooseMethod(double trace, double capture, Method current, const MethodCosts& costs) {
  if (current == Method::Trace)
    return capture * costs.hysteresis < trace ? Method::Capture : current;
  return trace * costs.hysteresis < capture ? Method::Trace : current;
}

}  // namespace reflect
