#include "core/frame_planner.h"

#include <algorithm>
#include <cmath>

#include "core/frustum.h"
#include "core/mesh_chunks.h"
#include "core/probe_layout.h"

namespace reflect {
namespace {

bool sameLevels(const std::vector<PlannedLevel>& a, const std::vector<PlannedLevel>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].triangles != b[i].triangles) return false;
  }
  return true;
}

bool sameState(const PlannedObject& a, const PlannedObject& b) {
  return a.model == b.model && a.colour == b.colour && a.look == b.look &&
         a.probeCentre == b.probeCentre && a.meshRevision == b.meshRevision &&
         a.probed == b.probed && a.localBounds.min == b.localBounds.min &&
         a.localBounds.max == b.localBounds.max && sameLevels(a.levels, b.levels);
}

bool contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

std::vector<ProbeLayout> probesOf(const std::vector<PlannedObject>& objects) {
  std::vector<ProbeCandidate> candidates;
  candidates.reserve(objects.size());
  for (const PlannedObject& o : objects) {
    candidates.push_back(ProbeCandidate{o.probed, o.probeGroup, o.probeCentre,
                                        transformBounds(o.localBounds, o.model)});
  }
  return layoutProbes(candidates);
}

}  // namespace

const char* policyName(UpdatePolicy policy) {
  switch (policy) {
    case UpdatePolicy::EveryFrame:
      return "every-frame";
    case UpdatePolicy::WhenChanged:
      return "when-changed";
    case UpdatePolicy::TimeSliced:
      return "time-sliced";
    case UpdatePolicy::EveryNFrames:
      return "every-n";
  }
  return "?";
}

bool parsePolicy(const std::string& text, UpdatePolicy* policy) {
  for (UpdatePolicy p : {UpdatePolicy::EveryFrame, UpdatePolicy::WhenChanged,
                         UpdatePolicy::TimeSliced, UpdatePolicy::EveryNFrames}) {
    if (text == policyName(p)) {
      *policy = p;
      return true;
    }
  }
  return false;
}

int PlannerSettings::maxStalenessFrames() const {
  switch (policy) {
    case UpdatePolicy::TimeSliced: {
      const int k = std::clamp(facesPerFrame, 1, 6);
      return (6 + k - 1) / k - 1;
    }
    case UpdatePolicy::EveryNFrames:
      return std::max(everyN, 1) - 1;
    default:
      return 0;
  }
}

float halfTexelAngle(int faceSize) {
  return 0.4082f / static_cast<float>(std::max(faceSize, 1));
}

bool plainLookupWithinHalfTexel(float reach, float nearest, int faceSize) {
  return reach < nearest * std::sin(halfTexelAngle(faceSize));
}

namespace {

float distanceToBox(const glm::vec3& p, const Bounds& box) {
  return glm::length(glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f)));
}

float farthestInBox(const glm::vec3& p, const Bounds& box) {
  return glm::length(glm::max(glm::abs(box.min - p), glm::abs(box.max - p)));
}

// What a probe stores (layers) and whether its reflectors need a search at all, from which
// objects each face can see.
void decideStorage(ProbePlan& probe, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context) {
  const bool sky = context.skyboxContent != 0;
  float reach = 0.0f;
  bool searched = false;  // a member is a mirror or glass
  // Without a sky the clear background is stored at the far plane, at least `far` away.
  float nearest = sky ? INFINITY : context.far;
  bool occlusion = false;
  std::array<int, 6> visible{};
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    const Bounds world = transformBounds(o.localBounds, o.model);
    if (contains(probe.members, static_cast<int>(i))) {
      reach = std::max(reach, farthestInBox(probe.centre, world));
      searched |= o.look.material == Material::Mirror || o.look.material == Material::Glass;
      continue;
    }
    bool seen = false;
    for (int face = 0; face < 6; ++face) {
      if (!faceMaySee(probe.centre, face, context.near, context.far, o.localBounds, o.model)) {
        continue;
      }
      seen = true;
      ++visible[static_cast<size_t>(face)];
    }
    if (seen) nearest = std::min(nearest, distanceToBox(probe.centre, world));
  }
  for (int count : visible) occlusion |= count >= 2 || (sky && count >= 1);
  const Search search = capturedSearch(context.accuracy.search);
  const bool searches = search != Search::Plain;
  probe.plainLookupSuffices =
      searches && (!searched || plainLookupWithinHalfTexel(reach, nearest, context.faceSize));
  probe.layers = search == Search::Hierarchical && context.accuracy.layers >= 2 && occlusion &&
                         !probe.plainLookupSuffices
                     ? 2
                     : 1;
}

}  // namespace

