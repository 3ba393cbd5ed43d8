#include "core/settings_schema.h"

#include "core/ggx.h"
#include "core/presets.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace reflect {
namespace {

using Kind = SettingInfo::Kind;
using nlohmann::json;

// Whole numbers with every digit ("1000000", not %g's "1e+06"), fractions as short as they go.
std::string formatNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.15g", v);
  return buffer;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

SettingInfo choice(std::string name, std::string label, std::string help,
                   std::vector<std::string> choices) {
  return {std::move(name),
          std::move(label),
          std::move(help),
          Kind::Choice,
          0,
          0,
          std::move(choices),
          {}};
}
// `only`: the values allowed within min..max, when not all of them are.
SettingInfo integer(std::string name, std::string label, std::string help, int min, int max,
                    std::vector<std::string> only = {}) {
  return {std::move(name), std::move(label), std::move(help), Kind::Integer,
          double(min),     double(max),      std::move(only), {}};
}
SettingInfo number(std::string name, std::string label, std::string help, double min, double max) {
  return {std::move(name), std::move(label), std::move(help), Kind::Number, min, max, {}, {}};
}
SettingInfo flag(std::string name, std::string label, std::string help) {
  return {std::move(name), std::move(label), std::move(help), Kind::Flag, 0, 1, {}, {}};
}
SettingInfo inFolder(SettingInfo info, std::string folder) {
  info.folder = std::move(folder);
  return info;
}

constexpr const char* kInsideFolder = "Inside the frame";
const std::vector<std::string> kInsideViews = {"off", "faces", "faceuse"};
const std::vector<std::string> kFacesChannels = {
    facesChannelName(FacesChannel::Colour), facesChannelName(FacesChannel::Distance),
    facesChannelName(FacesChannel::SecondLayer), facesChannelName(FacesChannel::Irradiance)};

template <class E>
E enumAt(const std::vector<std::string>& names, const std::string& name) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<E>(i);
  }
  return static_cast<E>(0);  // unreachable: the value passed the choice's check
}

const char* kKindNames[] = {"choice", "integer", "number", "flag"};

template <class S>
json schemaOf(const std::vector<SettingField<S>>& fields) {
  const S defaults{};
  json list = json::array();
  for (const auto& f : fields) {
    json entry = {{"name", f.info.name},
                  {"label", f.info.label},
                  {"help", f.info.help},
                  {"kind", kKindNames[static_cast<int>(f.info.kind)]},
                  {"default", f.get(defaults)}};
    if (f.info.kind == Kind::Integer || f.info.kind == Kind::Number) {
      entry["min"] = f.info.min;
      entry["max"] = f.info.max;
    }
    if (!f.info.choices.empty()) entry["choices"] = f.info.choices;
    if (!f.info.folder.empty()) entry["folder"] = f.info.folder;
    list.push_back(std::move(entry));
  }
  return list;
}

}  // namespace

std::string SettingInfo::optionName() const {
  std::string option = "--";
  for (char c : name) {
    if (std::isupper(static_cast<unsigned char>(c))) {
      option += '-';
      option += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      option += c;
    }
  }
  return option;
}

std::string SettingInfo::expected() const {
  switch (kind) {
    case Kind::Choice:
      return "one of " + joined(choices);
    case Kind::Integer:
      if (!choices.empty()) return "one of " + joined(choices);
      return "a whole number from " + formatNumber(min) + " to " + formatNumber(max);
    case Kind::Number:
      return "a number from " + formatNumber(min) + " to " + formatNumber(max);
    case Kind::Flag:
      return "true or false";
  }
  return {};
}

std::string SettingInfo::check(const json& value) const {
  const std::string shown = value.dump();
  switch (kind) {
    case Kind::Choice: {
      if (value.is_string()) {
        for (const std::string& c : choices) {
          if (c == value.get<std::string>()) return {};
        }
      }
      return name + ": " + shown + " is not " + expected();
    }
    case Kind::Integer:
    case Kind::Number: {
      if (!value.is_number()) return name + ": " + shown + " is not " + expected();
      const double v = value.get<double>();
      if (kind == Kind::Integer && !value.is_number_integer() && v != std::floor(v)) {
        return name + ": " + shown + " is not a whole number";
      }
      if (!(v >= min && v <= max)) {
        return name + ": " + shown + " is not in " + formatNumber(min) + ".." + formatNumber(max);
      }
      if (kind == Kind::Integer && !choices.empty()) {
        for (const std::string& c : choices) {
          if (c == formatNumber(v)) return {};
        }
        return name + ": " + shown + " is not " + expected();
      }
      return {};
    }
    case Kind::Flag:
      return value.is_boolean() ? std::string() : name + ": " + shown + " is not true or false";
  }
  return {};
}

