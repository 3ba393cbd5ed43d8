// Named settings a user picks in one step: the course's own scheme, and the shipped defaults.
// The page (?preset=NAME and the panel), the CLI (--preset NAME) and the bench read this one
// table; settings given beside a preset override its values.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"

namespace reflect {

struct Preset {
  std::string name;
  std::string help;
  PlannerSettings planner;
  AccuracySettings accuracy;
};

// "default" (the shipped settings) and "course" (Ex12-2 as the course wrote it: six faces every
// frame, every object at full detail, captured at the origin, looked up along the ray's
// direction, one layer, one glass surface, a 16-bit depth buffer).
const std::vector<Preset>& presets();
const Preset* findPreset(const std::string& name);
// [{"name", "help", "planner": {...}, "accuracy": {...}}], settings by the schema's names.
nlohmann::json presetsJson();

}  // namespace reflect