FramePlan FramePlanner::layout(const std::vector<PlannedObject>& objects,
                               const CaptureContext& context) {
  FramePlan plan;
  for (ProbeLayout& probe : probesOf(objects)) {
    plan.probes.push_back(ProbePlan{std::move(probe), {}});
    decideStorage(plan.probes.back(), objects, context);
  }
  return plan;
}

const ProbePlan* FramePlan::probeOf(int object) const {
  for (const ProbePlan& p : probes) {
    if (std::find(p.members.begin(), p.members.end(), object) != p.members.end()) return &p;
  }
  return nullptr;
}

bool FramePlan::traces(int object) const {
  for (const ProbeLayout& t : traced) {
    if (contains(t.members, object)) return true;
  }
  return false;
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

namespace {

// The world bounding sphere of an object's oriented box.
glm::vec3 worldCentreOf(const PlannedObject& o) {
  return glm::vec3(o.model * glm::vec4(o.localBounds.centre(), 1.0f));
}
float worldRadiusOf(const PlannedObject& o) {
  const glm::vec3 halfExtent = 0.5f * (o.localBounds.max - o.localBounds.min);
  const glm::mat3 m(o.model);
  return glm::length(glm::abs(m[0]) * halfExtent.x + glm::abs(m[1]) * halfExtent.y +
                     glm::abs(m[2]) * halfExtent.z);
}

bool traceable(const PlannedObject& o) {
  return o.look.material == Material::Mirror || o.look.material == Material::Glass;
}

// The coarsest level whose triangle count still covers the object's projected disc, seen from
// `centre`, at `trianglesPerPixel`; pixelsPerTangent converts the tangent of an angle to pixels
// (half the face for a 90-degree cube face). Distances and sizes from the bounding sphere of the
// oriented box.
int chooseLevel(const PlannedObject& o, const glm::vec3& centre, float pixelsPerTangent,
                float trianglesPerPixel) {
  if (trianglesPerPixel <= 0.0f || o.levels.size() < 2) return 0;
  const glm::vec3 worldCentre = worldCentreOf(o);
  const float radius = worldRadiusOf(o);
  const float distance = glm::length(worldCentre - centre);
  if (distance <= radius) return 0;  // the probe is inside or touching it
  const float pixels = radius / distance * pixelsPerTangent;
  const float wanted = trianglesPerPixel * 3.14159265f * pixels * pixels;
  int level = 0;
  while (level + 1 < static_cast<int>(o.levels.size()) &&
         static_cast<float>(o.levels[static_cast<size_t>(level + 1)].triangles) >= wanted) {
    ++level;
  }
  return level;
}

}  // namespace

float screenPixels(const glm::vec3& centre, float radius, const PlannerView& view) {
  if (view.pixelsPerTangent <= 0.0f) return 0.0f;
  const float distance = glm::length(centre - view.eye);
  if (distance <= radius) return view.pixels;  // the camera is inside it
  const float tangent = radius / std::sqrt(distance * distance - radius * radius);
  const float pixels = tangent * view.pixelsPerTangent;
  return std::min(3.14159265f * pixels * pixels, view.pixels);
}

std::vector<DrawItem> planViewDraws(const std::vector<PlannedObject>& objects, const glm::vec3& eye,
                                    float pixelsPerTangent, const PlannerSettings& settings) {
  std::vector<DrawItem> draws;
  draws.reserve(objects.size());
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    DrawItem item;
    item.object = static_cast<int>(i);
    item.lod = chooseLevel(o, eye, pixelsPerTangent, settings.viewLod);
    if (!o.levels.empty()) item.triangles = o.levels[static_cast<size_t>(item.lod)].triangles;
    draws.push_back(std::move(item));
  }
  return draws;
}