const std::vector<std::string>& policyNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (UpdatePolicy p : {UpdatePolicy::EveryFrame, UpdatePolicy::WhenChanged,
                           UpdatePolicy::TimeSliced, UpdatePolicy::EveryNFrames}) {
      list.push_back(policyName(p));
    }
    return list;
  }();
  return names;
}

const std::vector<SettingField<PlannerSettings>>& plannerFields() {
  using P = PlannerSettings;
  static const std::vector<SettingField<P>> fields = {
      {choice("policy", "update policy",
              "when a cube face is redrawn: every-frame (the course), when-changed (exact), "
              "time-sliced (at most facesPerFrame stale faces a frame), every-n (every everyN-th "
              "frame)",
              policyNames()),
       [](const P& s) { return json(policyName(s.policy)); },
       [](P& s, const json& v) { parsePolicy(v.get<std::string>(), &s.policy); }},
      {integer("facesPerFrame", "faces per frame", "time-sliced: faces redrawn per frame", 1, 6),
       [](const P& s) { return json(s.facesPerFrame); },
       [](P& s, const json& v) { s.facesPerFrame = v.get<int>(); }},
      {integer("everyN", "every N frames", "every-n: capture on every N-th frame", 1, 1000),
       [](const P& s) { return json(s.everyN); },
       [](P& s, const json& v) { s.everyN = v.get<int>(); }},
      {number("captureLod", "capture LOD (tris/px)",
              "capture level of detail: the coarsest mesh level with at least this many "
              "triangles per pixel of the object's disc in the face (0 = full detail)",
              0, 1000),
       [](const P& s) { return json(s.captureLod); },
       [](P& s, const json& v) { s.captureLod = v.get<float>(); }},
      {number("viewLod", "view LOD (tris/px)",
              "the same rule for the main camera's pass (0 = full detail)", 0, 1000),
       [](const P& s) { return json(s.viewLod); },
       [](P& s, const json& v) { s.viewLod = v.get<float>(); }},
  };
  return fields;
}

namespace {

std::vector<std::string> searchNames() {
  std::vector<std::string> names;
  for (Search s : kSearches) names.push_back(searchName(s));
  return names;
}

}  // namespace

