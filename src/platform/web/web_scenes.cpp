// Loading scenes into the page. A scene is loaded in stages, the page fetching each file the
// scene names: begin (parse the JSON) -> meshes and skybox images -> commit. The scene on screen
// stays until commit succeeds, so a bad file never costs the user the scene they had. The current
// scene's meshes for the page's level builder and the objects it adds are in web_meshes.cpp.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh_chunks.h"
#include "core/mesh_lod.h"
#include "core/scene_file.h"
#include "core/settings_schema.h"
#include "core/skybox_faces.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using reflect::JsonReader;
using namespace reflect::web;  // the bridge's helpers: web_state.h

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

// The demo a mesh request names: the pending scene's ("pending": true) or the current one's.
reflect::Demo* demoFor(bool pending) {
  return pending ? state().pending.demo.get() : state().demo.get();
}

// Which mesh a model load goes to: {"name", "source" (names the file in messages), "pending"
// (the scene being loaded, else the current one)}. Sets `error` (prefixed with `call`) when bad.
struct MeshTarget {
  std::string name, source;
  bool pending = false;
};
MeshTarget meshTarget(const json& request, const char* call, std::string* error) {
  const JsonReader in(request, "", error);
  in.onlyKeys({"name", "source", "pending"});
  MeshTarget target{in["name"].string(""), "", in["pending"].boolean(false)};
  target.source = in["source"].string(target.name);
  if (error->empty() && target.name.empty()) in["name"].fail("missing");
  if (!error->empty()) *error = std::string(call) + ": " + *error;
  return target;
}

// A model load's reply: {"error"}, {} or {"warnings": [...]} (what the loader let pass).
const char* replyLoaded(const reflect::Demo& demo, const std::string& error) {
  if (!error.empty()) return replyError(error);
  if (demo.lastWarnings().empty()) return replyDone();
  return reply({{"warnings", demo.lastWarnings()}});
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
  // The page's worker builds chunks and levels of detail (web/lod.js), after the first frame.
  pending.demo->setLevelBuilds(reflect::Demo::LevelBuilds::External);
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

// OBJ text (`bytes`, whole) for mesh "name" of the pending scene, or of the current one when
// "pending" is false (to replace a model in place or add one); "source" names the file in
// messages. {} or {"error"} (the mesh it had is kept), or {"warnings": [...]} when the file loaded
// with something the loader let pass (Demo::lastWarnings: each names the file and the first
// line). Large files go through rf_mesh_stream_* instead.
EMSCRIPTEN_KEEPALIVE const char* rf_load_mesh(const char* request, const uint8_t* bytes,
                                              int length) {
  auto r = parseRequest(request, "rf_load_mesh");
  if (!r) return replyError(r.error());
  std::string error;
  const MeshTarget target = meshTarget(r.value(), "rf_load_mesh", &error);
  if (!error.empty()) return replyError(error);
  reflect::Demo* demo = demoFor(target.pending);
  if (!demo) return replyError("no scene to load a model into");
  return replyLoaded(*demo,
                     demo->loadMeshText(target.name, bytesText(bytes, length), target.source));
}

// Starts streaming an OBJ file into mesh "name" ("source" names it in messages; "pending" as for
// rf_load_mesh). {"stream": id} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_stream_begin(const char* request) {
  auto r = parseRequest(request, "rf_mesh_stream_begin");
  if (!r) return replyError(r.error());
  std::string error;
  const MeshTarget target = meshTarget(r.value(), "rf_mesh_stream_begin", &error);
  if (!error.empty()) return replyError(error);
  if (!demoFor(target.pending)) return replyError("no scene to load a model into");
  const int id = state().nextStream++;
  state().streams.emplace(id, reflect::web::MeshStream{target.name, target.pending,
                                                       reflect::ObjStreamParser(target.source)});
  return reply({{"stream", id}});
}

// The next piece of stream {"stream": id}: `bytes`, cut anywhere. {} or {"error"} (the file is
// broken: the stream is closed, the mesh it had kept).
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_stream_feed(const char* request, const uint8_t* bytes,
                                                     int length) {
  auto r = parseRequest(request, "rf_mesh_stream_feed");
  if (!r) return replyError(r.error());
  std::string error;
  const int id = JsonReader(r.value(), "", &error)["stream"].integer(0, 0, 1 << 30);
  if (!error.empty()) return replyError("rf_mesh_stream_feed: " + error);
  auto it = state().streams.find(id);
  if (it == state().streams.end()) return replyError("no such model stream");
  const std::string_view piece(reinterpret_cast<const char*>(bytes),
                               bytes && length > 0 ? static_cast<size_t>(length) : 0);
  if (it->second.parser.feed(piece)) return replyDone();
  error = it->second.parser.error();
  state().streams.erase(it);
  return replyError(error);
}

// The end of stream {"stream": id} (or {"stream": id, "cancel": true} to drop it): the mesh
// replaces the one of its name. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_stream_end(const char* request) {
  auto r = parseRequest(request, "rf_mesh_stream_end");
  if (!r) return replyError(r.error());
  std::string error;
  const JsonReader in(r.value(), "", &error);
  const int id = in["stream"].integer(0, 0, 1 << 30);
  const bool cancel = in["cancel"].boolean(false);
  if (!error.empty()) return replyError("rf_mesh_stream_end: " + error);
  auto it = state().streams.find(id);
  if (it == state().streams.end()) return cancel ? replyDone() : replyError("no such model stream");
  reflect::web::MeshStream stream = std::move(it->second);
  state().streams.erase(it);
  if (cancel) return replyDone();
  reflect::Demo* demo = demoFor(stream.pending);
  if (!demo) return replyError("no scene to load a model into");
  return replyLoaded(*demo, demo->setLoadedMesh(stream.name, stream.parser.finish()));
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
// stays); a clamped cube size, or a near plane outside a reflector (Demo::captureNearNotice),
// is not an error but {"notice": "..."}.
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
  const std::string nearNotice = pending.demo->captureNearNotice();
  if (!nearNotice.empty()) notice += (notice.empty() ? "" : "; ") + nearNotice;
  if (state().demo) {
    // The user's capture and accuracy settings carry over to the new scene.
    pending.demo->setPlannerSettings(state().demo->plannerSettings());
    pending.demo->setAccuracySettings(state().demo->accuracySettings());
  }
  pending.demo->setViewSettings(state().view);
  error = pending.demo->initGraphics();
  if (!error.empty()) return replyError(error);
  if (state().demo) state().demo->releaseGraphics();
  state().demo = std::move(pending.demo);
  pending = {};
  // The trees' share of the commit, for load-time accounting (tools/peer_bench.mjs --load).
  nlohmann::json out = {{"bvhMs", state().demo->bvhBuildMs()}};
  if (!notice.empty()) out["notice"] = notice;
  return reply(out);
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

}  // extern "C"
