// The frame planner's driver: remembers what each probe's faces showed when they were drawn,
// and each frame plans every probe: traced, or captured with the faces that changed. Its parts
// are in files of their own: the update policies (update_policy.cpp), what a probe stores
// (probe_storage.cpp), the per-reflector method choice (method_choice.cpp) and what each face or
// view draws (planner_draws.cpp).
#include "core/frame_planner.h"

#include <algorithm>

#include "core/irradiance.h"
#include "core/planner_parts.h"
#include "core/probe_layout.h"

namespace reflect {

using planner::contains;

namespace {

// A probe that only lights its diffuse readers stores colours alone: one layer, no depths for a
// search, no rough levels. A probe-lit object's own probe is one, at kIrradianceFaceSize.
void keepColoursOnly(ProbePlan& probe, const std::vector<PlannedObject>& objects) {
  probe.lightOnly = true;
  probe.layers = 1;
  probe.plainLookupSuffices = true;
  probe.roughLevels.clear();
  probe.lobeTapReaders = false;
  if (objects[static_cast<size_t>(probe.reflector)].ownsLightProbe) {
    probe.faceSize = kIrradianceFaceSize;
  }
}

// What a probe stores for its readers, the same in the layout and the plan: one layer or two
// (or colours alone), its rough levels or lobe taps, and its face size.
void decideStorageFor(ProbePlan& probe, const std::vector<PlannedObject>& objects,
                      const CaptureContext& context) {
  planner::decideStorage(probe, objects, context);
  probe.roughLevels = planner::roughLevelsOf(probe, objects, context);
  probe.lobeTapReaders = planner::readsLobeTaps(probe, objects, context);
  probe.faceSize = planner::lobeTapFaceSize(probe, objects, context);
}

bool sameLevels(const std::vector<PlannedLevel>& a, const std::vector<PlannedLevel>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].triangles != b[i].triangles) return false;
  }
  return true;
}

bool sameState(const PlannedObject& a, const PlannedObject& b) {
  return a.model == b.model && a.colour == b.colour && a.look == b.look &&
         a.probeLit == b.probeLit && a.ownsLightProbe == b.ownsLightProbe &&
         a.probeCentre == b.probeCentre && a.meshRevision == b.meshRevision &&
         a.probed == b.probed && a.localBounds.min == b.localBounds.min &&
         a.localBounds.max == b.localBounds.max && sameLevels(a.levels, b.levels);
}

}  // namespace

FramePlan FramePlanner::layout(const std::vector<PlannedObject>& objects,
                               const CaptureContext& context) {
  FramePlan plan;
  for (ProbePlan& probe : planner::probesWithReaders(objects)) {
    plan.probes.push_back(std::move(probe));
    ProbePlan& laid = plan.probes.back();
    decideStorageFor(laid, objects, context);
    laid.filterFaces = 0;  // which levels there are; nothing is filtered here
    if (objects[static_cast<size_t>(laid.reflector)].ownsLightProbe) keepColoursOnly(laid, objects);
  }
  std::vector<int> skyLevels;  // which levels there are; nothing is filtered here
  uint64_t skyContent = 0;
  planner::decideSkyFiltering(plan, objects, context, skyLevels, skyContent);
  plan.filterSky = false;
  plan.skyFilterSamples = 0.0;
  for (const PlannedObject& o : objects) plan.models.push_back(o.model);
  return plan;
}

const ProbePlan* FramePlan::probeOf(int object) const {
  for (const ProbePlan& p : probes) {
    if (!p.lightOnly && contains(p.members, object)) return &p;
  }
  return nullptr;
}

const ProbePlan* FramePlan::irradianceOf(int object) const {
  for (const ProbePlan& p : probes) {
    if (contains(p.diffuseReaders, object)) return &p;
  }
  return nullptr;
}

bool FramePlan::traces(int object) const {
  for (const ProbeLayout& t : traced) {
    if (contains(t.members, object)) return true;
  }
  return false;
}

bool FramePlan::tracesGeneral(int object) const {
  return contains(generalTracers, object);
}

bool tracedForNarrowLobe(const SceneObject::Look& look, const AccuracySettings& accuracy) {
  const bool reflector = look.material == Material::Mirror || look.material == Material::Glass;
  return accuracy.search == Search::Planned && accuracy.narrowLobeRays > 0 && reflector &&
         look.rough() && look.roughness < kNarrowLobeRoughness;
}

int narrowLobeRaysOf(const SceneObject::Look& look, const AccuracySettings& accuracy) {
  if (look.material != Material::Glass) return accuracy.narrowLobeRays;
  return std::max(accuracy.narrowLobeRays / 2, 1);
}

int FramePlan::lobeRaysOf(int object) const {
  const size_t i = static_cast<size_t>(object);
  return i < lobeRays.size() ? lobeRays[i] : 0;
}

