// Loading scenes into the page. A scene is loaded in stages, the page fetching each file the
// scene names: begin (parse the JSON) -> meshes and skybox images -> commit. The scene on screen
// stays until commit succeeds, so a bad file never costs the user the scene they had. Also here:
// the current scene's meshes for the page's level-of-detail builder, and the objects it adds.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh_lod.h"
#include "core/scene_file.h"
#include "core/settings_schema.h"
#include "core/skybox_faces.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using reflect::JsonReader;
using reflect::web::parseRequest;
using reflect::web::reply;
using reflect::web::replyDone;
using reflect::web::replyError;
using reflect::web::state;

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

std::string bytesText(const uint8_t* bytes, int length) {
  if (!bytes || length <= 0) return {};
  return std::string(reinterpret_cast<const char*>(bytes), static_cast<size_t>(length));
}

// The current scene's level-0 mesh named by the request's "name", or null.
const reflect::MeshData* requestedMesh(const json& request) {
  if (!state().demo || !request.contains("name") || !request["name"].is_string()) return nullptr;
  return state().demo->meshLevel(request["name"].get<std::string>(), 0);
}

}  // namespace

extern "C" {

// Parses a scene file (`bytes`); {"source": "the URL it came from"} names it in messages and
// gives the scene its name (the file name without .json). On success it becomes the pending
// scene. {} or {"error"} (naming the file and the key path).
EMSCRIPTEN_KEEPALIVE const char* rf_begin_scene(const char* request, const uint8_t* bytes,
                                                int length) {
  auto r = parseRequest(request, "rf_begin_scene");
  if (!r) return replyError(r.error());
  std::string error;
  const std::string source = JsonReader(r.value(), "", &error)["source"].string("scene");
  if (!error.empty()) return replyError("rf_begin_scene: " + error);
  reflect::Result<reflect::Scene> scene = reflect::parseSceneJson(bytesText(bytes, length), source);
  if (!scene) return replyError(scene.error());
  std::string name = source;
  const size_t slash = name.find_last_of('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  scene.value().name = name.substr(0, name.rfind(".json"));
  auto& pending = state().pending;
  pending.demo = std::make_unique<reflect::Demo>(scene.take());
  const size_t images = skyboxFiles(pending.demo->scene()).size();
  pending.skyboxImages.assign(images, reflect::RgbaImage{});
  pending.skyboxReceived.assign(images, false);
  return replyDone();
}

// The pending scene's model file names and skybox image paths:
// {"meshes": ["quad.obj", ...], "skybox": ["skybox/sky_cross.png"], "title": "..."}
EMSCRIPTEN_KEEPALIVE const char* rf_pending_files() {
  const auto& pending = state().pending;
  if (!pending.demo) return reply(json::object());
  const reflect::Scene& scene = pending.demo->scene();
  return reply(
      {{"meshes", scene.meshNames()}, {"skybox", skyboxFiles(scene)}, {"title", scene.title}});
}

// OBJ text (`bytes`) for mesh "name" of the pending scene, or of the current one when "pending"
// is false (to replace a model in place or add one); "source" names the file in messages.
// {} or {"error"} (the mesh it had is kept), or {"warnings": [...]} when the file loaded with
// something the loader let pass (Demo::lastWarnings: each names the file and the first line).
EMSCRIPTEN_KEEPALIVE const char* rf_load_mesh(const char* request, const uint8_t* bytes,
                                              int length) {
  auto r = parseRequest(request, "rf_load_mesh");
  if (!r) return replyError(r.error());
  std::string error;
  const JsonReader in(r.value(), "", &error);
  in.onlyKeys({"name", "source", "pending"});
  const std::string name = in["name"].string("");
  const std::string source = in["source"].string(name);
  const bool pending = in["pending"].boolean(false);
  if (error.empty() && name.empty()) in["name"].fail("missing");
  if (!error.empty()) return replyError("rf_load_mesh: " + error);
  reflect::Demo* demo = pending ? state().pending.demo.get() : state().demo.get();
  if (!demo) return replyError("no scene to load a model into");
  error = demo->loadMeshText(name, bytesText(bytes, length), source);
  if (!error.empty()) return replyError(error);
  if (demo->lastWarnings().empty()) return replyDone();
  return reply({{"warnings", demo->lastWarnings()}});
}

// Skybox image "index" (in the order of rf_pending_files) as PNG/JPEG `bytes`; "source" names it.
EMSCRIPTEN_KEEPALIVE const char* rf_pending_skybox_image(const char* request, const uint8_t* bytes,
                                                         int length) {
  auto r = parseRequest(request, "rf_pending_skybox_image");
  if (!r) return replyError(r.error());
  std::string error;
  const JsonReader in(r.value(), "", &error);
  const std::string source = in["source"].string("image");
  const int index = in["index"].integer(-1, -1, 1 << 20);
  if (!error.empty()) return replyError("rf_pending_skybox_image: " + error);
  auto& pending = state().pending;
  if (!pending.demo || index < 0 || static_cast<size_t>(index) >= pending.skyboxImages.size()) {
    return replyError(source + ": not an image this scene asked for");
  }
  reflect::Result<reflect::RgbaImage> image =
      reflect::decodeImage(bytes, static_cast<size_t>(std::max(length, 0)), source);
  if (!image) return replyError(image.error());
  pending.skyboxImages[static_cast<size_t>(index)] = image.take();
  pending.skyboxReceived[static_cast<size_t>(index)] = true;
  return replyDone();
}

// Makes the pending scene the current one once everything is there and its GL resources are
// made; {"cubeSize": N} (N > 0) overrides the scene's face size. {} or {"error"} (the old scene
// stays); a clamped cube size is not an error but {"notice": "..."}.
EMSCRIPTEN_KEEPALIVE const char* rf_commit_scene(const char* request) {
  auto r = parseRequest(request, "rf_commit_scene");
  if (!r) return replyError(r.error());
  std::string error;
  const int cubeSize = JsonReader(r.value(), "", &error)["cubeSize"].integer(0, 0, 1 << 30);
  if (!error.empty()) return replyError("rf_commit_scene: " + error);
  auto& pending = state().pending;
  if (!pending.demo) return replyError("no scene is being loaded");
  for (const std::string& name : pending.demo->scene().meshNames()) {
    if (!pending.demo->meshLevel(name, 0)) return replyError(name + ": not loaded");
  }
  error = commitSkybox(pending);
  if (!error.empty()) return replyError(error);
  std::string notice;
  if (cubeSize > 0) notice = pending.demo->setCubeFaceSize(cubeSize);
  if (state().demo) {
    // The user's capture and accuracy settings carry over to the new scene.
    pending.demo->setPlannerSettings(state().demo->plannerSettings());
    pending.demo->setAccuracySettings(state().demo->accuracySettings());
  }
  pending.demo->setShowError(state().view.showError);
  error = pending.demo->initGraphics();
  if (!error.empty()) return replyError(error);
  if (state().demo) state().demo->releaseGraphics();
  state().demo = std::move(pending.demo);
  pending = {};
  return replyDone(notice);
}

// The current scene: {"name", "title", "meshes": [...], "cubeFaceSize": the capture's face size,
// "environments": the material environments it can give ("live", and "skybox" with a skybox)}.
EMSCRIPTEN_KEEPALIVE const char* rf_scene_json() {
  if (!state().demo) return reply(json::object());
  const reflect::Demo& demo = *state().demo;
  json environments = {reflect::environmentName(reflect::Environment::LiveProbe)};
  if (demo.hasSkybox())
    environments.push_back(reflect::environmentName(reflect::Environment::Skybox));
  return reply({{"name", demo.scene().name},
                {"title", demo.scene().title},
                {"meshes", demo.scene().meshNames()},
                {"cubeFaceSize", demo.scene().capture.faceSize},
                {"environments", environments}});
}

// Level 0 of mesh {"name"} of the current scene, for the page's simplifier: {"vertices": pointer,
// "vertexCount" (6 floats a vertex, position first), "vertexFloats": 6, "indices": pointer,
// "indexCount"} into wasm memory, valid until it changes; {} when there is no such mesh.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_arrays(const char* request) {
  auto r = parseRequest(request, "rf_mesh_arrays");
  if (!r) return replyError(r.error());
  const reflect::MeshData* mesh = requestedMesh(r.value());
  if (!mesh) return reply(json::object());
  return reply({{"vertices", reinterpret_cast<uintptr_t>(mesh->vertices.data())},
                {"vertexCount", mesh->vertices.size()},
                {"vertexFloats", sizeof(reflect::Vertex) / sizeof(float)},
                {"indices", reinterpret_cast<uintptr_t>(mesh->indices.data())},
                {"indexCount", mesh->indices.size()}});
}

// How the page should build levels of detail (the settings the native build uses).
EMSCRIPTEN_KEEPALIVE const char* rf_lod_settings_json() {
  const reflect::LodSettings s;
  return reply({{"maxLevels", s.maxLevels},
                {"triangleRatio", s.triangleRatio},
                {"targetError", s.targetError},
                {"minTriangles", s.minTriangles}});
}

// The next level of detail of mesh {"name"}: `count` indices into its level-0 vertices.
EMSCRIPTEN_KEEPALIVE const char* rf_add_lod(const char* request, const uint32_t* indices,
                                            int count) {
  auto r = parseRequest(request, "rf_add_lod");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("no scene loaded");
  std::string error;
  const std::string name = JsonReader(r.value(), "", &error)["name"].string("");
  if (!error.empty()) return replyError("rf_add_lod: " + error);
  std::vector<uint32_t> list;
  if (indices && count > 0) list.assign(indices, indices + count);
  return replyError(state().demo->addLodLevel(name, list));
}

// Adds an object to the current scene: the request is an entry of a scene file's "objects" whose
// mesh was loaded first with rf_load_mesh. The mesh may have any name (a user's file name): it is
// not a path to fetch, so the scene file's path rule does not apply to it. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_add_object(const char* request) {
  auto r = parseRequest(request, "rf_add_object");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("no scene loaded");
  json entry = r.value();
  if (!entry.contains("mesh") || !entry["mesh"].is_string()) {
    return replyError("object: mesh: expected the name of a loaded mesh");
  }
  const std::string mesh = entry["mesh"].get<std::string>();
  entry["mesh"] = "added.obj";  // checked as a scene file's entry, then given its own name
  reflect::Result<reflect::SceneObject> object =
      reflect::parseSceneObjectJson(entry.dump(), "object");
  if (!object) return replyError(object.error());
  object.value().mesh = mesh;
  return replyError(state().demo->addObject(object.value()));
}

// Object-space bounds of mesh {"name"} of the current scene: {"min": [..], "max": [..]}, or {}.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_bounds_json(const char* request) {
  auto r = parseRequest(request, "rf_mesh_bounds_json");
  if (!r) return replyError(r.error());
  const reflect::MeshData* mesh = requestedMesh(r.value());
  if (!mesh) return reply(json::object());
  const auto& b = mesh->bounds;
  return reply({{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}});
}

}  // extern "C"
