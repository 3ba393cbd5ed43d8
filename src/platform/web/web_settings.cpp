// The page's settings, by the names of the settings schema (core/settings_schema.h): the schema
// itself (the page builds its controls, link keys and messages from it), the capture planner,
// the accuracy settings and the objects' materials. Changes are JSON objects of the settings to
// change; absent ones keep their value, and a bad one changes nothing.
#include <emscripten/emscripten.h>

#include <string>
#include <vector>

#include "core/budget_pick.h"
#include "core/settings_schema.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using namespace reflect::web;  // the bridge's helpers: web_state.h

// The planner settings that only one policy reads: the panel shows them with that policy only,
// and a link carries them with that policy only.
struct PolicyParameter {
  reflect::UpdatePolicy policy;
  const char* setting;
};
constexpr PolicyParameter kPolicyParameters[] = {
    {reflect::UpdatePolicy::TimeSliced, "facesPerFrame"},
    {reflect::UpdatePolicy::EveryNFrames, "everyN"},
};

// The panel's one line for an object's material, e.g. "mirror 0.78 refl + 0.3 base".
std::string materialSummary(const reflect::SceneObject& o) {
  const std::string sky = o.environment == reflect::Environment::Skybox ? ", static sky" : "";
  switch (o.material) {
    case reflect::Material::Mirror:
      return (o.fresnel ? "mirror, Fresnel (ior " + shortestText(o.ior) + ")"
                        : "mirror " + shortestText(o.reflection) + " refl + " +
                              shortestText(o.base) + " base") +
             sky;
    case reflect::Material::Glass:
      return "glass ior " + shortestText(o.ior) + (o.fresnel ? ", Fresnel" : "") + sky;
    default:
      return reflect::materialName(o.material);
  }
}

// Mirrors and glass take their settings from the page; the other materials have none to edit.
bool editable(const reflect::SceneObject& o) {
  return o.material == reflect::Material::Mirror || o.material == reflect::Material::Glass;
}

}  // namespace

extern "C" {

// Every user-facing setting: {"planner": [...], "accuracy": [...], "material": [...]}, each entry
// {"name", "label", "help", "kind", "default", "min", "max", "choices"} (settingsSchemaJson).
EMSCRIPTEN_KEEPALIVE const char* rf_schema_json() {
  return reply(reflect::settingsSchemaJson());
}

// {"settings": {policy, facesPerFrame, everyN, captureLod, viewLod}, "maxStalenessFrames": n,
//  "policyParameters": [the settings only this policy reads],
//  "unusedSettings": [the settings only other policies read]}
EMSCRIPTEN_KEEPALIVE const char* rf_planner_json() {
  if (!state().demo) return reply(json::object());
  const reflect::PlannerSettings& s = state().demo->plannerSettings();
  json parameters = json::array(), unused = json::array();
  for (const PolicyParameter& p : kPolicyParameters) {
    (p.policy == s.policy ? parameters : unused).push_back(p.setting);
  }
  return reply({{"settings", reflect::settingsJson(s, reflect::plannerFields())},
                {"maxStalenessFrames", s.maxStalenessFrames()},
                {"policyParameters", parameters},
                {"unusedSettings", unused}});
}

// Changes the capture planner: {"facesPerFrame": 3, ...} by the schema's names. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_planner(const char* request) {
  auto r = parseRequest(request, "rf_set_planner");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("no scene loaded");
  reflect::PlannerSettings settings = state().demo->plannerSettings();
  std::string error = reflect::applySettingsJson(r.value(), reflect::plannerFields(), settings);
  if (!error.empty()) return replyError(error);
  state().demo->setPlannerSettings(settings);
  return replyDone();
}

// {"settings": {captureAtOrigin, search, ...}, "describe": "centre, hierarchical, ..."}
EMSCRIPTEN_KEEPALIVE const char* rf_accuracy_json() {
  if (!state().demo) return reply(json::object());
  const reflect::AccuracySettings& a = state().demo->accuracySettings();
  return reply({{"settings", reflect::settingsJson(a, reflect::accuracyFields())},
                {"describe", a.describe()}});
}

// Changes the accuracy settings by the schema's names (rebuilds the GL resources). {} or
// {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_accuracy(const char* request) {
  auto r = parseRequest(request, "rf_set_accuracy");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("no scene loaded");
  reflect::AccuracySettings settings = state().demo->accuracySettings();
  std::string error = reflect::applySettingsJson(r.value(), reflect::accuracyFields(), settings);
  if (!error.empty()) return replyError(error);
  return replyError(state().demo->setAccuracySettings(settings));
}

