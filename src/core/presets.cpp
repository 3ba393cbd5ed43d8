#include "core/presets.h"

#include "core/settings_schema.h"

namespace reflect {

const std::vector<Preset>& presets() {
  static const std::vector<Preset> table = [] {
    Preset shipped{"default", "the shipped settings: the planner traces or captures each reflector",
                   PlannerSettings{}, AccuracySettings{}};
    Preset course{"course",
                  "the course's Ex12-2: six faces every frame, every object at full detail, "
                  "captured at the origin and looked up along the ray",
                  PlannerSettings{}, AccuracySettings{}};
    course.planner.policy = UpdatePolicy::EveryFrame;
    course.planner.captureLod = 0.0f;
    course.planner.viewLod = 0.0f;
    course.accuracy.captureAtOrigin = true;
    course.accuracy.search = Search::Plain;
    course.accuracy.layers = 1;
    course.accuracy.glassSurfaces = 1;
    course.accuracy.depthBits = 16;
    return std::vector<Preset>{shipped, course};
  }();
  return table;
}

const Preset* findPreset(const std::string& name) {
  for (const Preset& p : presets()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

nlohmann::json presetsJson() {
  nlohmann::json list = nlohmann::json::array();
  for (const Preset& p : presets()) {
    list.push_back({{"name", p.name},
                    {"help", p.help},
                    {"planner", settingsJson(p.planner, plannerFields())},
                    {"accuracy", settingsJson(p.accuracy, accuracyFields())}});
  }
  return list;
}

}  // namespace reflect
