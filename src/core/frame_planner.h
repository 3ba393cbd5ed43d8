// Decides, each frame, the least capture work the scene needs: which probes to capture, which of
// their faces, and which objects (at which level of detail) to draw into each face.
// Plain C++ without GL, so every rule is unit-tested. The driver is frame_planner.cpp; its parts
// are update_policy.cpp, probe_storage.cpp, method_choice.cpp and planner_draws.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/accuracy_settings.h"
#include "core/mesh_data.h"
#include "core/method_cost.h"
#include "core/probe_layout.h"
#include "core/scene.h"

namespace reflect {

enum class UpdatePolicy {
  EveryFrame,    // the course: six faces, every object but the reflector, every frame
  WhenChanged,   // a face is redrawn only when what it shows changed (exact; the default)
  TimeSliced,    // as WhenChanged, but at most `facesPerFrame` faces a frame (may lag)
  EveryNFrames,  // as WhenChanged, but only on every `everyN`-th frame (may lag)
};

const char* policyName(UpdatePolicy policy);
// Accepts "every-frame", "when-changed", "time-sliced", "every-n"; false if unknown.
bool parsePolicy(const std::string& text, UpdatePolicy* policy);

struct PlannerSettings {
  UpdatePolicy policy = UpdatePolicy::WhenChanged;
  int facesPerFrame = 2;  // TimeSliced
  int everyN = 4;         // EveryNFrames
  // Capture level of detail: in each face an object is drawn with its coarsest level that still
  // has this many triangles per pixel of its projected bounding disc; 0 turns LOD off (full
  // detail). The default is the coarsest value that keeps the reflector as close to the exact
  // reference as full detail does (within 0.1 dB PSNR and +1 point of pixels off by more than 32
  // levels) on the default scene and on a figure of the course model's weight: `reflect bench
  // --lod-sweep`.
  float captureLod = 0.5f;
  // View level of detail: the same rule for the main camera's pass; 0 (the default) draws every
  // object at full detail there.
  float viewLod = 0.0f;
  // The largest number of frames a face may lag behind the scene under this policy.
  int maxStalenessFrames() const;
  bool operator==(const PlannerSettings&) const = default;
};

// One level of detail of an object's mesh (the pointer is borrowed for the plan() call).
struct PlannedLevel {
  size_t triangles = 0;
  const std::vector<MeshChunk>* chunks = nullptr;  // null or empty: cull the object as a whole
};

// What the planner needs to know of one scene object this frame.
struct PlannedObject {
  Bounds localBounds;
  glm::mat4 model{1.0f};
  glm::vec3 colour{1.0f};
  SceneObject::Look look{};     // its material, as other probes' captures show it
  uint32_t meshRevision = 0;    // the generation of the object's mesh: new when it is replaced
  bool probed = false;          // samples a live probe of its own (mirror, glass, cube-textured)
  bool probeLit = false;        // Phong lit by the nearest live probe's irradiance (Ambient::Probe)
  bool ownsLightProbe = false;  // ... by an irradiance probe of its own (Ambient::OwnProbe)
  // Probed objects with the same group >= 0 share one probe at the centre of their joint bounds
  // (cheaper, less exact: they do not see each other); -1 = a probe of its own.
  int probeGroup = -1;
  std::optional<glm::vec3> probeCentre;  // overrides the bounds centre (ungrouped probes)
  std::vector<PlannedLevel> levels;      // 0 = full detail; empty: one level, no chunks
};

// Everything else a capture depends on, compared by value: any change recaptures every face.
struct CaptureContext {
  glm::vec3 lightingEye{0.0f};  // the course lights captures from the main camera's eye
  int faceSize = 256;
  float near = 1.0f;
  float far = 100.0f;
  PhongLight light;
  glm::vec3 clearColour{0.4f};
  uint64_t skyboxContent = 0;  // a hash of the skybox's pixels (0: none)
  AccuracySettings accuracy;
  float captureLod = 0.0f;
  int skyFaceSize = 0;  // the skybox's face size, for its prefiltered levels (0: none)
  bool operator==(const CaptureContext&) const = default;
};

struct DrawItem {
  int object = 0;
  int lod = 0;
  std::vector<IndexRange> ranges;  // the visible chunks; empty = the whole mesh
  size_t triangles = 0;            // in `ranges` (0 when the level's size is unknown)
};

struct FacePlan {
  int face = 0;
  std::vector<DrawItem> draws;
  // Depth layers this face stores: 2 only in a two-layer probe, and only where something in the
  // face can hide something else (two objects, or one in front of the sky); a face of floor
  // alone needs one pass, not three.
  int layers = 1;
  // What the second layer's peel draws (layers == 2; capture pass 2, what the nearest surfaces
  // hide): the objects of `draws`, each culled to the face by its chunks and at the coarsest
  // level with kSecondLayerDetail of the capture LOD's triangles per pixel (full detail when
  // capture LOD is off). Pass 3, where the nearest objects end, draws `draws`: their backs must
  // be those of the meshes the first layer stored.
  std::vector<DrawItem> secondLayerDraws;
};

// What the nearest surfaces hide is seen only by the rays that pass behind them: the second
// layer's peel draws each object with this fraction of the triangles per pixel the first layer's
// get. In llvmpipe that pass was bound by the figures' triangles (every figure whole into every
// face, at full detail). Measured against full detail on the held-out times (docs/accuracy.md,
// "The second layer's detail and the pyramid's faces"): the same pixels at 256x256; coarse backs
// (pass 3) moved single times by up to 0.3 dB, so pass 3 keeps the first layer's detail.
inline constexpr float kSecondLayerDetail = 1.0f / 16.0f;

// A probe (who samples it, where it captures from), what it stores and the faces it redraws
// this frame.
struct ProbePlan : ProbeLayout {
  std::vector<FacePlan> faces;  // only the faces to redraw this frame
  // Depth layers to store (hierarchical search): 2 only when something in the probe's view can
  // hide something else from it (two objects in one face, or one in front of the sky).
  int layers = 1;
  // Everything the probe sees is so far, compared with how far its reflectors reach from its
  // centre, that the plain lookup is within half a texel (plainLookupWithinHalfTexel), or none of
  // its reflectors is a mirror or glass (a cube-textured object looks its cube up by its own
  // rule): no search, and no depths stored for one.
  bool plainLookupSuffices = false;
  // Rough mirrors (core/ggx.h): the prefiltered levels the probe's readers need (ascending, from
  // 1 to accuracy.roughLevels; level 0 is the capture itself), empty when none is rough: then
  // there is no filtered texture and no filter pass. `filterFaces` (bit f for face f): the faces
  // whose levels are filtered this frame: all six when a face was captured (a lobe reads across
  // face edges) or the levels needed changed, else none.
  std::vector<int> roughLevels{};
  unsigned filterFaces = 0;
  // Rough readers that sample their lobes from the capture itself (AccuracySettings::lobeTaps):
  // the probe keeps its colours' box chain, and has no prefiltered levels.
  bool lobeTapReaders = false;
  // Diffuse light (Ambient::Probe): the probe-lit objects nearest this probe, which take their
  // ambient from its irradiance (nearestProbe, core/probe_layout.h), and whether that irradiance
  // is projected again this frame (it has readers and a face was redrawn).
  std::vector<int> diffuseReaders{};
  bool projectIrradiance = false;
  // Captured for its diffuse readers alone: its reflectors' rays are traced (FramePlan::traced),
  // so nothing searches or filters it; it stores colours only (one layer, no depths).
  bool lightOnly = false;
  // Its faces' size when it is not the scene's (a probe-lit object's own: kIrradianceFaceSize;
  // one read only by rough mirrors' lobe taps: planner::lobeTapFaceSize).
  int faceSize = 0;
};

// The plain lookup (the cube map along the ray's direction d) is off by the parallax angle
// between d and the direction from the probe centre to what the ray meets. For a ray from p,
// |p| <= r, meeting q = p + t d at |q| >= D > r, that angle is the triangle (centre, p, q)'s angle
// at q, and by the law of sines sin(angle) = |p| sin(angle at p) / |q| <= r / D (the angle is
// acute: it faces the shorter side): at most asin(r / D), reached when |p| = r, d is
// perpendicular to p and |q| = D.
// Half a texel, as an angle: a face point (s, t) is off by less than half a texel (1 / N of s and
// of t, a texel being 2 / N) when its direction is closer than the nearest of the great circles
// s = s0 +- 1 / N, t = t0 +- 1 / N around it. The angle from the direction (s, t, 1) to the great
// circle s = c is asin(|s - c| / (sqrt(1 + c^2) sqrt(1 + s^2 + t^2))), smallest at the face's
// corners (c, s, t -> 1): asin(1 / (sqrt(6) N)) > 0.4082 / N (halfTexelAngle). (Not 0.4714 / N,
// the rate sqrt(1 + t^2) / (1 + s^2 + t^2) of the angle along s alone at the corner, sqrt(2) / 3:
// a direction error along the corner's diagonal moves s by half a texel at 1 / (sqrt(6) N).)
// So the plain lookup is within half a texel wherever asin(r / D) < halfTexelAngle(N), that is
// r < D sin(halfTexelAngle(N)). `reach`: the reflectors' farthest point from the centre;
// `nearest`: the nearest surface the probe can store (infinity for the sky alone).
float halfTexelAngle(int faceSize);
bool plainLookupWithinHalfTexel(float reach, float nearest, int faceSize);

// Everything a frame's passes need to know: the capture renders `faces`, and the main pass binds
// each probed object to its probe's cube and centre from here, or traces its rays.
struct FramePlan {
  std::vector<ProbePlan> probes;  // one per captured probe, even when nothing is redrawn
  // Reflectors whose rays are traced this frame (search: exact, or planned where tracing is the
  // cheaper): who they are and the centre their error is measured from. No probe, no face.
  std::vector<ProbeLayout> traced;
  // The traced reflectors whose rays need the general tracer (planner::needsGeneralTracer).
  std::vector<int> generalTracers;
  // Rough mirrors traced only for being too narrow for the capture (tracedForNarrowLobe), where
  // the weighing chose to capture them.
  std::vector<int> narrowTraced;
  // Per object, the lobe rays a pixel of it traces in the main pass: narrowLobeRays for those of
  // `narrowTraced`, accuracy.lobeRays for any other traced rough mirror or glass, 0 for the rest.
  // (A traced rough mirror seen in a capture is a second bounce, seen small: it traces its
  // lobe's centre alone.)
  std::vector<int> lobeRays;
  // The static skybox read by rough mirrors or frosted glass (environment: skybox): the
  // prefiltered levels they need (as ProbePlan::roughLevels, for the sky's face size; empty when
  // no skybox reader is rough: then the sky has no filtered cube), and whether the sky is
  // filtered this frame (the levels or the skybox changed: the sky is static, so once).
  // `skyFilterSamples`: what that filter takes this frame (texels x samples), 0 in the frames it is
  // not filtered.
  std::vector<int> skyRoughLevels{};
  bool filterSky = false;
  double skyFilterSamples = 0.0;
  // Each object's model matrix this frame, in the scene's order (PlannedObject::model): every
  // pass draws and traces with these, so no renderer computes a placement again.
  std::vector<glm::mat4> models;
  int facesCaptured() const;
  const glm::mat4& modelOf(int object) const { return models.at(static_cast<size_t>(object)); }
  // The probe object `object` samples, or null (none, or its rays are traced).
  const ProbePlan* probeOf(int object) const;
  // The probe whose irradiance probe-lit `object` takes, or null (not probe-lit, or no probe).
  const ProbePlan* irradianceOf(int object) const;
  bool traces(int object) const;
  bool tracesGeneral(int object) const;
  int lobeRaysOf(int object) const;
  // Where `object`'s reflection is measured from: its probe's or its traced layout's centre.
  const ProbeLayout* layoutOf(int object) const;
};

// A rough mirror or frosted glass whose lobe is too narrow to be read from a capture: a
// mirror's neighbours' reflections are discs a few degrees wide, which a fixed set of lobe taps
// draws as rings and the prefiltered levels as blurs of the wrong width (roughness 0.25: 29.96 dB
// with 16 taps, 29.55 prefiltered, 39.22 traced with 8 lobe rays; roughness 0.5: 35.77 with
// taps, 33.85 traced with 8 rays and 35.56 with 12); what glass's light through shows, the lens
// draws as a few sharp copies (0.25: 30.90 dB with taps, 34.53 traced with 4 rays a lobe,
// held out; docs/rough.md). Under search: planned it is traced where the weighing chose to
// capture it, with narrowLobeRays rays (FramePlan::narrowTraced): true for such a look under
// those settings.
inline constexpr float kNarrowLobeRoughness = 0.375f;
bool tracedForNarrowLobe(const SceneObject::Look& look, const AccuracySettings& accuracy);
// The lobe rays such a look's pixel traces: narrowLobeRays for a mirror; for glass half as many
// (at least 1) for each of its two lobes, the reflection and the light through, so that a
// pixel casts as many rays as a mirror's.
int narrowLobeRaysOf(const SceneObject::Look& look, const AccuracySettings& accuracy);

// What the planner knows of the main camera, to weigh tracing (a cost per pixel on screen)
// against capturing. pixelsPerTangent 0: no view; search: planned then captures.
struct PlannerView {
  glm::vec3 eye{0.0f};
  float pixelsPerTangent = 0.0f;  // half the viewport height over tan(fovY / 2)
  float pixels = 0.0f;            // the viewport's width x height
};

// The main pass's draws: every object, each at the coarsest level that still has
// settings.viewLod triangles per pixel of its projected bounding disc (full
// detail when that is 0). pixelsPerTangent: half the viewport height over tan(fovY / 2).
std::vector<DrawItem> planViewDraws(const std::vector<PlannedObject>& objects, const glm::vec3& eye,
                                    float pixelsPerTangent, const PlannerSettings& settings);

// Pixels on screen of a sphere of `radius` at `centre` (its projected disc, at most the
// viewport); 0 without a view.
float screenPixels(const glm::vec3& centre, float radius, const PlannerView& view);

// The planner's estimate of a probe's two methods this frame, and what it picked.
struct MethodChoice {
  int reflector = 0;
  Method method = Method::Capture;
  TraceWork trace;
  CaptureWork capture;
  double traceMs = 0.0;
  double captureMs = 0.0;
};

class FramePlanner {
 public:
  FramePlan plan(const std::vector<PlannedObject>& objects, const CaptureContext& context,
                 const PlannerSettings& settings, const PlannerView& view = {});
  // The coefficients search: planned weighs the methods with.
  void setCosts(const MethodCosts& costs) { costs_ = costs; }
  const MethodCosts& costs() const { return costs_; }
  // What plan() weighed for each probe under search: planned, the last frame.
  const std::vector<MethodChoice>& choices() const { return choices_; }
  // The probes alone, with no faces to capture and nothing remembered: for a pass that reads the
  // cubes a plan() already captured.
  static FramePlan layout(const std::vector<PlannedObject>& objects, const CaptureContext& context);
  // Forget every capture (the GL context was lost, or the caller wants a clean start).
  void invalidate() {
    probes_.clear();
    skyFilteredLevels_.clear();
    skyFilteredContent_ = 0;
  }