const ProbeLayout* FramePlan::layoutOf(int object) const {
  if (const ProbePlan* probe = probeOf(object)) return probe;
  for (const ProbeLayout& t : traced) {
    if (contains(t.members, object)) return &t;
  }
  return nullptr;
}

int FramePlan::facesCaptured() const {
  int n = 0;
  for (const ProbePlan& p : probes) n += static_cast<int>(p.faces.size());
  return n;
}

void FramePlanner::trackChanges(const std::vector<PlannedObject>& objects) {
  if (objects.size() != previous_.size()) {
    // A different object list: every object is new, every probe starts over.
    previous_ = objects;
    stateVersions_.assign(objects.size(), 1);
    contentVersions_.assign(objects.size(), 1);
    movedNow_.assign(objects.size(), true);
    probes_.clear();
    return;
  }
  for (size_t i = 0; i < objects.size(); ++i) {
    movedNow_[i] = !sameState(objects[i], previous_[i]);
    if (movedNow_[i]) {
      ++stateVersions_[i];
      previous_[i] = objects[i];
    }
  }
}

FramePlanner::Staleness FramePlanner::faceStaleness(const ProbeMemory& probe, int face,
                                                    const std::vector<int>& visibleNow) const {
  const FaceMemory& memory = probe.faces[static_cast<size_t>(face)];
  if (!memory.captured) return Staleness::Changed;
  if (visibleNow != memory.visible) return Staleness::Changed;  // something entered or left
  Staleness result = Staleness::Fresh;
  for (int i : visibleNow) {
    const size_t k = static_cast<size_t>(i);
    if (stateVersions_[k] != memory.stateVersions[k]) return Staleness::Changed;
    if (contentVersions_[k] != memory.contentVersions[k]) result = Staleness::BounceOnly;
  }
  return result;
}

FramePlanner::ProbeMemory& FramePlanner::memoryOf(int reflector) {
  auto memoryIt = std::find_if(probes_.begin(), probes_.end(),
                               [&](const ProbeMemory& m) { return m.reflector == reflector; });
  if (memoryIt == probes_.end()) {
    probes_.push_back(ProbeMemory{});
    memoryIt = std::prev(probes_.end());
    memoryIt->reflector = reflector;
  }
  return *memoryIt;
}

FacePlan FramePlanner::planFace(const ProbePlan& probe, int face, std::vector<DrawItem> draws,
                                const std::vector<PlannedObject>& objects,
                                const CaptureContext& context, const PlannerSettings& settings,
                                FaceMemory& memory) const {
  memory.captured = true;
  memory.visible.clear();
  for (const DrawItem& d : draws) memory.visible.push_back(d.object);
  memory.stateVersions = stateVersions_;
  memory.contentVersions = contentVersions_;
  const int layers = planner::faceStoresTwoLayers(probe.layers, draws.size(), context) ? 2 : 1;
  // The second layer is beyond the course's capture: culled and coarser under any policy.
  std::vector<DrawItem> secondLayer;
  if (layers == 2) {
    secondLayer = drawsFor(objects, probe.members, probe.centre, face, context, false,
                           settings.captureLod * kSecondLayerDetail);
  }
  return FacePlan{face, std::move(draws), layers, std::move(secondLayer)};
}

FramePlanner::FaceDraws FramePlanner::faceDraws(const ProbePlan& probe,
                                                const std::vector<PlannedObject>& objects,
                                                const CaptureContext& context,
                                                const PlannerSettings& settings) const {
  // A probe kept for its diffuse readers alone leaves them out too (a reader would otherwise
  // light itself with its own image), and is drawn at its own face size.
  std::vector<int> left = probe.members;
  if (probe.lightOnly) {
    left.insert(left.end(), probe.diffuseReaders.begin(), probe.diffuseReaders.end());
  }
  CaptureContext sized = context;
  if (probe.faceSize > 0) sized.faceSize = probe.faceSize;
  FaceDraws draws;
  for (int face = 0; face < 6; ++face) {
    draws[static_cast<size_t>(face)] =
        drawsFor(objects, left, probe.centre, face, sized,
                 settings.policy == UpdatePolicy::EveryFrame, settings.captureLod);
  }
  return draws;
}

