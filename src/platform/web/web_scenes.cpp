// Loading scenes into the page. A scene is loaded in stages, the page fetching each file the
// scene names: begin (parse the JSON) -> meshes and skybox images -> commit. The scene on screen
// stays until commit succeeds, so a bad file never costs the user the scene they had.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/frame_stats.h"
#include "core/mesh_lod.h"
#include "core/scene_file.h"
#include "core/skybox_faces.h"
#include "platform/web/web_state.h"

namespace {

using reflect::jsonQuote;
using reflect::web::returnText;
using reflect::web::state;

std::string jsonList(const std::vector<std::string>& items) {
  std::string json = "[";
  for (const std::string& item : items) json += (json.size() > 1 ? "," : "") + jsonQuote(item);
  return json + "]";
}

std::vector<std::string> skyboxFiles(const reflect::Scene& scene) {
  if (scene.skybox.empty()) return {};
  if (!scene.skybox.cross.empty()) return {scene.skybox.cross};
  return {scene.skybox.faces.begin(), scene.skybox.faces.end()};
}

std::string commitSkybox(reflect::web::PendingScene& p) {
  const std::vector<std::string> files = skyboxFiles(p.demo->scene());
  if (files.empty()) return {};
  for (size_t i = 0; i < files.size(); ++i) {
    if (!p.skyboxReceived[i]) return files[i] + ": not loaded";
  }
  reflect::Result<reflect::CubeFaces> faces =
      files.size() == 1 ? reflect::facesFromCross(p.skyboxImages[0], files[0])
                        : reflect::facesFromImages(p.skyboxImages, {files[0], files[1], files[2],
                                                                    files[3], files[4], files[5]});
  if (!faces) return faces.error();
  return p.demo->setSkybox(faces.take());
}

}  // namespace