const std::vector<SettingField<AccuracySettings>>& accuracyFields() {
  using A = AccuracySettings;
  static const std::vector<SettingField<A>> fields = {
      {flag("captureAtOrigin", "capture at origin",
            "capture at (0,0,0) as the course does, not at the reflector's centre"),
       [](const A& s) { return json(s.captureAtOrigin); },
       [](A& s, const json& v) { s.captureAtOrigin = v.get<bool>(); }},
      {choice("search", "search",
              "how a mirror finds what its ray meets: plain (the course: along the ray's "
              "direction), linear (12 steps against stored distances), hierarchical (every texel "
              "the ray passes, through a min/max depth chain), exact (the ray traced against the "
              "scene's triangles: no cube map), planned (per reflector, the cheaper of exact and "
              "hierarchical, by the planner's cost model)",
              searchNames()),
       [](const A& s) { return json(searchName(s.search)); },
       [](A& s, const json& v) { parseSearch(v.get<std::string>(), &s.search); }},
      {integer("layers", "depth layers",
               "hierarchical search: 2 also stores what the nearest surface hides from the probe",
               1, 2),
       [](const A& s) { return json(s.layers); },
       [](A& s, const json& v) { s.layers = v.get<int>(); }},
      {integer("glassSurfaces", "glass surfaces",
               "glass: 2 refracts in and out again, 1 only where the ray enters (the course)", 1,
               2),
       [](const A& s) { return json(s.glassSurfaces); },
       [](A& s, const json& v) { s.glassSurfaces = v.get<int>(); }},
      {integer("depthBits", "depth bits", "the capture's depth buffer: 16 or 24 bits", 16, 24,
               {"16", "24"}),
       [](const A& s) { return json(s.depthBits); },
       [](A& s, const json& v) { s.depthBits = v.get<int>(); }},
      {flag("mipmaps", "mipmaps", "trilinear lookup from a mip chain rebuilt after each capture"),
       [](const A& s) { return json(s.mipmaps); },
       [](A& s, const json& v) { s.mipmaps = v.get<bool>(); }},
      {integer("lobeTaps", "lobe taps",
               "rough mirrors and frosted glass, captured: the lobe samples each pixel reads from "
               "the probe's box chain for its own view (0: the prefiltered levels instead)",
               0, 64),
       [](const A& s) { return json(s.lobeTaps); },
       [](A& s, const json& v) { s.lobeTaps = v.get<int>(); }},
      {flag("lobeQuarters", "lobe quarters",
            "rough mirrors and frosted glass with lobe taps, searched: each quarter of the lobe "
            "(glass: of its light through) searched for how far its taps meet the scene (off: "
            "the central ray's distance for every tap)"),
       [](const A& s) { return json(s.lobeQuarters); },
       [](A& s, const json& v) { s.lobeQuarters = v.get<bool>(); }},
      {integer("filterSamples", "filter samples",
               "rough mirrors: GGX samples per texel of the probe's prefilter pass", 1,
               kMaxFilterSamples),
       [](const A& s) { return json(s.filterSamples); },
       [](A& s, const json& v) { s.filterSamples = v.get<int>(); }},
      {integer("roughLevels", "rough levels",
               "rough mirrors: prefiltered mip levels; level m holds roughness m / levels", 1, 8),
       [](const A& s) { return json(s.roughLevels); },
       [](A& s, const json& v) { s.roughLevels = v.get<int>(); }},
      {integer("lobeRays", "lobe rays",
               "rough mirrors, traced (search: exact): the fixed rays each pixel traces in its "
               "lobe",
               1, 256),
       [](const A& s) { return json(s.lobeRays); },
       [](A& s, const json& v) { s.lobeRays = v.get<int>(); }},
      {integer("narrowLobeRays", "narrow lobe rays",
               "rough mirrors and frosted glass under roughness 0.375, planned: traced with this "
               "many fixed lobe rays a pixel (glass: half as many for each of its two lobes), a "
               "lobe too narrow for lobe taps (0: captured like the rest)",
               0, 256),
       [](const A& s) { return json(s.narrowLobeRays); },
       [](A& s, const json& v) { s.narrowLobeRays = v.get<int>(); }},
      {flag("halfFloat", "RGBA16F", "RGBA16F capture colour instead of RGBA8"),
       [](const A& s) { return json(s.halfFloat); },
       [](A& s, const json& v) { s.halfFloat = v.get<bool>(); }},
      {flag("mediump", "mediump", "fragment shaders at mediump precision instead of highp"),
       [](const A& s) { return json(s.mediump); },
       [](A& s, const json& v) { s.mediump = v.get<bool>(); }},
  };
  return fields;
}

