#include "core/scene_file.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <sstream>

#include "core/json_reader.h"
#include "core/settings_schema.h"
#include "core/skybox_faces.h"

namespace reflect {
namespace {

// Model and image names are plain file names or relative paths inside the site: no "..", no
// absolute paths, so a scene cannot reach outside the folders it is served from.
bool safeRelativePath(const std::string& path) {
  if (path.empty() || path.front() == '/' || path.find("..") != std::string::npos ||
      path.find('\\') != std::string::npos || path.find(':') != std::string::npos) {
    return false;
  }
  for (char c : path) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
          c == '/')) {
      return false;
    }
  }
  return true;
}

std::string readPath(const JsonReader& r) {
  const std::string path = r.string("");
  if (r.ok() && !safeRelativePath(path))
    r.fail("expected a relative file path (letters, digits, _ - . /)");
  return path;
}

// A material's keys and ranges are settings_schema's material fields; defaults are SceneObject's.
void readMaterial(const JsonReader& m, SceneObject& o) {
  if (m.isString() || !m.has("type")) {
    const std::string type = m.isString() ? m.string("") : "phong";
    if (type != "phong") m.fail("a material other than \"phong\" needs an object with \"type\"");
    if (!m.isString() && m.isObject()) m.onlyKeys({});
    return;
  }
  if (!m.requireObject()) return;
  std::set<std::string> keys;
  for (const auto& field : materialFields()) keys.insert(field.info.name);
  m.onlyKeys(keys);
  const SceneObject defaults;
  for (const auto& field : materialFields()) {
    const SettingInfo& info = field.info;
    const JsonReader value = m[info.name.c_str()];
    nlohmann::json read;
    switch (info.kind) {
      case SettingInfo::Kind::Choice: {
        read = value.string(field.get(defaults).get<std::string>());
        if (value.ok() && !info.check(read).empty()) value.fail("expected " + info.expected());
        break;
      }
      case SettingInfo::Kind::Number:
        read = value.number(field.get(defaults).get<double>(), info.min, info.max);
        break;
      case SettingInfo::Kind::Integer:
        read = value.integer(field.get(defaults).get<int>(), int(info.min), int(info.max));
        break;
      case SettingInfo::Kind::Flag:
        read = value.boolean(field.get(defaults).get<bool>());
        break;
    }
    if (!m.ok()) return;
    field.set(o, read);
  }
}

void readAnimation(const JsonReader& a, SceneObject& o) {
  if (!a.requireObject()) return;
  a.onlyKeys({"type", "degreesPerSecond", "axis"});
  const std::string type = a["type"].string("");
  if (type == "orbit") {
    o.motion = Motion::Orbit;
  } else if (type == "spin") {
    o.motion = Motion::Spin;
  } else {
    a["type"].fail("expected \"orbit\" or \"spin\"");
  }
  o.degreesPerSecond = a["degreesPerSecond"].number(27.0, -36000, 36000);
  o.axis = a["axis"].vec3({0, 1, 0});
  if (a.ok() && glm::length(o.axis) == 0.0f) a["axis"].fail("must not be zero");
}

