// The browser entry point: a WebGL2 context on #canvas and the C functions the page calls
// (web/app.js drives the frame loop, input and file loading; this file owns no policy).
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/mesh_lod.h"
#include "gfx/gl.h"

namespace {

constexpr const char* kCanvas = "#canvas";

std::unique_ptr<reflect::Demo> gDemo;
EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gContext = 0;
std::string gReturnText;  // storage for strings handed back to JS

const char* returnText(std::string text) {
  gReturnText = std::move(text);
  return gReturnText.c_str();
}

std::string makeContextCurrent() {
  EmscriptenWebGLContextAttributes attributes;
  emscripten_webgl_init_context_attributes(&attributes);
  attributes.majorVersion = 2;
  attributes.minorVersion = 0;
  attributes.alpha = EM_FALSE;
  attributes.depth = EM_TRUE;
  // Off, so the page shows exactly the pixels the native build renders for the same time.
  attributes.antialias = EM_FALSE;
  attributes.preserveDrawingBuffer = EM_FALSE;
  gContext = emscripten_webgl_create_context(kCanvas, &attributes);
  if (gContext <= 0) return "WebGL2 is not available in this browser";
  emscripten_webgl_make_context_current(gContext);
  return {};
}

EM_BOOL onContextLost(int, const void*, void*) {
  if (gDemo) gDemo->loseGraphics();
  return EM_TRUE;  // prevents the default, which would forbid a restore
}

EM_BOOL onContextRestored(int, const void*, void*) {
  emscripten_webgl_destroy_context(gContext);
  std::string error = makeContextCurrent();
  if (error.empty() && gDemo) error = gDemo->initGraphics();
  if (!error.empty()) emscripten_log(EM_LOG_ERROR, "context restore failed: %s", error.c_str());
  return EM_TRUE;
}

}  // namespace

extern "C" {

// Creates the demo and its WebGL2 context. Returns "" or an error message for the page.
EMSCRIPTEN_KEEPALIVE const char* rf_create() {
  std::string error = makeContextCurrent();
  if (!error.empty()) return returnText(error);
  gDemo = std::make_unique<reflect::Demo>(reflect::makeDynamicReflectionScene());
  emscripten_set_webglcontextlost_callback(kCanvas, nullptr, EM_FALSE, onContextLost);
  emscripten_set_webglcontextrestored_callback(kCanvas, nullptr, EM_FALSE, onContextRestored);
  return returnText("");
}

// The scene's model file names, as a JSON array.
EMSCRIPTEN_KEEPALIVE const char* rf_mesh_names() {
  std::string json = "[";
  for (const std::string& name : gDemo->scene().meshNames()) {
    json += (json.size() > 1 ? ",\"" : "\"") + name + "\"";
  }
  return returnText(json + "]");
}

// OBJ text for the scene's mesh `name`; `source` names the file in messages. Returns "" or the
// error; on error the mesh the scene had is kept.
EMSCRIPTEN_KEEPALIVE const char* rf_load_mesh(const char* name, const char* text, int length,
                                              const char* source) {
  return returnText(gDemo->loadMeshText(name, std::string(text, static_cast<size_t>(length)), source));
}

EMSCRIPTEN_KEEPALIVE const char* rf_init_graphics(int cubeSize) {
  if (!gDemo->hasAllMeshes()) return returnText("some models are missing");
  gDemo->setCubeFaceSize(cubeSize);
  return returnText(gDemo->initGraphics());
}

// One complete frame into the canvas at its current size. waitForGpu: time it with glFinish.
EMSCRIPTEN_KEEPALIVE const char* rf_frame(double dtSeconds, int waitForGpu) {
  int width = 0, height = 0;
  emscripten_get_canvas_element_size(kCanvas, &width, &height);
  return returnText(gDemo->frame(dtSeconds, 0, width, height, waitForGpu != 0).toJson());
}

EMSCRIPTEN_KEEPALIVE void rf_set_time(double seconds) { gDemo->clock().set(seconds); }

// Capture planning: policy by name ("every-frame", "when-changed", "time-sliced", "every-n"),
// faces per frame for time-sliced, N for every-n, LOD triangles per pixel (0 = off).
// Returns "" or an error for an unknown policy.
EMSCRIPTEN_KEEPALIVE const char* rf_set_planner(const char* policy, int facesPerFrame, int everyN,
                                                double lodTrianglesPerPixel) {
  reflect::PlannerSettings settings = gDemo->plannerSettings();
  if (!reflect::parsePolicy(policy, &settings.policy)) {
    return returnText(std::string("unknown update policy '") + policy + "'");
  }
  settings.facesPerFrame = facesPerFrame;
  settings.everyN = everyN;
  settings.lodTrianglesPerPixel = static_cast<float>(lodTrianglesPerPixel);
  gDemo->setPlannerSettings(settings);
  return returnText("");
}

// {"policy":..., "maxStalenessFrames":...}
EMSCRIPTEN_KEEPALIVE const char* rf_planner_json() {
  const reflect::PlannerSettings& s = gDemo->plannerSettings();
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "{\"policy\":\"%s\",\"facesPerFrame\":%d,\"everyN\":%d,\"lod\":%g,"
                "\"maxStalenessFrames\":%d}",
                reflect::policyName(s.policy), s.facesPerFrame, s.everyN, s.lodTrianglesPerPixel,
                s.maxStalenessFrames());
  return returnText(buffer);
}

// Level 0 of mesh `name` for the page's simplifier: vertex array (6 floats a vertex, position
// first) and index array. Pointers into wasm memory, valid until the mesh changes.
EMSCRIPTEN_KEEPALIVE const void* rf_mesh_vertices(const char* name, int* count) {
  const reflect::MeshData* mesh = gDemo->meshLevel(name, 0);
  *count = mesh ? static_cast<int>(mesh->vertices.size()) : 0;
  return mesh ? mesh->vertices.data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE const void* rf_mesh_indices(const char* name, int* count) {
  const reflect::MeshData* mesh = gDemo->meshLevel(name, 0);
  *count = mesh ? static_cast<int>(mesh->indices.size()) : 0;
  return mesh ? mesh->indices.data() : nullptr;
}
// How the page should build levels of detail (the same settings the native build uses).
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
  return returnText(gDemo->addLodLevel(
      name, std::vector<uint32_t>(indices, indices + std::max(count, 0))));
}
EMSCRIPTEN_KEEPALIVE void rf_drag(float dx, float dy, float canvasHeight) {
  gDemo->camera().drag(dx, dy, canvasHeight);
}
EMSCRIPTEN_KEEPALIVE void rf_move(float steps) { gDemo->camera().move(steps); }
EMSCRIPTEN_KEEPALIVE void rf_reset_camera() { gDemo->camera().reset(); }

// {"eye":[x,y,z],"yaw":deg,"pitch":deg}
EMSCRIPTEN_KEEPALIVE const char* rf_camera_json() {
  const reflect::LookCamera& c = gDemo->camera();
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "{\"eye\":[%.5f,%.5f,%.5f],\"yaw\":%.5f,\"pitch\":%.5f}",
                c.eye().x, c.eye().y, c.eye().z, c.yawDeg(), c.pitchDeg());
  return returnText(buffer);
}

}  // extern "C"