const std::vector<SettingField<ViewSettings>>& viewFields() {
  using V = ViewSettings;
  static const std::vector<SettingField<V>> fields = {
      {flag("showError", "show error",
            "a heat map of each reflector pixel's difference from the exact mode (rendered "
            "alongside and compared on the GPU), with the reflector PSNR and the pixels off by "
            "more than 32 levels"),
       [](const V& s) { return json(s.showError); },
       [](V& s, const json& v) { s.showError = v.get<bool>(); }},
      {flag("auto", "auto (frame budget)",
            "time the searches on this machine and run the most accurate one whose frame fits "
            "the budget, judged by its error against the exact mode on the current scene"),
       [](const V& s) { return json(s.autoAccuracy); },
       [](V& s, const json& v) { s.autoAccuracy = v.get<bool>(); }},
      {number("budget", "frame budget (ms)",
              "auto: the frame time to stay within (0 = the display's frame interval)", 0, 1000),
       [](const V& s) { return json(s.budget); },
       [](V& s, const json& v) { s.budget = v.get<float>(); }},
      {inFolder(
           choice("inside", "view",
                  "inside the frame: off (the picture), faces (the probe's cube map unfolded as "
                  "a cross, each face with the course's look and up vectors, stale faces "
                  "dimmed with their age), faceuse (each mirror and glass pixel in the colour "
                  "of the cube face it read, with a legend of the pixels each face serves)",
                  kInsideViews),
           kInsideFolder),
       [](const V& s) { return json(insideViewName(s.inside)); },
       [](V& s, const json& v) {
         s.inside = enumAt<InsideView>(kInsideViews, v.get<std::string>());
       }},
      {inFolder(choice("facesChannel", "faces channel",
                       "what the faces view shows of each texel: colour, distance (the stored "
                       "depth along each face's look "
                       "direction, near bright; needs the depth search) or layer2 (the second "
                       "layer's colour; needs search: hierarchical with layers 2) or irradiance "
                       "(the colour faces' order-2 "
                       "spherical harmonics, each texel the ambient light a probe-lit figure "
                       "whose normal points there takes)",
                       kFacesChannels),
                kInsideFolder),
       [](const V& s) { return json(facesChannelName(s.facesChannel)); },
       [](V& s, const json& v) {
         s.facesChannel = enumAt<FacesChannel>(kFacesChannels, v.get<std::string>());
       }},
      {inFolder(integer("facesProbe", "probe",
                        "which probe the faces view shows and the face-use view's legend marks: "
                        "the frame's Nth (1 = the first; past the last, the last)",
                        1, 64),
                kInsideFolder),
       [](const V& s) { return json(s.facesProbe); },
       [](V& s, const json& v) { s.facesProbe = v.get<int>(); }},
  };
  return fields;
}

const char* insideViewName(InsideView view) {
  return kInsideViews[static_cast<size_t>(view)].c_str();
}

const std::vector<SettingField<SceneObject>>& materialFields() {
  using O = SceneObject;
  static const std::vector<SettingField<O>> fields = {
      {choice("type", "material", "how the object is shaded",
              {materialName(Material::Phong), materialName(Material::Mirror),
               materialName(Material::Glass), materialName(Material::CubeTextured)}),
       [](const O& o) { return json(materialName(o.material)); },
       [](O& o, const json& v) { parseMaterial(v.get<std::string>(), &o.material); }},
      {number("reflection", "reflection", "the environment's weight in the fixed mix", 0, 4),
       [](const O& o) { return json(o.reflection); },
       [](O& o, const json& v) { o.reflection = v.get<float>(); }},
      {number("base", "base colour", "the base colour's weight in the fixed mix", 0, 4),
       [](const O& o) { return json(o.base); },
       [](O& o, const json& v) { o.base = v.get<float>(); }},
      {number("ior", "index of refraction",
              "glass: air to the material (air 1.00, ice 1.309, water 1.33, glass 1.52, "
              "diamond 2.42); also sets Fresnel's F0",
              1, 4),
       [](const O& o) { return json(o.ior); }, [](O& o, const json& v) { o.ior = v.get<float>(); }},
      {flag("fresnel", "Fresnel", "Schlick's Fresnel weighting instead of the fixed mix"),
       [](const O& o) { return json(o.fresnel); },
       [](O& o, const json& v) { o.fresnel = v.get<bool>(); }},
      {number(
           "roughness", "roughness",
           "mirror and glass: 0 a perfect surface, up to 1; what it reflects (and glass lets "
           "through) is averaged over a GGX lobe (a prefiltered probe, or lobe rays when traced)",
           0, 1),
       [](const O& o) { return json(o.roughness); },
       [](O& o, const json& v) { o.roughness = v.get<float>(); }},
      {choice("environment", "environment",
              "live: a cube captured around the object each frame; skybox: the static sky",
              {environmentName(Environment::LiveProbe), environmentName(Environment::Skybox)}),
       [](const O& o) { return json(environmentName(o.environment)); },
       [](O& o, const json& v) { parseEnvironment(v.get<std::string>(), &o.environment); }},
  };
  return fields;
}

json settingsSchemaJson() {
  return {{"planner", schemaOf(plannerFields())},
          {"accuracy", schemaOf(accuracyFields())},
          {"material", schemaOf(materialFields())},
          {"view", schemaOf(viewFields())},
          {"presets", presetsJson()}};
}

}  // namespace reflect