// The current scene's objects: [{"mesh", "material": {type, reflection, base, ior, fresnel,
// environment}, "summary": the panel's line, "reflective": it uses an environment, "editable":
// the page may change its material, "orbits": it circles the origin, "translate": [x, y, z],
// "screen": {"x0", "y0", "x1", "y1", "inFront"} where its bounding box lands on the canvas now, in
// fractions of the drawing buffer from the top left (Demo::screenBoxes)}]
EMSCRIPTEN_KEEPALIVE const char* rf_objects_json() {
  json list = json::array();
  if (!state().demo) return reply(list);
  int width = 0, height = 0;
  emscripten_webgl_get_drawing_buffer_size(state().context, &width, &height);
  const std::vector<reflect::ScreenBox> boxes = state().demo->screenBoxes(width, height);
  const auto& objects = state().demo->scene().objects;
  for (size_t i = 0; i < objects.size(); ++i) {
    const reflect::SceneObject& o = objects[i];
    const glm::vec3 at(o.placement[3]);
    const reflect::ScreenBox& box = boxes[i];
    list.push_back({{"mesh", o.mesh},
                    {"material", reflect::settingsJson(o, reflect::materialFields())},
                    {"summary", materialSummary(o)},
                    {"reflective", o.usesEnvironment()},
                    {"editable", editable(o)},
                    {"orbits", o.motion == reflect::Motion::Orbit},
                    {"translate", {at.x, at.y, at.z}},
                    {"screen",
                     {{"x0", box.x0},
                      {"y0", box.y0},
                      {"x1", box.x1},
                      {"y1", box.y1},
                      {"inFront", box.inFront}}}});
  }
  return reply(list);
}

// Changes object "index"'s material: {"index": 3, "changes": {"reflection": 0.5, ...}} by the
// schema's names (mirror and glass objects only). {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_material(const char* request) {
  auto r = parseRequest(request, "rf_set_material");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("no scene loaded");
  const json& in = r.value();
  const auto& objects = state().demo->scene().objects;
  if (!in.contains("index") || !in["index"].is_number_integer()) {
    return replyError("rf_set_material: index: expected a whole number");
  }
  const auto index = in["index"].get<long long>();
  if (index < 0 || index >= static_cast<long long>(objects.size())) {
    return replyError("no object " + std::to_string(index) + " in this scene (it has " +
                      std::to_string(objects.size()) + ")");
  }
  reflect::SceneObject object = objects[static_cast<size_t>(index)];
  if (!editable(object)) {
    return replyError("object " + std::to_string(index) + " (" + object.mesh + ") is " +
                      reflect::materialName(object.material) + ", not a mirror or glass");
  }
  const json changes = in.contains("changes") ? in["changes"] : json::object();
  std::string error = reflect::applySettingsJson(changes, reflect::materialFields(), object);
  if (!error.empty()) return replyError(error);
  const json material = reflect::settingsJson(object, reflect::materialFields());
  return replyError(state().demo->setMaterialJson(static_cast<int>(index), material.dump()));
}

// The page's view settings: {"settings": {showError, auto, budget, inside, facesChannel}}.
EMSCRIPTEN_KEEPALIVE const char* rf_view_json() {
  return reply({{"settings", reflect::settingsJson(state().view, reflect::viewFields())}});
}

// Changes them by the schema's names; showError turns the demo's error view on or off, inside
// its teaching view (Inside the frame). {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_view(const char* request) {
  auto r = parseRequest(request, "rf_set_view");
  if (!r) return replyError(r.error());
  reflect::ViewSettings view = state().view;
  std::string error = reflect::applySettingsJson(r.value(), reflect::viewFields(), view);
  if (!error.empty()) return replyError(error);
  if (state().demo) error = state().demo->setViewSettings(view);
  if (!error.empty()) return replyError(error);
  state().view = view;
  return replyDone();
}

// The settings "auto" times: [{"name", "accuracy": {by the schema's names}}] (the current accuracy
// settings with each search).
EMSCRIPTEN_KEEPALIVE const char* rf_budget_candidates() {
  json list = json::array();
  if (!state().demo) return reply(list);
  for (const reflect::BudgetCandidate& c :
       reflect::budgetCandidates(state().demo->accuracySettings())) {
    list.push_back({{"name", c.name},
                    {"accuracy", reflect::settingsJson(c.accuracy, reflect::accuracyFields())}});
  }
  return reply(list);
}

// The pick: {"budget": ms, "candidates": [{"name", "accuracy", "frameMs", "psnrDb"}]} (as measured
// by the page) -> {"index", "fits", "reason", "table"} (core/budget_pick.h's rule).
EMSCRIPTEN_KEEPALIVE const char* rf_pick_accuracy(const char* request) {
  auto r = parseRequest(request, "rf_pick_accuracy");
  if (!r) return replyError(r.error());
  const json& in = r.value();
  if (!in.contains("budget") || !in["budget"].is_number() || !in.contains("candidates") ||
      !in["candidates"].is_array()) {
    return replyError("rf_pick_accuracy: expected {budget: ms, candidates: [...]}");
  }
  std::vector<reflect::BudgetCandidate> candidates;
  for (const json& c : in["candidates"]) {
    reflect::BudgetCandidate candidate;
    candidate.name = c.value("name", std::string());
    if (c.contains("accuracy")) {
      const std::string error =
          reflect::applySettingsJson(c["accuracy"], reflect::accuracyFields(), candidate.accuracy);
      if (!error.empty()) return replyError("rf_pick_accuracy: " + error);
    }
    const auto number = [&c](const char* key) {
      return c.contains(key) && c[key].is_number() ? c[key].get<double>() : 0.0;
    };
    candidate.frameMs = number("frameMs");
    candidate.psnrDb = number("psnrDb");
    candidates.push_back(candidate);
  }
  const reflect::BudgetPick pick =
      reflect::pickWithinBudget(candidates, in["budget"].get<double>());
  return reply(
      {{"index", pick.index}, {"fits", pick.fits}, {"reason", pick.reason}, {"table", pick.table}});
}

}  // extern "C"
