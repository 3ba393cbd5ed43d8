// The current scene's meshes as the page needs them: their arrays and the settings for the
// level-of-detail worker, the levels it hands back, their bounds, and the objects the page adds.
#include <emscripten/emscripten.h>

#include <span>
#include <string>
#include <vector>

#include "core/json_reader.h"
#include "core/mesh_chunks.h"
#include "core/mesh_lod.h"
#include "core/scene_file.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using reflect::JsonReader;
using namespace reflect::web;  // the bridge's helpers: web_state.h

// The current scene's level-0 mesh named by the request's "name", or null.
const reflect::MeshData* requestedMesh(const json& request) {
  if (!state().demo || !request.contains("name") || !request["name"].is_string()) return nullptr;
  return state().demo->meshLevel(request["name"].get<std::string>(), 0);
}

// The request's name, revision and chunk sizes, and `count` indices at `indices`.
struct LevelRequest {
  std::string name;
  uint32_t revision = 0;
  std::vector<uint32_t> chunkTriangles;
  // The caller's indices, not copied: a level keeps a copy, the chunk order is copied over the
  // mesh's own indices (a second array of a heavy mesh's would raise the wasm heap's peak).
  std::span<const uint32_t> indices;
};

reflect::Result<LevelRequest> levelRequest(const char* request, const char* function,
                                           const uint32_t* indices, int count) {
  using Out = reflect::Result<LevelRequest>;
  auto r = parseRequest(request, function);
  if (!r) return Out::failure(r.error());
  std::string error;
  const JsonReader in(r.value(), "", &error);
  in.onlyKeys({"name", "revision", "chunkTriangles"});
  LevelRequest out;
  out.name = in["name"].string("");
  out.revision = static_cast<uint32_t>(in["revision"].integer(0, 0, 1 << 30));
  if (r.value().contains("chunkTriangles") && r.value()["chunkTriangles"].is_array()) {
    for (const json& n : r.value()["chunkTriangles"]) {
      if (!n.is_number_unsigned())
        return Out::failure(std::string(function) + ": bad chunkTriangles");
      out.chunkTriangles.push_back(n.get<uint32_t>());
    }
  }
  if (!error.empty()) return Out::failure(std::string(function) + ": " + error);
  if (indices && count > 0) out.indices = {indices, static_cast<size_t>(count)};
  return out;
}

}  // namespace

extern "C" {

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
                {"minTriangles", s.minTriangles},
                {"chunkTriangles", reflect::kChunkTriangles}});
}

// What is left to build for the page's worker (web/lod.js): [{"name", "revision", "chunks":
// bool, "coarser": bool}]: what the frames drew wants (a captured face: chunks and capture LOD's
// levels; view LOD's levels while it is on), or everything since rf_ask_levels.
EMSCRIPTEN_KEEPALIVE const char* rf_level_jobs() {
  json jobs = json::array();
  if (state().demo) {
    for (const reflect::Demo::LevelJob& job : state().demo->levelJobs()) {
      jobs.push_back({{"name", job.name},
                      {"revision", job.revision},
                      {"chunks", job.chunks},
                      {"coarser", job.coarser}});
    }
  }
  return reply(jobs);
}

// From now on every mesh's chunks and, while a LOD setting is on, its coarser levels are wanted,
// whatever the frames draw (demo.lodReady(): tests and the bench want the meshes the settings
// could draw). {}.
EMSCRIPTEN_KEEPALIVE const char* rf_ask_levels() {
  if (state().demo) state().demo->askForLevels();
  return replyDone();
}

// Mesh {"name", "revision"}'s triangles in chunk order: `count` indices (a reordering of its
// own) and {"chunkTriangles": [...]} the chunks' triangle counts. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_set_mesh_chunks(const char* request, const uint32_t* indices,
                                                    int count) {
  if (!state().demo) return replyError("no scene loaded");
  auto r = levelRequest(request, "rf_set_mesh_chunks", indices, count);
  if (!r) return replyError(r.error());
  LevelRequest& q = r.value();
  return replyError(state().demo->setMeshChunks(q.name, q.revision, q.indices, q.chunkTriangles));
}

// The next coarser level of mesh {"name", "revision"}: `count` indices into its level-0
// vertices, in chunk order, {"chunkTriangles": [...]}. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_add_lod(const char* request, const uint32_t* indices,
                                            int count) {
  if (!state().demo) return replyError("no scene loaded");
  auto r = levelRequest(request, "rf_add_lod", indices, count);
  if (!r) return replyError(r.error());
  LevelRequest& q = r.value();
  return replyError(state().demo->addLodLevel(
      q.name, q.revision, std::vector<uint32_t>(q.indices.begin(), q.indices.end()),
      q.chunkTriangles));
}

// Every coarser level of mesh {"name", "revision"} has been given. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_finish_levels(const char* request) {
  if (!state().demo) return replyError("no scene loaded");
  auto r = levelRequest(request, "rf_finish_levels", nullptr, 0);
  if (!r) return replyError(r.error());
  return replyError(state().demo->finishLevels(r.value().name, r.value().revision));
}

// Triangles of each level of mesh {"name"}, level 0 first: {"levels": [..]} ({} if none).
EMSCRIPTEN_KEEPALIVE const char* rf_level_triangles(const char* request) {
  auto r = parseRequest(request, "rf_level_triangles");
  if (!r) return replyError(r.error());
  if (!state().demo || !r.value().contains("name") || !r.value()["name"].is_string()) {
    return reply(json::object());
  }
  return reply({{"levels", state().demo->levelTriangles(r.value()["name"].get<std::string>())}});
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