std::vector<DrawItem> FramePlanner::drawsFor(const std::vector<PlannedObject>& objects,
                                             const std::vector<int>& members,
                                             const glm::vec3& centre, int face,
                                             const CaptureContext& context, bool whole,
                                             float trianglesPerPixel) const {
  std::vector<DrawItem> draws;
  for (size_t i = 0; i < objects.size(); ++i) {
    // The probe's own reflectors are left out by identity: they surround the capture point.
    if (contains(members, static_cast<int>(i))) continue;
    const PlannedObject& o = objects[i];
    DrawItem item{static_cast<int>(i), 0, {}, 0};
    if (!o.levels.empty()) item.triangles = o.levels[0].triangles;
    if (whole) {  // the course draws every object whole into every face
      draws.push_back(std::move(item));
      continue;
    }
    if (!faceMaySee(centre, face, context.near, context.far, o.localBounds, o.model)) continue;
    // At 90 degrees one unit of tangent spans half the face.
    item.lod =
        chooseLevel(o, centre, 0.5f * static_cast<float>(context.faceSize), trianglesPerPixel);
    if (!o.levels.empty()) {
      const PlannedLevel& level = o.levels[static_cast<size_t>(item.lod)];
      item.triangles = level.triangles;
      if (level.chunks && !level.chunks->empty()) {
        item.triangles = 0;
        for (const MeshChunk& chunk : *level.chunks) {
          if (!faceMaySee(centre, face, context.near, context.far, chunk.bounds, o.model)) continue;
          appendRange(item.ranges, chunk.range);
          item.triangles += chunk.range.count / 3;
        }
        if (item.ranges.empty()) continue;  // the box reaches in, but no part of the mesh does
      }
    }
    draws.push_back(std::move(item));
  }
  return draws;
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

std::vector<int> FramePlanner::chooseFaces(const std::vector<int>& stale,
                                           const PlannerSettings& settings,
                                           ProbeMemory& memory) const {
  switch (settings.policy) {
    case UpdatePolicy::EveryFrame:
    case UpdatePolicy::WhenChanged:
      return stale;
    case UpdatePolicy::EveryNFrames:
      if (frameIndex_ % static_cast<uint64_t>(std::max(settings.everyN, 1)) == 0) return stale;
      return {};
    case UpdatePolicy::TimeSliced: {
      // Round robin from a cursor, so every stale face is reached within ceil(6/k) frames.
      const int k = std::clamp(settings.facesPerFrame, 1, 6);
      std::vector<int> chosen;
      for (int step = 0; step < 6 && static_cast<int>(chosen.size()) < k; ++step) {
        const int face = (memory.sliceCursor + step) % 6;
        if (contains(stale, face)) chosen.push_back(face);
      }
      if (!chosen.empty()) memory.sliceCursor = (chosen.back() + 1) % 6;
      std::sort(chosen.begin(), chosen.end());
      return chosen;
    }
  }
  return stale;
}

MethodChoice FramePlanner::weigh(const ProbePlan& probe, const std::vector<PlannedObject>& objects,
                                 const CaptureContext& context, const PlannerSettings& settings,
                                 const PlannerView& view) const {
  MethodChoice c;
  c.reflector = probe.reflector;
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    if (!o.levels.empty()) c.trace.triangles += static_cast<double>(o.levels[0].triangles);
    if (contains(probe.members, static_cast<int>(i))) {
      c.trace.pixels += screenPixels(worldCentreOf(o), worldRadiusOf(o), view);
    } else {
      c.trace.general |= o.look.material != Material::Phong;
    }
  }
  // Captured: the faces that show something moving are redrawn (every face, every frame, under
  // the course's policy), each with one pass, or three where two layers are stored; then every
  // mirror pixel searches.
  const bool everyFrame = settings.policy == UpdatePolicy::EveryFrame;
  const double texels = static_cast<double>(context.faceSize) * context.faceSize;
  for (int face = 0; face < 6; ++face) {
    const std::vector<DrawItem> draws = drawsFor(objects, probe.members, probe.centre, face,
                                                 context, everyFrame, settings.captureLod);
    bool moving = everyFrame;
    double triangles = 0.0;
    for (const DrawItem& d : draws) {
      moving |= movedNow_[static_cast<size_t>(d.object)];
      triangles += static_cast<double>(d.triangles);
    }
    if (!moving) continue;
    const bool hides = draws.size() >= 2 || (context.skyboxContent != 0 && !draws.empty());
    // Two layers: the nearest surfaces and their backs at the capture's detail, what they hide
    // at kSecondLayerDetail of it.
    const double passes = probe.layers == 2 && hides ? 2.0 + kSecondLayerDetail : 1.0;
    c.capture.faces += 1.0;
    c.capture.triangles += triangles * passes;
    c.capture.texels += texels * (probe.layers == 2 && hides ? 3.0 : 1.0);
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
  c.traceMs = traceCost(c.trace, costs_);
  c.captureMs = captureCost(c.capture, costs_);
  return c;
}

FramePlan FramePlanner::plan(const std::vector<PlannedObject>& objects,
                             const CaptureContext& context, const PlannerSettings& settings,
                             const PlannerView& view) {
  trackChanges(objects);
  FramePlan plan;
  choices_.clear();
  std::vector<int> recapturedForRealChange;
  const Search search = context.accuracy.search;
  for (ProbeLayout& layout : probesOf(objects)) {
    ProbePlan probe{std::move(layout), {}};
    decideStorage(probe, objects, context);
    const int reflector = probe.reflector;
    const std::vector<int>& members = probe.members;
    auto memoryIt = std::find_if(probes_.begin(), probes_.end(),
                                 [&](const ProbeMemory& m) { return m.reflector == reflector; });
    if (memoryIt == probes_.end()) {
      probes_.push_back(ProbeMemory{});
      memoryIt = std::prev(probes_.end());
      memoryIt->reflector = reflector;
    }
    ProbeMemory& memory = *memoryIt;

    // Trace its rays, or capture it. A cube-textured member's look is its cube: captured.
    const bool rays = std::all_of(members.begin(), members.end(), [&](int m) {
      return traceable(objects[static_cast<size_t>(m)]);
    });
    Method method = Method::Capture;
    if (rays && search == Search::Exact) method = Method::Trace;
    if (rays && search == Search::Planned && view.pixelsPerTangent > 0.0f) {
      MethodChoice choice = weigh(probe, objects, context, settings, view);
      choice.method = chooseMethod(choice.traceMs, choice.captureMs, memory.method, costs_);
      method = choice.method;
      choices_.push_back(choice);
    }
    if (method != memory.method) {
      for (FaceMemory& f : memory.faces) f.captured = false;  // a trace keeps no faces
      memory.method = method;
    }
    if (method == Method::Trace) {
      plan.traced.push_back(static_cast<ProbeLayout&>(probe));
      continue;
    }
    // The probe moved, a capture option changed or it stores other layers or none: no face is
    // valid any more.
    if (probe.centre != memory.centre || !(context == memory.context) ||
        probe.layers != memory.layers || probe.plainLookupSuffices != memory.plainLookupSuffices) {
      for (FaceMemory& f : memory.faces) f.captured = false;
      memory.centre = probe.centre;
      memory.context = context;
      memory.layers = probe.layers;
      memory.plainLookupSuffices = probe.plainLookupSuffices;
    }

    std::array<std::vector<DrawItem>, 6> draws;
    std::array<Staleness, 6> staleness{};
    std::vector<int> stale;  // faces that need a redraw, in face order
    for (int face = 0; face < 6; ++face) {
      const size_t f = static_cast<size_t>(face);
      draws[f] = drawsFor(objects, members, probe.centre, face, context,
                          settings.policy == UpdatePolicy::EveryFrame, settings.captureLod);
      std::vector<int> visible;
      for (const DrawItem& d : draws[f]) visible.push_back(d.object);
      staleness[f] = settings.policy == UpdatePolicy::EveryFrame
                         ? Staleness::Changed
                         : faceStaleness(memory, face, visible);
      if (staleness[f] != Staleness::Fresh) stale.push_back(face);
    }

    const std::vector<int> chosen = chooseFaces(stale, settings, memory);
    bool capturedReal = false;
    for (int face : chosen) {
      const size_t f = static_cast<size_t>(face);
      capturedReal |= staleness[f] == Staleness::Changed;
      FaceMemory& m = memory.faces[f];
      m.captured = true;
      m.visible.clear();
      for (const DrawItem& d : draws[f]) m.visible.push_back(d.object);
      m.stateVersions = stateVersions_;
      m.contentVersions = contentVersions_;
      const size_t shown = draws[f].size();
      const bool hides = shown >= 2 || (context.skyboxContent != 0 && shown >= 1);
      const int layers = probe.layers == 2 && hides ? 2 : 1;
      // The second layer is beyond the course's capture: culled and coarser under any policy.
      std::vector<DrawItem> secondLayer;
      if (layers == 2) {
        secondLayer = drawsFor(objects, members, probe.centre, face, context, false,
                               settings.captureLod * kSecondLayerDetail);
      }
      probe.faces.push_back(FacePlan{face, std::move(draws[f]), layers, std::move(secondLayer)});
    }
    if (capturedReal) {
      recapturedForRealChange.insert(recapturedForRealChange.end(), members.begin(), members.end());
    }
    plan.probes.push_back(std::move(probe));
  }
  // The exact mode traces every mirror and glass, a static skybox's users too.
  if (search == Search::Exact) {
    for (size_t i = 0; i < objects.size(); ++i) {
      const PlannedObject& o = objects[i];
      if (!traceable(o) || plan.layoutOf(static_cast<int>(i))) continue;
      plan.traced.push_back(
          ProbeLayout{static_cast<int>(i), {static_cast<int>(i)}, worldCentreOf(o)});
    }
  }
  // Mirrors whose cube changed look different from the next frame on.
  for (int r : recapturedForRealChange) ++contentVersions_[static_cast<size_t>(r)];
  ++frameIndex_;
  return plan;
}

}  // namespace reflect
