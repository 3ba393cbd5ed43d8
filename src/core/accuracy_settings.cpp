#include "core/accuracy_settings.h"

#include <iterator>

#include "core/enum_names.h"

namespace reflect {

namespace {

constexpr EnumName<Search> kSearchNames[] = {{Search::Plain, "plain"},
                                             {Search::Linear, "linear"},
                                             {Search::Hierarchical, "hierarchical"},
                                             {Search::Exact, "exact"},
                                             {Search::Planned, "planned"}};
static_assert(std::size(kSearchNames) == std::size(kSearches), "every search has a name");

}  // namespace

const char* searchName(Search search) {
  return nameIn(kSearchNames, search);
}

bool parseSearch(const std::string& name, Search* search) {
  return parseIn(kSearchNames, name, search);
}

std::string AccuracySettings::describe() const {
  std::string s = captureAtOrigin ? "origin" : "centre";
  s += std::string(", ") + searchName(search);
  if (search == Search::Hierarchical || search == Search::Planned) {
    s += ", layers " + std::to_string(layers);
  }
  s += ", glass " + std::to_string(glassSurfaces);
  s += ", depth " + std::to_string(depthBits);
  s += mipmaps ? ", mipmapped" : ", linear";
  s += halfFloat ? ", RGBA16F" : ", RGBA8";
  s += mediump ? ", mediump" : ", highp";
  // Rough mirrors' knobs, where they differ from the defaults (most scenes have no rough mirror).
  const AccuracySettings defaults;
  if (lobeTaps != defaults.lobeTaps) s += ", lobe taps " + std::to_string(lobeTaps);
  if (filterSamples != defaults.filterSamples) {
    s += ", filter samples " + std::to_string(filterSamples);
  }
  if (roughLevels != defaults.roughLevels) s += ", rough levels " + std::to_string(roughLevels);
  if (lobeRays != defaults.lobeRays) s += ", lobe rays " + std::to_string(lobeRays);
  if (!lobeQuarters) s += ", one lobe distance";
  if (narrowLobeRays != defaults.narrowLobeRays)
    s += ", narrow lobe rays " + std::to_string(narrowLobeRays);
  return s;
}

}  // namespace reflect
