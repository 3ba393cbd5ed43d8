// Search: planned, per reflector: what tracing its rays and capturing its probe would cost this
// frame (core/method_cost.h weighs them), and the method each probe's reflectors get.
#include <algorithm>

#include "core/frame_planner.h"
#include "core/planner_parts.h"

namespace reflect {

using planner::contains;
using planner::worldCentreOf;
using planner::worldRadiusOf;

MethodChoice FramePlanner::weigh(const ProbePlan& probe, const FaceDraws& draws,
                                 const std::vector<PlannedObject>& objects,
                                 const CaptureContext& context, const PlannerSettings& settings,
                                 const PlannerView& view) const {
  MethodChoice c;
  c.reflector = probe.reflector;
  double quarterPixels = 0.0;  // rough pixels whose lobe's quarters search: a mirror's
                               // (lobeDistances), glass's light through (transmittedDistances)
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    if (!o.levels.empty()) c.trace.triangles += static_cast<double>(o.levels[0].triangles);
    if (contains(probe.members, static_cast<int>(i))) {
      const float pixels = screenPixels(worldCentreOf(o), worldRadiusOf(o), view);
      c.trace.pixels += pixels;
      c.trace.general |= planner::needsGeneralTracer(objects, static_cast<int>(i));
      if (o.look.rough()) {
        // Frosted glass traces two lobes a pixel (its reflection's and the light through it),
        // each crossing the object: about twice a rough mirror's rays.
        c.trace.lobePixels += o.look.material == Material::Glass ? 2.0f * pixels : pixels;
        quarterPixels += pixels;
      }
    }
  }
  // Captured: the faces that show something moving are redrawn (every face, every frame, under
  // the course's policy), each with one pass, or three where two layers are stored; then every
  // mirror pixel searches.
  const bool everyFrame = settings.policy == UpdatePolicy::EveryFrame;
  const int faceSize = probe.faceSize > 0 ? probe.faceSize : context.faceSize;
  const double texels = static_cast<double>(faceSize) * faceSize;
  for (int face = 0; face < 6; ++face) {
    const std::vector<DrawItem>& shown = draws[static_cast<size_t>(face)];
    bool moving = everyFrame;
    double triangles = 0.0;
    for (const DrawItem& d : shown) {
      moving |= movedNow_[static_cast<size_t>(d.object)];
      triangles += static_cast<double>(d.triangles);
    }
    if (!moving) continue;
    const bool twoLayers = planner::faceStoresTwoLayers(probe.layers, shown.size(), context);
    // Two layers: the nearest surfaces and their backs at the capture's detail, what they hide
    // at kSecondLayerDetail of it.
    const double passes = twoLayers ? 2.0 + kSecondLayerDetail : 1.0;
    c.capture.faces += 1.0;
    c.capture.triangles += triangles * passes;
    c.capture.texels += texels * (twoLayers ? 3.0 : 1.0);
  }
  double share = 1.0;  // of the redraws a frame, under the policies that spread them
  if (settings.policy == UpdatePolicy::TimeSliced && c.capture.faces > 0.0) {
    share = std::min(1.0, std::clamp(settings.facesPerFrame, 1, 6) / c.capture.faces);
  } else if (settings.policy == UpdatePolicy::EveryNFrames) {
    share = 1.0 / std::max(settings.everyN, 1);
  }
  c.capture.faces *= share;
  c.capture.triangles *= share;
  c.capture.texels *= share;
  c.capture.pixels = probe.plainLookupSuffices ? 0.0 : c.trace.pixels;
  c.trace.lobeRays = context.accuracy.lobeRays;
  if (probe.lobeTapReaders) c.capture.lobeTaps = c.trace.lobePixels * context.accuracy.lobeTaps;
  // Only the hierarchical search runs the quarters' searches (not a plain lookup).
  if (probe.lobeTapReaders && context.accuracy.lobeQuarters && !probe.plainLookupSuffices)
    c.capture.lobeSearches = kLobeQuarters * quarterPixels;
  if (c.capture.faces > 0.0) {
    c.capture.filterSamples = share * planner::filterSamplesFor(probe.roughLevels, faceSize,
                                                                context.accuracy.filterSamples);
  }
  c.traceMs = traceCost(c.trace, costs_);
  c.captureMs = captureCost(c.capture, costs_);
  if (!probe.diffuseReaders.empty()) {
    // Diffuse readers keep the probe captured either way: traced, its faces are still drawn
    // (colours only, one layer), with nothing searched or filtered.
    CaptureWork colours = c.capture;
    if (colours.faces > 0.0) colours.texels = colours.faces * texels;
    colours.pixels = 0.0;
    colours.filterSamples = 0.0;
    colours.lobeTaps = 0.0;
    colours.lobeSearches = 0.0;
    c.traceMs += captureCost(colours, costs_);
  }
  return c;
}

Method FramePlanner::chooseProbeMethod(const ProbePlan& probe, const FaceDraws& draws,
                                       const std::vector<PlannedObject>& objects,
                                       const CaptureContext& context,
                                       const PlannerSettings& settings, const PlannerView& view,
                                       ProbeMemory& memory) {
  // Trace its rays, or capture it. A cube-textured member's look is its cube: captured.
  const bool rays = std::all_of(probe.members.begin(), probe.members.end(), [&](int m) {
    return planner::traceable(objects[static_cast<size_t>(m)]);
  });
  const Search search = context.accuracy.search;
  Method method = Method::Capture;
  if (rays && search == Search::Exact) method = Method::Trace;
  if (rays && search == Search::Planned && view.pixelsPerTangent > 0.0f) {
    // Weighed against what the weighing chose last frame, not against a forced trace below.
    const Method before = memory.narrowForced ? Method::Capture : memory.method;
    MethodChoice choice = weigh(probe, draws, objects, context, settings, view);
    choice.method = chooseMethod(choice.traceMs, choice.captureMs, before, costs_);
    method = choice.method;
    choices_.push_back(choice);
  }
  // A lobe too narrow for the capture is traced all the same, with narrowLobeRays rays (fewer
  // than lobeRays, which a trace the weighing chose casts).
  const bool narrow = std::any_of(probe.members.begin(), probe.members.end(), [&](int m) {
    return tracedForNarrowLobe(objects[static_cast<size_t>(m)].look, context.accuracy);
  });
  memory.narrowForced = rays && narrow && method == Method::Capture;
  if (memory.narrowForced) {
    method = Method::Trace;
    narrowTraced_.insert(narrowTraced_.end(), probe.members.begin(), probe.members.end());
  }
  if (method != memory.method) {
    for (FaceMemory& f : memory.faces) f.captured = false;  // a trace keeps no faces
    memory.method = method;
  }
  return method;
}

}  // namespace reflect
