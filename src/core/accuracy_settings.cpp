#include "core/accuracy_settings.h"

namespace reflect {

const char* searchName(Search search) {
  switch (search) {
    case Search::Plain:
      return "plain";
    case Search::Linear:
      return "linear";
    case Search::Hierarchical:
      return "hierarchical";
    case Search::Exact:
      return "exact";
    case Search::Planned:
      return "planned";
  }
  return "?";
}

bool parseSearch(const std::string& name, Search* search) {
  for (Search s : kSearches) {
    if (name == searchName(s)) {
      *search = s;
      return true;
    }
  }
  return false;
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
  if (filterSamples != defaults.filterSamples) {
    s += ", filter samples " + std::to_string(filterSamples);
  }
  if (roughLevels != defaults.roughLevels) s += ", rough levels " + std::to_string(roughLevels);
  if (lobeRays != defaults.lobeRays) s += ", lobe rays " + std::to_string(lobeRays);
  return s;
}

}  // namespace reflect