 private:
  // What a face showed when it was last drawn: which objects, and each object's versions then.
  struct FaceMemory {
    bool captured = false;
    std::vector<int> visible;
    std::vector<uint32_t> stateVersions;    // per object
    std::vector<uint32_t> contentVersions;  // per object (reflectors: their cube's content)
  };
  struct ProbeMemory {
    int reflector = -1;
    Method method = Method::Capture;
    bool narrowForced = false;  // traced for a narrow lobe where the weighing chose the capture
    glm::vec3 centre{0.0f};
    int faceSize = 0;  // ProbePlan::faceSize
    int layers = 1;
    bool plainLookupSuffices = false;  // (the capture then stores no depths)
    std::vector<int> filteredLevels;   // the prefiltered levels as last filtered
    CaptureContext context;
    std::array<FaceMemory, 6> faces;
    int sliceCursor = 0;
  };
  enum class Staleness { Fresh, BounceOnly, Changed };
  // What each face of a probe shows this frame (drawsFor), culled once: the cost of a capture
  // and the capture itself read the same draws.
  using FaceDraws = std::array<std::vector<DrawItem>, 6>;
  FaceDraws faceDraws(const ProbePlan& probe, const std::vector<PlannedObject>& objects,
                      const CaptureContext& context, const PlannerSettings& settings) const;