SceneObject readObject(const JsonReader& r, std::vector<std::string>& probeGroups) {
  SceneObject o;
  if (!r.requireObject()) return o;
  r.onlyKeys({"mesh", "translate", "rotate", "scale", "colour", "material", "animation", "probe",
              "probeCentre", "ambient", "ambientRadius"});
  if (!r.has("mesh")) r["mesh"].fail("missing (expected an .obj file name)");
  o.mesh = readPath(r["mesh"]);
  if (r.ok() && o.mesh.size() < 5) r["mesh"].fail("expected an .obj file name");
  const glm::vec3 translate = r["translate"].vec3({0, 0, 0});
  glm::mat4 rotate(1.0f);
  if (r.has("rotate")) {
    const JsonReader rot = r["rotate"];
    if (rot.requireObject()) {
      rot.onlyKeys({"axis", "degrees"});
      const glm::vec3 axis = rot["axis"].vec3({0, 1, 0});
      const double degrees = rot["degrees"].number(0, -36000, 36000);
      if (glm::length(axis) == 0.0f) {
        rot["axis"].fail("must not be zero");
      } else {
        rotate = glm::rotate(glm::mat4(1.0f), glm::radians(static_cast<float>(degrees)),
                             glm::normalize(axis));
      }
    }
  }
  const glm::vec3 scale = r["scale"].scaleVec3({1, 1, 1});
  o.placement = glm::scale(glm::translate(glm::mat4(1.0f), translate) * rotate, scale);
  o.colour = r["colour"].vec3({1, 1, 1});
  if (r.has("material")) readMaterial(r["material"], o);
  if (r.has("animation")) readAnimation(r["animation"], o);
  if (r.has("probeCentre")) o.probeCentre = r["probeCentre"].vec3({0, 0, 0});
  if (r.has("ambient")) {
    const JsonReader a = r["ambient"];
    const std::string ambient = a.string("");
    if (ambient == "probe" || ambient == "own-probe") {
      o.ambient = ambient == "probe" ? Ambient::Probe : Ambient::OwnProbe;
      if (o.material != Material::Phong) a.fail("\"" + ambient + "\" lights a Phong object only");
    } else if (ambient != "constant" && a.ok()) {
      a.fail("expected \"constant\", \"probe\" or \"own-probe\"");
    }
  }
  if (r.has("ambientRadius")) {
    const JsonReader radius = r["ambientRadius"];
    if (radius.isString()) {
      if (radius.string("") != "measured")
        radius.fail("expected a number from 0 to 1000 or \"measured\"");
    } else {
      o.ambientRadius = static_cast<float>(radius.number(0, 0, 1000));
    }
    if (radius.ok() && o.ambient == Ambient::Constant) {
      radius.fail("needs \"ambient\": \"probe\" or \"own-probe\"");
    }
  }
  if (r.has("probe")) {
    const std::string group = r["probe"].string("");
    auto it = std::find(probeGroups.begin(), probeGroups.end(), group);
    if (it == probeGroups.end()) it = probeGroups.insert(probeGroups.end(), group);
    o.probeGroup = static_cast<int>(it - probeGroups.begin());
  }
  return o;
}

void readSkybox(const JsonReader& r, SkyboxSource& skybox) {
  if (r.isString()) {
    const std::string path = readPath(r);
    const auto paths = skyboxSuffixPaths(path);
    for (size_t i = 0; i < 6; ++i) skybox.faces[i] = paths[i];
    return;
  }
  if (!r.requireObject()) return;
  r.onlyKeys({"faces", "cross"});
  if (r.has("cross") == r.has("faces")) {
    r.fail("expected either \"faces\" (6 paths) or \"cross\" (one image)");
    return;
  }
  if (r.has("cross")) {
    skybox.cross = readPath(r["cross"]);
    return;
  }
  const JsonReader faces = r["faces"];
  if (!faces.requireArray()) return;
  if (faces.size() != 6) {
    faces.fail("expected 6 paths in the order +X -X +Y -Y +Z -Z");
    return;
  }
  for (size_t i = 0; i < 6; ++i) skybox.faces[i] = readPath(faces[i]);
}

}  // namespace

