// Pick a pixel on a rough mirror or frosted glass (docs/rough.md): which GGX lobe the pixel
// averages and how the frame drew it: sampled with lobe taps from the probe's capture, read from
// its prefiltered levels (which two, at what face sizes) or traced with lobe rays; a reader of the
// static skybox from the sky's own prefiltered levels. The explanation's rays and
// lookups follow the lobe's centre (the reflected ray); these lines say what lies around it. The
// facts are the renderer's own: the accuracy settings, the frame plan and the probe's cube as
// captured.
#pragma once

#include <string>
#include <vector>

#include "app/demo.h"
#include "core/ggx.h"

namespace reflect {

struct LobeExplanation {
  enum class Source {
    None,            // a perfect mirror or polished glass (roughness 0), or neither: no lobe
    Prefiltered,     // read from the probe's prefiltered levels
    Traced,          // traced with lobeRays rays (search: exact, or planned found tracing cheaper)
    NotFiltered,     // a probe without the levels this roughness reads (none captured this frame)
    PrefilteredSky,  // read from the static skybox's prefiltered levels (environment: skybox)
    LobeTaps,        // sampled with lobeTaps taps from the probe's capture (its box chain)
  };
  Source source = Source::None;
  float roughness = 0.0f;
  float alpha = 0.0f;  // ggxAlpha(roughness)
  // Prefiltered: the level read, roughness x usableLevels (as the renderer's u_roughLod), the two
  // levels around it (0: the capture itself) and their face sizes.
  int usableLevels = 0;
  float level = 0.0f;
  RoughLevels levels;
  int lowerFaceSize = 0;
  int upperFaceSize = 0;
  int lobeRays = 0;     // traced: FramePlan::lobeRaysOf
  bool narrow = false;  // traced for being too narrow for taps (FramePlan::narrowTraced)
  int lobeTaps = 0;     // lobe taps: AccuracySettings::lobeTaps, from faces of tapFaceSize
  int tapFaceSize = 0;
  // Lobe taps of a mirror drawn with the hierarchical search: each quarter of the lobe searched
  // for its own distance (shaders/environment_lookup.glsl lobeDistances), not the centre's alone.
  bool quartersSearched = false;
  // ... and, the lobe being wide (alpha over kWideLobeAlpha), each tap blended towards where the
  // central ray met the scene where the probe's depths hold that point better (tapSeenChecked).
  bool tapsChecked = false;
  // Frosted glass: the light through it is a lobe too, read prefiltered at its own level
  // (transmissionRoughness x usableLevels, as the renderer's u_refractLod).
  bool glass = false;
  float throughRoughness = 0.0f;
  float throughLevel = 0.0f;
};

// The search the renderer drew captured object `object` with (EnvironmentBinding's rule): its
// probe's plain lookup where a search would find the same, else the captured search.
Search searchDrawnWith(const Demo& demo, int object);

// The lobe of `object` in the frame the demo drew last (Source::None where it has none).
LobeExplanation explainLobe(const Demo& demo, int object);

// The lines `reflect explain` prints (and the page's pick panel shows) for the lobe: none where
// there is no lobe. `raysShown`: the explanation draws and lists the lobe centre's rays.
std::vector<std::string> lobeLines(const LobeExplanation& lobe, bool raysShown);

}  // namespace reflect