  ProbeMemory& memoryOf(int reflector);
  // Trace the probe's reflectors or capture it (search: exact traces, planned weighs the two);
  // a change of method forgets the probe's faces.
  Method chooseProbeMethod(const ProbePlan& probe, const FaceDraws& draws,
                           const std::vector<PlannedObject>& objects, const CaptureContext& context,
                           const PlannerSettings& settings, const PlannerView& view,
                           ProbeMemory& memory);
  // Plans the faces a captured probe redraws this frame into probe.faces, and remembers what
  // they show. True when one is redrawn for a real change (not only a bounce).
  bool planCapture(ProbePlan& probe, FaceDraws draws, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context, const PlannerSettings& settings,
                   ProbeMemory& memory) const;
  FacePlan planFace(const ProbePlan& probe, int face, std::vector<DrawItem> draws,
                    const std::vector<PlannedObject>& objects, const CaptureContext& context,
                    const PlannerSettings& settings, FaceMemory& memory) const;
  // The stale faces the policy redraws this frame (update_policy.cpp).
  std::vector<int> chooseFaces(const std::vector<int>& stale, const PlannerSettings& settings,
                               ProbeMemory& memory) const;
  Staleness faceStaleness(const ProbeMemory& probe, int face,
                          const std::vector<int>& visibleNow) const;
  void trackChanges(const std::vector<PlannedObject>& objects);
  // Search: planned: what each method would cost `probe` this frame.
  MethodChoice weigh(const ProbePlan& probe, const FaceDraws& draws,
                     const std::vector<PlannedObject>& objects, const CaptureContext& context,
                     const PlannerSettings& settings, const PlannerView& view) const;
  // The objects a face shows: with `whole`, every object at full detail (the course's capture);
  // otherwise those the face may see, culled by chunks, at the coarsest level with
  // `trianglesPerPixel` (0: full detail).
  std::vector<DrawItem> drawsFor(const std::vector<PlannedObject>& objects,
                                 const std::vector<int>& members, const glm::vec3& centre, int face,
                                 const CaptureContext& context, bool whole,
                                 float trianglesPerPixel) const;

  std::vector<PlannedObject> previous_;
  std::vector<uint32_t> stateVersions_;  // per object: bumped each frame its state changes
  // Per object: bumped when a reflector's cube was redrawn for a real change, so probes that
  // show this mirror redraw once (one bounce), without two mirrors re-triggering each other.
  std::vector<uint32_t> contentVersions_;
  std::vector<ProbeMemory> probes_;
  std::vector<int> skyFilteredLevels_;  // the sky's prefiltered levels as last filtered
  uint64_t skyFilteredContent_ = 0;     // and the skybox they were filtered from
  std::vector<bool> movedNow_;          // per object: its state changed this frame
  uint64_t frameIndex_ = 0;
  MethodCosts costs_ = MethodCosts::softwareRenderer();
  std::vector<MethodChoice> choices_;
  std::vector<int> narrowTraced_;  // this frame's objects traced for a narrow lobe alone
};

}  // namespace reflect