Result<Scene> parseSceneJson(const std::string& text, const std::string& source) {
  if (text.size() > kMaxSceneFileBytes) {
    return Result<Scene>::failure(source + ": " + std::to_string(text.size()) +
                                  " bytes, over the limit of " +
                                  std::to_string(kMaxSceneFileBytes));
  }
  Result<nlohmann::json> json = parseJson(text, source);
  if (!json) return Result<Scene>::failure(json.error());
  std::string error;
  const JsonReader root(json.value(), "", &error);
  Scene scene;
  scene.objects.clear();
  if (root.requireObject()) {
    root.onlyKeys(
        {"title", "description", "camera", "light", "background", "skybox", "capture", "objects"});
    scene.title = root["title"].string("untitled scene");
    root["description"].string("");
    if (root.has("camera")) {
      const JsonReader c = root["camera"];
      if (c.requireObject()) {
        c.onlyKeys({"eye", "fovY", "near", "far"});
        scene.camera.eye = c["eye"].vec3(scene.camera.eye);
        scene.camera.fovYDeg = static_cast<float>(c["fovY"].number(70, 1, 179));
        scene.camera.near = static_cast<float>(c["near"].number(1, 1e-4, 1e5));
        scene.camera.far = static_cast<float>(c["far"].number(100, 1e-3, 1e7));
        if (error.empty() && scene.camera.far <= scene.camera.near)
          c["far"].fail("must be greater than near");
      }
    }
    if (root.has("light")) {
      const JsonReader l = root["light"];
      if (l.requireObject()) {
        l.onlyKeys({"position", "ambient", "diffuse", "specular", "shininess"});
        scene.light.position = l["position"].vec3(scene.light.position);
        scene.light.ambient = static_cast<float>(l["ambient"].number(0.2, 0, 10));
        scene.light.diffuse = static_cast<float>(l["diffuse"].number(0.7, 0, 10));
        scene.light.specular = static_cast<float>(l["specular"].number(1.0, 0, 10));
        scene.light.shininess = static_cast<float>(l["shininess"].number(10, 0, 10000));
      }
    }
    scene.clearColour = root["background"].vec3(scene.clearColour);
    if (root.has("skybox")) readSkybox(root["skybox"], scene.skybox);
    if (root.has("capture")) {
      const JsonReader c = root["capture"];
      if (c.requireObject()) {
        c.onlyKeys({"faceSize", "near", "far"});
        scene.capture.faceSize = c["faceSize"].integer(256, 1, 4096);
        scene.capture.near = static_cast<float>(c["near"].number(1, 1e-4, 1e5));
        scene.capture.far = static_cast<float>(c["far"].number(100, 1e-3, 1e7));
      }
    }
    const JsonReader objects = root["objects"];
    if (objects.requireArray()) {
      if (objects.size() > kMaxSceneObjects) {
        objects.fail("more than " + std::to_string(kMaxSceneObjects) + " objects");
      }
      std::vector<std::string> probeGroups;
      for (size_t i = 0; i < objects.size() && error.empty(); ++i) {
        scene.objects.push_back(readObject(objects[i], probeGroups));
      }
      if (error.empty() && scene.objects.empty()) objects.fail("a scene needs at least one object");
      const auto has = [&](bool (SceneObject::*what)() const) {
        return std::any_of(scene.objects.begin(), scene.objects.end(),
                           [&](const SceneObject& o) { return (o.*what)(); });
      };
      const auto readsNearest = [](const SceneObject& o) { return o.ambient == Ambient::Probe; };
      const bool nearestReader =
          std::any_of(scene.objects.begin(), scene.objects.end(), readsNearest);
      if (error.empty() && nearestReader && !has(&SceneObject::needsLiveProbe) &&
          !has(&SceneObject::ownsLightProbe)) {
        objects.fail(
            "an object with \"ambient\": \"probe\" needs a live probe to read (a mirror, glass "
            "or cube-textured object with a live environment)");
      }
    }
  }
  if (!error.empty()) return Result<Scene>::failure(source + ": " + error);
  return scene;
}

Result<SceneObject> parseSceneObjectJson(const std::string& text, const std::string& source) {
  Result<nlohmann::json> json = parseJson(text, source);
  if (!json) return Result<SceneObject>::failure(json.error());
  std::string error;
  std::vector<std::string> groups;
  SceneObject object = readObject(JsonReader(json.value(), "", &error), groups);
  if (!error.empty()) return Result<SceneObject>::failure(source + ": " + error);
  return object;
}

std::string applyMaterialJson(const std::string& text, const std::string& source,
                              SceneObject& object) {
  Result<nlohmann::json> json = parseJson(text, source);
  if (!json) return json.error();
  std::string error;
  SceneObject changed = object;
  readMaterial(JsonReader(json.value(), "material", &error), changed);
  if (!error.empty()) return source + ": " + error;
  object = changed;
  return {};
}

Result<Scene> loadSceneFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return Result<Scene>::failure(path + ": cannot open file");
  std::ostringstream text;
  text << file.rdbuf();
  Result<Scene> scene = parseSceneJson(text.str(), path);
  if (scene) {
    const size_t slash = path.find_last_of('/');
    std::string stem = path.substr(slash == std::string::npos ? 0 : slash + 1);
    scene.value().name = stem.substr(0, stem.rfind(".json"));
  }
  return scene;
}

}  // namespace reflect
