#include "app/pixel_lobe.h"

#include <algorithm>
#include <cstdio>

#include "app/text_line.h"

namespace reflect {
namespace {

bool has(const std::vector<int>& levels, int level) {
  return level == 0 || std::find(levels.begin(), levels.end(), level) != levels.end();
}

// The levels a lobe reads from a filtered cube whose source has faceSize (as the renderer binds
// it), and whether `kept` (the levels filtered this frame) holds them.
void readLevels(int faceSize, const std::vector<int>& kept, bool made, int roughLevels,
                LobeExplanation::Source source, LobeExplanation& lobe) {
  lobe.usableLevels = usableRoughLevels(roughLevels, faceSize);
  lobe.level = std::clamp(lobe.roughness, 0.0f, 1.0f) * static_cast<float>(lobe.usableLevels);
  lobe.throughLevel = lobe.throughRoughness * static_cast<float>(lobe.usableLevels);
  lobe.levels = roughLevelsFor(lobe.roughness, lobe.usableLevels);
  lobe.lowerFaceSize = std::max(faceSize >> lobe.levels.lower, 1);
  lobe.upperFaceSize = std::max(faceSize >> lobe.levels.upper, 1);
  const bool filtered = made && has(kept, lobe.levels.lower) && has(kept, lobe.levels.upper);
  lobe.source = filtered ? source : LobeExplanation::Source::NotFiltered;
}

// A probe's reader: its capture's levels.
void readPrefiltered(const Demo& demo, const ProbePlan& probe, LobeExplanation& lobe) {
  const CubeCaptureTarget* target =
      demo.renderer() ? demo.renderer()->probeTarget(probe.reflector) : nullptr;
  readLevels(target ? target->faceSize() : 0, probe.roughLevels, target != nullptr,
             demo.accuracySettings().roughLevels, LobeExplanation::Source::Prefiltered, lobe);
}

// A reader of the static skybox: the sky's levels, filtered from its own faces.
void readPrefilteredSky(const Demo& demo, LobeExplanation& lobe) {
  const CubeFaces* sky = demo.skyboxFaces();
  readLevels(sky ? (*sky)[0].width : 0, demo.lastPlan().skyRoughLevels, sky != nullptr,
             demo.accuracySettings().roughLevels, LobeExplanation::Source::PrefilteredSky, lobe);
}

std::string levelName(int level, int faceSize) {
  return formatLine("level %d (%dx%d faces)", level, faceSize, faceSize);
}

// Which levels the lookup blends: the sharp reflection and level 1 below level 1 (the
// renderer's own mix), a single level at the top, otherwise the two around it (trilinear).
std::string levelsRead(const LobeExplanation& lobe) {
  const std::string upper = levelName(lobe.levels.upper, lobe.upperFaceSize);
  if (lobe.levels.lower == 0 && lobe.source == LobeExplanation::Source::PrefilteredSky) {
    return formatLine(", between the sharp sky (level 0, the skybox itself, %dx%d faces) and ",
                      lobe.lowerFaceSize, lobe.lowerFaceSize) +
           upper;
  }
  if (lobe.levels.lower == 0) {
    return formatLine(
               ", between the sharp reflection its search found (level 0, the capture itself, "
               "%dx%d faces) and ",
               lobe.lowerFaceSize, lobe.lowerFaceSize) +
           upper;
  }
  if (lobe.levels.lower == lobe.levels.upper) return ", " + upper + " alone";
  return ", blended trilinearly between " + levelName(lobe.levels.lower, lobe.lowerFaceSize) +
         " and " + upper;
}

std::string howRead(const LobeExplanation& lobe) {
  using Source = LobeExplanation::Source;
  switch (lobe.source) {
    case Source::Traced:
      if (lobe.narrow) {
        return formatLine(
            "  lobe: traced with %d lobe rays (narrowLobeRays; half as many for glass's two "
            "lobes) around the reflected ray, each weighed by the GGX reflectance (search: "
            "planned traces a lobe this narrow, roughness under %.3g, which taps from a capture "
            "would draw as rings, or through glass as a few sharp copies)",
            lobe.lobeRays, kNarrowLobeRoughness);
      }
      return formatLine(
          "  lobe: traced with %d lobe rays (lobeRays) around the reflected ray, each weighed "
          "by the GGX reflectance (search: exact, or planned found tracing cheaper)",
          lobe.lobeRays);
    case Source::LobeTaps:
      return formatLine(
          "  lobe: %d lobe taps (lobeTaps) around the reflected ray for this view, each weighed "
          "by the GGX reflectance and read from the probe's capture (%dx%d faces, its box chain) "
          "at the level its share of the lobe covers, towards where %s met the scene%s",
          lobe.lobeTaps, lobe.tapFaceSize, lobe.tapFaceSize,
          lobe.quartersSearched ? "a search of its quarter of the lobe" : "the search's ray",
          lobe.tapsChecked ? " (a wide lobe: each tap blended towards where the central ray met "
                             "the scene, as far as the probe's depths hold that point better)"
                           : "");
    case Source::PrefilteredSky:
      return formatLine(
                 "  lobe: read from the static skybox's prefiltered levels (filtered once): "
                 "roughness %.2f x %d levels = level %.2f",
                 lobe.roughness, lobe.usableLevels, lobe.level) +
             levelsRead(lobe);
    case Source::NotFiltered:
      return formatLine(
          "  lobe: level %.2f (roughness x %d levels) was not prefiltered for this probe (or "
          "sky) this frame",
          lobe.level, lobe.usableLevels);
    default:
      break;
  }
  return formatLine(
             "  lobe: read from the probe's prefiltered levels: roughness %.2f x %d levels = "
             "level %.2f",
             lobe.roughness, lobe.usableLevels, lobe.level) +
         levelsRead(lobe);
}

}  // namespace

Search searchDrawnWith(const Demo& demo, int object) {
  const Search search = capturedSearch(demo.accuracySettings().search);
  const ProbePlan* probe = demo.lastPlan().probeOf(object);
  if (probe == nullptr || probe->plainLookupSuffices) return Search::Plain;
  return search;
}

LobeExplanation explainLobe(const Demo& demo, int object) {
  LobeExplanation lobe;
  if (object < 0 || object >= static_cast<int>(demo.scene().objects.size())) return lobe;
  const SceneObject& o = demo.scene().objects[static_cast<size_t>(object)];
  if (!o.rough()) return lobe;
  lobe.roughness = o.roughness;
  lobe.glass = o.material == Material::Glass;
  lobe.throughRoughness = lobe.glass ? transmissionRoughness(o.roughness, o.ior) : 0.0f;
  lobe.alpha = ggxAlpha(o.roughness);
  if (demo.lastPlan().traces(object)) {
    lobe.source = LobeExplanation::Source::Traced;
    lobe.lobeRays = demo.lastPlan().lobeRaysOf(object);
    const std::vector<int>& narrow = demo.lastPlan().narrowTraced;
    lobe.narrow = std::find(narrow.begin(), narrow.end(), object) != narrow.end();
  } else if (o.environment == Environment::Skybox) {
    readPrefilteredSky(demo, lobe);
  } else if (const ProbePlan* probe = demo.lastPlan().probeOf(object);
             probe && probe->lobeTapReaders) {
    const CubeCaptureTarget* target =
        demo.renderer() ? demo.renderer()->probeTarget(probe->reflector) : nullptr;
    lobe.source = target ? LobeExplanation::Source::LobeTaps : LobeExplanation::Source::NotFiltered;
    lobe.lobeTaps = demo.accuracySettings().lobeTaps;
    lobe.tapFaceSize = target ? target->faceSize() : 0;
    lobe.quartersSearched = !lobe.glass && demo.accuracySettings().lobeQuarters &&
                            searchDrawnWith(demo, object) == Search::Hierarchical;
    lobe.tapsChecked = lobe.quartersSearched && lobe.alpha > kWideLobeAlpha;
  } else if (probe) {
    readPrefiltered(demo, *probe, lobe);
  } else {
    lobe.source = LobeExplanation::Source::NotFiltered;
  }
  return lobe;
}

std::vector<std::string> lobeLines(const LobeExplanation& lobe, bool raysShown) {
  if (lobe.source == LobeExplanation::Source::None) return {};
  std::vector<std::string> lines;
  if (lobe.glass) {
    lines.push_back(
        formatLine("  frosted glass: roughness %.2f, GGX alpha %.4f (roughness squared): its "
                   "reflection is averaged over the GGX lobe around the reflected ray, the light "
                   "through it over the view ray refracted through the lobe's microfacet normals",
                   lobe.roughness, lobe.alpha));
  } else {
    lines.push_back(formatLine(
        "  rough mirror: roughness %.2f, GGX alpha %.4f (roughness squared): it sees the "
        "environment averaged over the GGX lobe around the reflected ray",
        lobe.roughness, lobe.alpha));
  }
  lines.push_back(howRead(lobe));
  if (lobe.glass && (lobe.source == LobeExplanation::Source::Prefiltered ||
                     lobe.source == LobeExplanation::Source::PrefilteredSky)) {
    lines.push_back(formatLine(
        "  light through: read around the refracted ray at level %.2f (transmission roughness "
        "%.2f x %d levels: core/ggx.h transmissionRoughness)",
        lobe.throughLevel, lobe.throughRoughness, lobe.usableLevels));
  }
  if (lobe.glass && lobe.source == LobeExplanation::Source::LobeTaps) {
    lines.push_back(formatLine(
        "  light through: %d lobe taps of its own, the view ray refracted through the lobe's "
        "microfacet normals, each read at the level of its share of a lobe of alpha %.4f "
        "(transmission roughness %.2f squared, core/ggx.h transmissionRoughness)",
        lobe.lobeTaps, lobe.throughRoughness * lobe.throughRoughness, lobe.throughRoughness));
  }
  if (lobe.glass && lobe.source == LobeExplanation::Source::Traced) {
    lines.push_back(formatLine(
        "  light through: traced with %d rays refracted through the lobe's microfacet normals",
        lobe.lobeRays));
  }
  if (raysShown) {
    lines.push_back(
        "  the rays and lookups below (and the lines the page draws) are the lobe's centre: "
        "the reflected ray, and where its search lands");
  }
  return lines;
}

}  // namespace reflect
