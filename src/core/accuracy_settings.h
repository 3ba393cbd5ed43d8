// The knobs that trade speed for accuracy in the capture and the lookup (measured by
// `reflect bench --sweep` against the ray-traced reference). Their names, ranges and help are in
// settings_schema.cpp.
#pragma once

#include <string>

namespace reflect {

// How a mirror or glass finds where its ray meets the captured surroundings.
enum class Search {
  // The course: the cube map looked up along the ray's direction, exact only for a world
  // infinitely far away.
  Plain,
  // The distance-impostor method (Szirmay-Kalos et al., 2005) as this project first shipped it:
  // 12 linear steps along the ray against each texel's stored distance, then 2 secant steps.
  // It can step over anything thinner than a step (shaders/linear_search.glsl).
  Linear,
  // A walk of each face's min/max depth chain that tests every texel the ray passes
  // (shaders/depth_search.glsl): nothing is stepped over.
  Hierarchical,
  // Every mirror and glass pixel's ray traced against the scene's triangles (two-level BVH,
  // core/bvh.h; shaders/exact_trace.glsl) and shaded as a capture would: no cube map at all.
  Exact,
  // Per reflector, the frame planner picks the cheaper of the two ways its cost model weighs
  // (core/method_cost.h): tracing the rays (Exact) or capturing a probe and searching it
  // (Hierarchical). Tracing is exact, so where it is the cheaper it is also the better.
  Planned,
};

const char* searchName(Search search);
// Every search, in the settings table's order.
inline constexpr Search kSearches[] = {Search::Plain, Search::Linear, Search::Hierarchical,
                                       Search::Exact, Search::Planned};
bool parseSearch(const std::string& name, Search* search);
// The search a captured probe is searched with: planned captures for the hierarchical search.
inline Search capturedSearch(Search search) {
  return search == Search::Planned ? Search::Hierarchical : search;
}

struct AccuracySettings {
  bool captureAtOrigin = false;  // the course's capture point (0,0,0), not the reflector's centre
  Search search = Search::Planned;
  // Stored depth layers per probe (hierarchical search): 1, or 2, where the second holds the
  // nearest surface behind the first that faces the probe, so a ray that passes behind a figure
  // finds what is there. The planner gives a probe its second layer only where something in its
  // capture can hide something else.
  int layers = 2;
  // Glass: 2 refracts into the object and out of its far side, 1 only at entry (the course's
  // notes).
  int glassSurfaces = 2;
  int depthBits = 24;      // capture depth buffer: 16 or 24
  bool mipmaps = false;    // trilinear lookup from a mip chain rebuilt after each capture
  bool halfFloat = false;  // RGBA16F capture colour instead of RGBA8
  bool mediump = false;    // fragment shaders at mediump instead of highp
  // Rough mirrors (core/ggx.h, docs/rough.md): the lobe taps a pixel of a captured rough mirror
  // or frosted glass reads from its probe's box chain (0: the prefiltered levels instead, the split
  // sum, which the static sky's readers always read); the prefilter pass's GGX samples per
  // texel, the number of prefiltered mip levels (level m holds roughness m / roughLevels), and
  // the fixed lobe rays a traced pixel casts.
  int lobeTaps = 16;
  int filterSamples = 32;
  int roughLevels = 5;
  int lobeRays = 16;
  // Rough mirrors and frosted glass whose lobe is too narrow for lobe taps or prefiltered levels
  // (tracedForNarrowLobe: roughness under 0.375) are traced under search: planned where the
  // weighing would capture them, with this many fixed lobe rays a pixel (glass: half as many
  // for each of its two lobes, narrowLobeRaysOf); 0: they are captured.
  int narrowLobeRays = 8;
  // Rough mirrors and frosted glass with lobe taps, captured and searched (hierarchical): each
  // quarter of the lobe (glass: of its light through, from its own exit point) searched for how
  // far its taps meet the scene (false: the central ray's distance for every tap, the default
  // before; docs/rough.md, "Each quarter searched").
  bool lobeQuarters = true;

  bool operator==(const AccuracySettings&) const = default;
  // e.g. "centre, hierarchical, layers 2, glass 2, depth 24, linear, RGBA8, highp"
  std::string describe() const;
};

}  // namespace reflect