extern "C" {

// Parses a scene file; on success it becomes the pending scene. Returns "" or the error (file
// name and key path).
EMSCRIPTEN_KEEPALIVE const char* rf_begin_scene(const char* json, int length, const char* source) {
  reflect::Result<reflect::Scene> scene =
      reflect::parseSceneJson(std::string(json, static_cast<size_t>(std::max(length, 0))), source);
  if (!scene) return returnText(scene.error());
  std::string name = source;
  const size_t slash = name.find_last_of('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  scene.value().name = name.substr(0, name.rfind(".json"));
  auto& pending = state().pending;
  pending.demo = std::make_unique<reflect::Demo>(scene.take());
  const size_t images = skyboxFiles(pending.demo->scene()).size();
  pending.skyboxImages.assign(images, reflect::RgbaImage{});
  pending.skyboxReceived.assign(images, false);
  return returnText("");
}

// The pending scene's model file names and skybox image paths, as JSON:
// {"meshes":["quad.obj",...],"skybox":["skybox/sky_cross.png"],"title":"..."}
EMSCRIPTEN_KEEPALIVE const char* rf_pending_files() {
  const auto& pending = state().pending;
  if (!pending.demo) return returnText("{}");
  return returnText("{\"meshes\":" + jsonList(pending.demo->scene().meshNames()) +
                    ",\"skybox\":" + jsonList(skyboxFiles(pending.demo->scene())) +
                    ",\"title\":" + jsonQuote(pending.demo->scene().title) + "}");
}

// OBJ text for mesh `name` of the pending scene (or of the current one when `pending` is 0, to
// replace a model in place). Returns "" or the error; on error the mesh it had is kept.
EMSCRIPTEN_KEEPALIVE const char* rf_load_mesh(int pending, const char* name, const char* text,
                                              int length, const char* source) {
  reflect::Demo* demo = pending ? state().pending.demo.get() : state().demo.get();
  if (!demo) return returnText("no scene to load a model into");
  return returnText(demo->loadMeshText(
      name, std::string(text, static_cast<size_t>(std::max(length, 0))), source));
}

// Skybox image `index` (in the order of rf_pending_files) as PNG/JPEG bytes.
EMSCRIPTEN_KEEPALIVE const char* rf_pending_skybox_image(int index, const uint8_t* bytes,
                                                         int length, const char* source) {
  auto& pending = state().pending;
  if (!pending.demo || index < 0 || static_cast<size_t>(index) >= pending.skyboxImages.size()) {
    return returnText(std::string(source) + ": not an image this scene asked for");
  }
  reflect::Result<reflect::RgbaImage> image =
      reflect::decodeImage(bytes, static_cast<size_t>(std::max(length, 0)), source);
  if (!image) return returnText(image.error());
  pending.skyboxImages[static_cast<size_t>(index)] = image.take();
  pending.skyboxReceived[static_cast<size_t>(index)] = true;
  return returnText("");
}

// Makes the pending scene the current one once everything is there and its GL resources are
// made. cubeSize > 0 overrides the scene's face size. Returns "" or an error (the old scene
// stays). A clamped cube size is not an error: it comes back as {"notice": "..."}.
EMSCRIPTEN_KEEPALIVE const char* rf_commit_scene(int cubeSize) {
  auto& pending = state().pending;
  if (!pending.demo) return returnText("no scene is being loaded");
  for (const std::string& name : pending.demo->scene().meshNames()) {
    if (!pending.demo->meshLevel(name, 0)) return returnText(name + ": not loaded");
  }
  std::string error = commitSkybox(pending);
  if (!error.empty()) return returnText(error);
  std::string notice;
  if (cubeSize > 0) notice = pending.demo->setCubeFaceSize(cubeSize);
  if (state().demo) {
    // The user's capture and accuracy settings carry over to the new scene.
    pending.demo->setPlannerSettings(state().demo->plannerSettings());
    pending.demo->setAccuracySettings(state().demo->accuracySettings());
  }
  error = pending.demo->initGraphics();
  if (!error.empty()) return returnText(error);
  if (state().demo) state().demo->releaseGraphics();
  state().demo = std::move(pending.demo);
  pending = {};
  return returnText(notice.empty() ? "" : "{\"notice\":" + jsonQuote(notice) + "}");
}

// The current scene: {"name":...,"title":...,"meshes":[...]}
EMSCRIPTEN_KEEPALIVE const char* rf_scene_json() {
  if (!state().demo) return returnText("{}");
  const reflect::Scene& s = state().demo->scene();
  return returnText("{\"name\":" + jsonQuote(s.name) + ",\"title\":" + jsonQuote(s.title) +
                    ",\"meshes\":" + jsonList(s.meshNames()) + "}");
}

// Level 0 of mesh `name` of the current scene, for the page's simplifier: vertex array (6 floats
// a vertex, position first) and index array; pointers into wasm memory, valid until it changes.
EMSCRIPTEN_KEEPALIVE const void* rf_mesh_vertices(const char* name, int* count) {
  const reflect::MeshData* mesh = state().demo ? state().demo->meshLevel(name, 0) : nullptr;
  *count = mesh ? static_cast<int>(mesh->vertices.size()) : 0;
  return mesh ? mesh->vertices.data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE const void* rf_mesh_indices(const char* name, int* count) {
  const reflect::MeshData* mesh = state().demo ? state().demo->meshLevel(name, 0) : nullptr;
  *count = mesh ? static_cast<int>(mesh->indices.size()) : 0;
  return mesh ? mesh->indices.data() : nullptr;
}
// How the page should build levels of detail (the settings the native build uses).
EMSCRIPTEN_KEEPALIVE const char* rf_lod_settings_json() {
  const reflect::LodSettings s;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "{\"maxLevels\":%d,\"triangleRatio\":%g,\"targetError\":%g,\"minTriangles\":%zu}",
                s.maxLevels, s.triangleRatio, s.targetError, s.minTriangles);
  return returnText(buffer);
}
// The next level of detail of `name` as indices into its level-0 vertices.
EMSCRIPTEN_KEEPALIVE const char* rf_add_lod(const char* name, const uint32_t* indices, int count) {
  if (!state().demo) return returnText("no scene loaded");
  return returnText(state().demo->addLodLevel(
      name, std::vector<uint32_t>(indices, indices + std::max(count, 0))));
}

}  // extern "C"

extern "C" {

// Adds an object to the current scene: an entry of a scene file's "objects" (its mesh loaded
// first with rf_load_mesh(0, ...)). Returns "" or the error.
EMSCRIPTEN_KEEPALIVE const char* rf_add_object(const char* json) {
  if (!state().demo) return returnText("no scene loaded");
  reflect::Result<reflect::SceneObject> object = reflect::parseSceneObjectJson(json, "object");
  if (!object) return returnText(object.error());
  return returnText(state().demo->addObject(object.value()));
}

// Object-space bounds of a loaded mesh of the current scene: {"min":[..],"max":[..]} or {}.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_bounds_json(const char* name) {
  const reflect::MeshData* mesh = state().demo ? state().demo->meshLevel(name, 0) : nullptr;
  if (!mesh) return returnText("{}");
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "{\"min\":[%g,%g,%g],\"max\":[%g,%g,%g]}",
                mesh->bounds.min.x, mesh->bounds.min.y, mesh->bounds.min.z, mesh->bounds.max.x,
                mesh->bounds.max.y, mesh->bounds.max.z);
  return returnText(buffer);
}

