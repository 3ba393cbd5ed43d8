// What the frame planner's files (frame_planner.cpp, planner_draws.cpp, probe_storage.cpp,
// method_choice.cpp, update_policy.cpp) share: small rules on planned objects. Internal to the
// planner: callers include core/frame_planner.h.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/frame_planner.h"
#include "core/probe_layout.h"

namespace reflect::planner {

bool contains(const std::vector<int>& list, int value);

// The probes the objects ask for (grouped, placed), before any is planned.
std::vector<ProbeLayout> probesOf(const std::vector<PlannedObject>& objects);

// The probes laid out (probesOf), each with the probe-lit objects nearest it as its
// diffuseReaders; nothing else of the plan decided.
std::vector<ProbePlan> probesWithReaders(const std::vector<PlannedObject>& objects);

// The world bounding sphere of an object's oriented box.
glm::vec3 worldCentreOf(const PlannedObject& o);
float worldRadiusOf(const PlannedObject& o);

// A mirror or glass: its rays can be traced.
bool traceable(const PlannedObject& o);
// Whether the rays traced from object `object` need the general tracer: they can meet another
// object that is not Phong (a mirror, glass or a cube-textured object), or glass's own far side.
// The rest meet Phong surfaces or the sky alone, which the Phong-only tracer draws for less. The
// one rule: the planner costs it (weigh) and records it (FramePlan::tracesGeneral) for the
// renderer's program.
bool needsGeneralTracer(const std::vector<PlannedObject>& objects, int object);

// The coarsest level whose triangle count still covers the object's projected disc, seen from
// `centre`, at `trianglesPerPixel`; pixelsPerTangent converts the tangent of an angle to pixels
// (half the face for a 90-degree cube face). Distances and sizes from the bounding sphere of the
// oriented box.
int chooseLevel(const PlannedObject& o, const glm::vec3& centre, float pixelsPerTangent,
                float trianglesPerPixel);

// What a probe stores (layers) and whether its reflectors need a search at all, from which
// objects each face can see.
void decideStorage(ProbePlan& probe, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context);

// The roughnesses of the lobes a reader reads from prefiltered levels: none for a perfect
// surface, a rough mirror's own, rough glass's own (its reflection) and its transmission's
// (transmissionRoughness, core/ggx.h).
std::vector<float> lobeRoughnesses(const SceneObject::Look& look);

// Whether something in a face that shows `shown` objects can hide something else: two objects,
// or one in front of the sky. A probe stores a second layer only if one of its faces can, and a
// face of a two-layer probe keeps two only then: the one rule for the probe's storage, its faces'
// plan and the cost of a capture.
bool faceCanHide(size_t shown, const CaptureContext& context);
inline bool faceStoresTwoLayers(int probeLayers, size_t shown, const CaptureContext& context) {
  return probeLayers == 2 && faceCanHide(shown, context);
}

// Whether a probe's rough readers sample their lobes from its capture (ProbePlan::lobeTapReaders).
bool readsLobeTaps(const ProbeLayout& probe, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context);
// The face size a probe whose readers are all rough mirrors sampling lobe taps needs
// (ProbePlan::faceSize; 0: the scene's): the scene's halved while each reader's tap at its lobe's
// peak still covers kMinTapFootprintTexels texels across, and never under kMinLobeTapFaceSize.
// A probe with other readers (sharp, glass, diffuse) keeps the scene's size.
inline constexpr float kMinTapFootprintTexels = 4.0f;
inline constexpr int kMinLobeTapFaceSize = 32;
int lobeTapFaceSize(const ProbePlan& probe, const std::vector<PlannedObject>& objects,
                    const CaptureContext& context);
// The prefiltered levels a probe's rough readers need (ProbePlan::roughLevels), sorted; none
// where they take lobe taps.
std::vector<int> roughLevelsOf(const ProbeLayout& probe, const std::vector<PlannedObject>& objects,
                               const CaptureContext& context);

// The faces to filter this frame (ProbePlan::filterFaces) given probe.roughLevels and the levels
// filtered before (`filtered`, updated).
void decideFiltering(ProbePlan& probe, std::vector<int>& filtered);

// The static sky's prefiltered levels, those its rough readers (environment: skybox, not traced
// this frame) need at context.skyFaceSize, into plan.skyRoughLevels; plan.filterSky when they
// or the skybox changed since they were last filtered (`filtered` from `filteredContent`, both
// updated), with the samples that takes.
void decideSkyFiltering(FramePlan& plan, const std::vector<PlannedObject>& objects,
                        const CaptureContext& context, std::vector<int>& filtered,
                        uint64_t& filteredContent);

// What the prefilter pass does a frame for `levels` of a probe of faceSize: texels filtered times
// samples each, every face of every level (ProbePlan::filterFaces is all six or none).
double filterSamplesFor(const std::vector<int>& levels, int faceSize, int samples);

}  // namespace reflect::planner
