// The browser entry point: a WebGL2 context on #canvas and the C functions the page calls for
// frames and input (web/app.js drives the loop, input and file loading; this file owns no
// policy). Scene loading is in web_scenes.cpp.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <string>

#include "gfx/gl.h"
#include "platform/web/web_state.h"

namespace reflect::web {

WebState& state() {
  static WebState s;
  return s;
}

const char* returnText(std::string text) {
  state().returnText = std::move(text);
  return state().returnText.c_str();
}

}  // namespace reflect::web

namespace {

using reflect::web::returnText;
using reflect::web::state;

constexpr const char* kCanvas = "#canvas";

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
  state().context = emscripten_webgl_create_context(kCanvas, &attributes);
  if (state().context <= 0) return "WebGL2 is not available in this browser";
  emscripten_webgl_make_context_current(state().context);
  emscripten_webgl_enable_extension(state().context, "EXT_disjoint_timer_query_webgl2");
  return {};
}

EM_BOOL onContextLost(int, const void*, void*) {
  if (state().demo) state().demo->loseGraphics();
  if (state().pending.demo) state().pending.demo->loseGraphics();
  return EM_TRUE;  // prevents the default, which would forbid a restore
}

EM_BOOL onContextRestored(int, const void*, void*) {
  emscripten_webgl_destroy_context(state().context);
  std::string error = makeContextCurrent();
  // Every GL resource is rebuilt from CPU-side data; the planner recaptures every probe.
  if (error.empty() && state().demo) error = state().demo->initGraphics();
  if (!error.empty()) emscripten_log(EM_LOG_ERROR, "context restore failed: %s", error.c_str());
  return EM_TRUE;
}

}  // namespace

extern "C" {

// Creates the WebGL2 context. Returns "" or an error message for the page.
EMSCRIPTEN_KEEPALIVE const char* rf_create() {
  std::string error = makeContextCurrent();
  if (!error.empty()) return returnText(error);
  emscripten_set_webglcontextlost_callback(kCanvas, nullptr, EM_FALSE, onContextLost);
  emscripten_set_webglcontextrestored_callback(kCanvas, nullptr, EM_FALSE, onContextRestored);
  return returnText("");
}

// One complete frame into the canvas's drawing buffer, as JSON stats (see FrameStats).
// waitForGpu: time it end to end (a read back after each pass).
EMSCRIPTEN_KEEPALIVE const char* rf_frame(double dtSeconds, int waitForGpu) {
  if (!state().demo) return returnText("{}");
  // The drawing buffer, not the canvas element: past the GPU's limits (a wide canvas at a high
  // devicePixelRatio) the browser gives a smaller buffer, and drawing at the element's size
  // would crop the picture.
  int width = 0, height = 0;
  emscripten_webgl_get_drawing_buffer_size(state().context, &width, &height);
  return returnText(state().demo->frame(dtSeconds, 0, width, height, waitForGpu != 0).toJson());
}

EMSCRIPTEN_KEEPALIVE void rf_set_time(double seconds) {
  if (state().demo) state().demo->clock().set(seconds);
}
EMSCRIPTEN_KEEPALIVE void rf_drag(float dx, float dy, float canvasHeight) {
  if (state().demo) state().demo->camera().drag(dx, dy, canvasHeight);
}
EMSCRIPTEN_KEEPALIVE void rf_move(float steps) {
  if (state().demo) state().demo->camera().move(steps);
}
EMSCRIPTEN_KEEPALIVE void rf_reset_camera() {
  if (state().demo) state().demo->camera().reset();
}
EMSCRIPTEN_KEEPALIVE void rf_set_camera(float x, float y, float z, float yawDeg, float pitchDeg) {
  if (!state().demo) return;
  state().demo->camera().setEye({x, y, z});
  state().demo->camera().setAngles(yawDeg, pitchDeg);
}

// {"eye":[x,y,z],"yaw":deg,"pitch":deg}
EMSCRIPTEN_KEEPALIVE const char* rf_camera_json() {
  if (!state().demo) return returnText("{}");
  const reflect::LookCamera& c = state().demo->camera();
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "{\"eye\":[%.5f,%.5f,%.5f],\"yaw\":%.5f,\"pitch\":%.5f}",
                c.eye().x, c.eye().y, c.eye().z, c.yawDeg(), c.pitchDeg());
  return returnText(buffer);
}

// Capture planning: policy by name ("every-frame", "when-changed", "time-sliced", "every-n"),
// faces per frame for time-sliced, N for every-n, capture and view LOD triangles per pixel
// (0 = off). Returns "" or an error for an unknown policy.
EMSCRIPTEN_KEEPALIVE const char* rf_set_planner(const char* policy, int facesPerFrame, int everyN,
                                                double captureLod, double viewLod) {
  if (!state().demo) return returnText("no scene loaded");
  reflect::PlannerSettings settings = state().demo->plannerSettings();
  if (!reflect::parsePolicy(policy, &settings.policy)) {
    return returnText(std::string("unknown update policy '") + policy + "'");
  }
  settings.facesPerFrame = facesPerFrame;
  settings.everyN = everyN;
  settings.captureLod = static_cast<float>(captureLod);
  settings.viewLod = static_cast<float>(viewLod);
  state().demo->setPlannerSettings(settings);
  return returnText("");
}

// {"policy":..., "facesPerFrame":..., "everyN":..., "lod":..., "viewLod":...,
//  "maxStalenessFrames":...}
EMSCRIPTEN_KEEPALIVE const char* rf_planner_json() {
  if (!state().demo) return returnText("{}");
  const reflect::PlannerSettings& s = state().demo->plannerSettings();
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "{\"policy\":\"%s\",\"facesPerFrame\":%d,\"everyN\":%d,\"lod\":%g,"
                "\"viewLod\":%g,\"maxStalenessFrames\":%d}",
                reflect::policyName(s.policy), s.facesPerFrame, s.everyN, s.captureLod, s.viewLod,
                s.maxStalenessFrames());
  return returnText(buffer);
}

}  // extern "C"
