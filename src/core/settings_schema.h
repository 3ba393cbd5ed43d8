// Every user-facing setting, defined once: its name, label, help, kind and range. The name is the
// C++ field, the JSON key (scene files, the page's bridge), the URL key and, in kebab case, the
// command-line option; the label is the panel's. The page reads this table (settingsSchemaJson)
// instead of keeping lists of its own, and the CLI builds its options from it.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/accuracy_settings.h"
#include "core/cube_cross.h"
#include "core/frame_planner.h"
#include "core/scene.h"

namespace reflect {

struct SettingInfo {
  enum class Kind { Choice, Integer, Number, Flag };
  std::string name;   // e.g. "facesPerFrame"
  std::string label;  // e.g. "faces per frame"
  std::string help;   // one line: what it does, what 0 or each choice means
  Kind kind = Kind::Number;
  double min = 0.0, max = 0.0;       // Integer and Number
  std::vector<std::string> choices;  // Choice; for an Integer, the only values allowed (if any)
  std::string folder;  // the panel's folder when not its group's own (e.g. "Inside the frame")

  // "--faces-per-frame"
  std::string optionName() const;
  // What a value must be, for messages: "a whole number from 1 to 6", "one of a, b, c".
  std::string expected() const;
  // "" when `value` is valid for this setting, else "NAME: VALUE is not in 1..6" and the like.
  std::string check(const nlohmann::json& value) const;
};

// One setting of a settings struct S: its description and how to read and write it.
template <class S>
struct SettingField {
  SettingInfo info;
  std::function<nlohmann::json(const S&)> get;
  std::function<void(S&, const nlohmann::json&)> set;  // the value has passed info.check
};

const std::vector<SettingField<PlannerSettings>>& plannerFields();
const std::vector<SettingField<AccuracySettings>>& accuracyFields();

// How the page shows and picks (show error, auto with its frame budget): page settings, in the
// link and the panel like the rest; natively `render --error-view` and `bench --budget`.
// Inside the frame (the teaching views): `inside` replaces the picture with one of them, natively
// also `render --faces FILE` and `render --face-use FILE`.
enum class InsideView {
  Off,
  Faces,    // the probe's cube map unfolded (core/cube_cross.h)
  FaceUse,  // each mirror and glass pixel in the colour of the face it read (core/face_use.h)
};
const char* insideViewName(InsideView view);

struct ViewSettings {
  bool showError = false;
  bool autoAccuracy = false;  // "auto"
  float budget = 0.0f;        // ms; 0 = the display's frame interval
  InsideView inside = InsideView::Off;
  FacesChannel facesChannel = FacesChannel::Colour;
  int facesProbe = 1;  // the frame's Nth probe, for the faces view and the face-use legend
  bool operator==(const ViewSettings&) const = default;
};
const std::vector<SettingField<ViewSettings>>& viewFields();

// A material's settings, as scene files and the page's material editor name them.
const std::vector<SettingField<SceneObject>>& materialFields();

// Names of the enumerations, in one place (scene files, JSON, the page's pickers).
const char* materialName(Material material);
bool parseMaterial(const std::string& name, Material* material);
const char* environmentName(Environment environment);
bool parseEnvironment(const std::string& name, Environment* environment);
const std::vector<std::string>& policyNames();

// settings as {"name": value, ...}.
template <class S>
nlohmann::json settingsJson(const S& settings, const std::vector<SettingField<S>>& fields) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& f : fields) json[f.info.name] = f.get(settings);
  return json;
}

// Applies the keys of `changes` (an object; absent keys keep their value). Every key is checked
// before any is applied, so a bad one changes nothing. Returns "" or the first problem.
template <class S>
std::string applySettingsJson(const nlohmann::json& changes,
                              const std::vector<SettingField<S>>& fields, S& settings) {
  if (!changes.is_object()) return "expected an object of settings";
  for (auto it = changes.begin(); it != changes.end(); ++it) {
    const SettingField<S>* field = nullptr;
    for (const auto& f : fields) {
      if (f.info.name == it.key()) field = &f;
    }
    if (!field) {
      std::string known;
      for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f.info.name;
      return "unknown setting '" + it.key() + "' (known: " + known + ")";
    }
    std::string problem = field->info.check(it.value());
    if (!problem.empty()) return problem;
  }
  S changed = settings;
  for (const auto& f : fields) {
    if (changes.contains(f.info.name)) f.set(changed, changes[f.info.name]);
  }
  settings = changed;
  return {};
}

// The whole table for the page: {"planner": [INFO...], "accuracy": [...], "material": [...],
// "view": [...]},
// each INFO {"name", "label", "help", "kind", "min", "max", "choices", "default"}.
nlohmann::json settingsSchemaJson();

}  // namespace reflect
