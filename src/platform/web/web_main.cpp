// The browser entry point: a WebGL2 context on #canvas and the C functions the page calls
// (web/app.js drives the frame loop, input and file loading; this file owns no policy).
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <memory>
#include <string>

#include "app/demo.h"
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