// Changes object `index`'s material: a scene file's "material" object, e.g.
// {"type":"mirror","reflection":0.78,"base":0.3,"fresnel":true,"ior":1.52}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_material(int index, const char* json) {
  if (!state().demo) return returnText("no scene loaded");
  return returnText(state().demo->setMaterialJson(index, json));
}

// The current scene's objects and materials, as JSON.
EMSCRIPTEN_KEEPALIVE const char* rf_objects_json() {
  if (!state().demo) return returnText("[]");
  std::string json = "[";
  const char* names[] = {"phong", "mirror", "glass", "cube-textured"};
  for (const reflect::SceneObject& o : state().demo->scene().objects) {
    char buffer[320];
    std::snprintf(buffer, sizeof buffer,
                  "%s{\"mesh\":%s,\"material\":{\"type\":\"%s\",\"reflection\":%g,\"base\":%g,"
                  "\"ior\":%g,\"fresnel\":%s,\"environment\":\"%s\"}}",
                  json.size() > 1 ? "," : "", reflect::jsonQuote(o.mesh).c_str(),
                  names[static_cast<int>(o.material)], o.reflection, o.base, o.ior,
                  o.fresnel ? "true" : "false",
                  o.environment == reflect::Environment::Skybox ? "skybox" : "live");
    json += buffer;
  }
  return returnText(json + "]");
}

// Accuracy mode: {"distance":2,"origin":false,"depth":24,"mipmaps":false,"halfFloat":false,
// "mediump":false} (missing keys keep their value). Rebuilds the GL resources. "" or an error.
EMSCRIPTEN_KEEPALIVE const char* rf_set_accuracy(int distanceIterations, int captureAtOrigin,
                                                 int depthBits, int mipmaps, int halfFloat,
                                                 int mediump) {
  if (!state().demo) return returnText("no scene loaded");
  reflect::AccuracySettings a = state().demo->accuracySettings();
  a.search = distanceIterations > 0 ? reflect::Search::Hierarchical : reflect::Search::Plain;
  a.captureAtOrigin = captureAtOrigin != 0;
  a.depthBits = depthBits;
  a.mipmaps = mipmaps != 0;
  a.halfFloat = halfFloat != 0;
  a.mediump = mediump != 0;
  return returnText(state().demo->setAccuracySettings(a));
}

EMSCRIPTEN_KEEPALIVE const char* rf_accuracy_json() {
  if (!state().demo) return returnText("{}");
  const reflect::AccuracySettings& a = state().demo->accuracySettings();
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "{\"distance\":%d,\"origin\":%s,\"depth\":%d,\"mipmaps\":%s,\"halfFloat\":%s,"
                "\"mediump\":%s,\"describe\":%s}",
                a.search == reflect::Search::Plain ? 0 : 2, a.captureAtOrigin ? "true" : "false",
                a.depthBits, a.mipmaps ? "true" : "false", a.halfFloat ? "true" : "false",
                a.mediump ? "true" : "false", reflect::jsonQuote(a.describe()).c_str());
  return returnText(buffer);
}

}  // extern "C"