bool FramePlanner::planCapture(ProbePlan& probe, FaceDraws draws,
                               const std::vector<PlannedObject>& objects,
                               const CaptureContext& context, const PlannerSettings& settings,
                               ProbeMemory& memory) const {
  // The probe moved, a capture option changed or it stores other layers or none: no face is
  // valid any more.
  if (probe.centre != memory.centre || !(context == memory.context) ||
      probe.faceSize != memory.faceSize || probe.layers != memory.layers ||
      probe.plainLookupSuffices != memory.plainLookupSuffices) {
    for (FaceMemory& f : memory.faces) f.captured = false;
    memory.centre = probe.centre;
    memory.context = context;
    memory.faceSize = probe.faceSize;
    memory.layers = probe.layers;
    memory.plainLookupSuffices = probe.plainLookupSuffices;
  }

  std::array<Staleness, 6> staleness{};
  std::vector<int> stale;  // faces that need a redraw, in face order
  for (int face = 0; face < 6; ++face) {
    const size_t f = static_cast<size_t>(face);
    std::vector<int> visible;
    for (const DrawItem& d : draws[f]) visible.push_back(d.object);
    staleness[f] = settings.policy == UpdatePolicy::EveryFrame
                       ? Staleness::Changed
                       : faceStaleness(memory, face, visible);
    if (staleness[f] != Staleness::Fresh) stale.push_back(face);
  }

  bool capturedReal = false;
  for (int face : chooseFaces(stale, settings, memory)) {
    const size_t f = static_cast<size_t>(face);
    capturedReal |= staleness[f] == Staleness::Changed;
    probe.faces.push_back(
        planFace(probe, face, std::move(draws[f]), objects, context, settings, memory.faces[f]));
  }
  return capturedReal;
}

FramePlan FramePlanner::plan(const std::vector<PlannedObject>& objects,
                             const CaptureContext& context, const PlannerSettings& settings,
                             const PlannerView& view) {
  trackChanges(objects);
  FramePlan plan;
  choices_.clear();
  narrowTraced_.clear();
  std::vector<int> recapturedForRealChange;
  for (ProbePlan& probe : planner::probesWithReaders(objects)) {
    decideStorageFor(probe, objects, context);
    const bool own = objects[static_cast<size_t>(probe.reflector)].ownsLightProbe;
    if (own) keepColoursOnly(probe, objects);
    ProbeMemory& memory = memoryOf(probe.reflector);
    // Culled once, for the cost and the capture; the exact mode traces without weighing.
    FaceDraws draws;
    const bool traced = context.accuracy.search == Search::Exact &&
                        std::all_of(probe.members.begin(), probe.members.end(), [&](int m) {
                          return planner::traceable(objects[static_cast<size_t>(m)]);
                        });
    const bool readers = !probe.diffuseReaders.empty();
    if (!traced || readers) draws = faceDraws(probe, objects, context, settings);
    if (chooseProbeMethod(probe, draws, objects, context, settings, view, memory) ==
        Method::Trace) {
      memory.filteredLevels.clear();  // a trace keeps no filtered levels either
      plan.traced.push_back(static_cast<ProbeLayout&>(probe));
      if (!readers) continue;
      // Kept alive for its diffuse readers: the colours they take their light from, nothing
      // more. (Its reflectors see their own rays, so their looks do not change with it.)
      keepColoursOnly(probe, objects);
      draws = faceDraws(probe, objects, context, settings);
      planCapture(probe, std::move(draws), objects, context, settings, memory);
      probe.projectIrradiance = !probe.faces.empty();
      plan.probes.push_back(std::move(probe));
      continue;
    }
    // What an object's own light probe holds changes no one's look (probe light is one bounce).
    if (planCapture(probe, std::move(draws), objects, context, settings, memory) && !own) {
      recapturedForRealChange.insert(recapturedForRealChange.end(), probe.members.begin(),
                                     probe.members.end());
    }
    planner::decideFiltering(probe, memory.filteredLevels);
    probe.projectIrradiance = readers && !probe.faces.empty();
    plan.probes.push_back(std::move(probe));
  }
  // The exact mode traces every mirror and glass, a static skybox's users too.
  if (context.accuracy.search == Search::Exact) {
    for (size_t i = 0; i < objects.size(); ++i) {
      const PlannedObject& o = objects[i];
      if (!planner::traceable(o) || plan.layoutOf(static_cast<int>(i))) continue;
      plan.traced.push_back(
          ProbeLayout{static_cast<int>(i), {static_cast<int>(i)}, planner::worldCentreOf(o)});
    }
  }
  plan.narrowTraced = narrowTraced_;
  plan.lobeRays.assign(objects.size(), 0);
  for (const ProbeLayout& t : plan.traced) {
    for (int m : t.members) {
      if (planner::needsGeneralTracer(objects, m)) plan.generalTracers.push_back(m);
      const PlannedObject& o = objects[static_cast<size_t>(m)];
      if (!o.look.rough()) continue;
      const bool narrow = contains(narrowTraced_, m);  // (else the weighing's own trace)
      plan.lobeRays[static_cast<size_t>(m)] =
          narrow ? narrowLobeRaysOf(o.look, context.accuracy) : context.accuracy.lobeRays;
    }
  }
  planner::decideSkyFiltering(plan, objects, context, skyFilteredLevels_, skyFilteredContent_);
  // Mirrors whose cube changed look different from the next frame on.
  for (int r : recapturedForRealChange) ++contentVersions_[static_cast<size_t>(r)];
  ++frameIndex_;
  for (const PlannedObject& o : objects) plan.models.push_back(o.model);
  return plan;
}

}  // namespace reflect
