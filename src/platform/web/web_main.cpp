// The browser entry point: a WebGL2 context on #canvas, and the exports for frames, the clock and
// the camera. The page (web/wasm_bridge.js) calls them; every rule lives here or below (the
// camera's moves are LookCamera's). Scene loading is in web_scenes.cpp, the settings in
// web_settings.cpp.
#include <emscripten/emscripten.h>
#include <emscripten/heap.h>
#include <emscripten/html5.h>
#include <emscripten/stack.h>
#include <malloc.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "gfx/gl.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using namespace reflect::web;  // the bridge's helpers: web_state.h

constexpr const char* kCanvas = "#canvas";

// The stack's high-water mark, for choosing its size (CMakeLists.txt): rf_create fills the free
// stack with a pattern, and each frame's stats say how much of it was ever overwritten.
constexpr unsigned char kStackPaint = 0xA5;

void paintFreeStack() {
  const uintptr_t end = emscripten_stack_get_end();  // the stack grows down to here
  constexpr uintptr_t kMargin = 4096;  // this call's frame and memset's stay unpainted
  const uintptr_t below = emscripten_stack_get_current() - kMargin;
  if (below > end) std::memset(reinterpret_cast<void*>(end), kStackPaint, below - end);
}

size_t stackHighWater() {
  const uintptr_t end = emscripten_stack_get_end(), base = emscripten_stack_get_base();
  uintptr_t p = end;
  while (p < base && *reinterpret_cast<const unsigned char*>(p) == kStackPaint) ++p;
  return base - p;
}

// The WebGL2 extensions the renderer uses where the browser has them: float and half-float colour
// targets (the float offscreen targets, RGBA16F capture faces), linear filtering and blending of
// float textures, and GPU timer queries (gfx/gpu_timer).
constexpr const char* kExtensions[] = {
    "EXT_color_buffer_float", "EXT_color_buffer_half_float",     "OES_texture_float_linear",
    "EXT_float_blend",        "EXT_disjoint_timer_query_webgl2",
};

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
  // Emscripten would enable every extension the browser offers, one getExtension each (43 ms of
  // the main thread in a sampling profile of a SwiftShader load, though the load timed without
  // the profiler was the same within its noise). The renderer asks for what it uses alone.
  attributes.enableExtensionsByDefault = EM_FALSE;
  state().context = emscripten_webgl_create_context(kCanvas, &attributes);
  if (state().context <= 0) return "WebGL2 is not available in this browser";
  emscripten_webgl_make_context_current(state().context);
  for (const char* extension : kExtensions)
    emscripten_webgl_enable_extension(state().context, extension);
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

json cameraJson(const reflect::LookCamera& c) {
  return {{"eye", {c.eye().x, c.eye().y, c.eye().z}}, {"yaw", c.yawDeg()}, {"pitch", c.pitchDeg()}};
}

}  // namespace

extern "C" {

// Creates the WebGL2 context. {} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_create() {
  paintFreeStack();
  std::string error = makeContextCurrent();
  if (!error.empty()) return replyError(error);
  emscripten_set_webglcontextlost_callback(kCanvas, nullptr, EM_FALSE, onContextLost);
  emscripten_set_webglcontextrestored_callback(kCanvas, nullptr, EM_FALSE, onContextRestored);
  return replyError("");
}

// One complete frame into the canvas's drawing buffer: {"dt": seconds, "waitForGpu": bool (time
// it end to end, a read back after each pass), "waitAtEnd": bool (one read back after the frame,
// as the peer pages wait: what a frame costs, with no wait between its passes)}. Returns the
// frame's stats (see FrameStats).
EMSCRIPTEN_KEEPALIVE const char* rf_frame(const char* request) {
  auto r = parseRequest(request, "rf_frame");
  if (!r) return replyError(r.error());
  if (!state().demo) return reply(json::object());
  std::string error;
  const reflect::JsonReader in(r.value(), "", &error);
  const double dt = in["dt"].number(0, 0, 1e6);
  const bool wait = in["waitForGpu"].boolean(false);
  const bool waitAtEnd = in["waitAtEnd"].boolean(false);
  if (!error.empty()) return replyError("rf_frame: " + error);
  // The drawing buffer, not the canvas element: past the GPU's limits (a wide canvas at a high
  // devicePixelRatio) the browser gives a smaller buffer, and drawing at the element's size
  // would crop the picture.
  int width = 0, height = 0;
  emscripten_webgl_get_drawing_buffer_size(state().context, &width, &height);
  json stats = state().demo->frame(dt, 0, width, height, wait).toJson();
  if (waitAtEnd) reflect::waitForGpu();
  // The wasm memory now (it grows and never shrinks: what a load's peak left behind).
  stats["heapBytes"] = emscripten_get_heap_size();
  // This frame (or one before) drew a capture whose chunks or levels are not built: the page
  // starts its worker (session.js).
  stats["levelsWanted"] = state().demo->levelsWanted();
  return reply(stats);
}

// What the heap is made of, on request (demo.stats() asks; a frame does not: mallinfo walks
// malloc's chunks and the high-water mark scans the stack): {heapBytes, mallocInUseBytes (in use),
// mallocArenaBytes (taken from the heap in all), stackBytes, stackHighWaterBytes (the most
// stack ever used)}. Beside the first two, the rest is free space a load's peak left.
EMSCRIPTEN_KEEPALIVE const char* rf_memory_json() {
  const struct mallinfo m = mallinfo();
  return reply({{"heapBytes", emscripten_get_heap_size()},
                {"mallocInUseBytes", m.uordblks},
                {"mallocArenaBytes", m.arena},
                {"stackBytes", emscripten_stack_get_base() - emscripten_stack_get_end()},
                {"stackHighWaterBytes", stackHighWater()}});
}

// The animation clock: {"seconds": t} sets it; returns {"seconds": now}.
EMSCRIPTEN_KEEPALIVE const char* rf_clock(const char* request) {
  auto r = parseRequest(request, "rf_clock");
  if (!r) return replyError(r.error());
  if (!state().demo) return reply({{"seconds", 0}});
  std::string error;
  const reflect::JsonReader in(r.value(), "", &error);
  if (in.has("seconds")) {
    const double seconds = in["seconds"].number(0, -1e9, 1e9);
    if (!error.empty()) return replyError(error);
    state().demo->clock().set(seconds);
  }
  return reply({{"seconds", state().demo->clock().seconds()}});
}

// The main camera, changed by the request's keys in this order (each optional):
//   "reset": true                          the scene's own camera
//   "eye": [x, y, z], "yaw": deg, "pitch": deg   placed (pitch clamped to +-89)
//   "drag": {"dx", "dy", "height"}         a pointer drag over a canvas `height` pixels tall
//   "forward", "right", "up": steps        LookCamera::move, strafe, rise (0.1 a step)
// Returns the camera: {"eye": [x, y, z], "yaw": deg, "pitch": deg}. A bad request changes nothing.
EMSCRIPTEN_KEEPALIVE const char* rf_camera(const char* request) {
  auto r = parseRequest(request, "rf_camera");
  if (!r) return replyError(r.error());
  if (!state().demo) return reply(json::object());
  reflect::LookCamera camera = state().demo->camera();
  std::string error;
  const reflect::JsonReader in(r.value(), "", &error);
  in.onlyKeys({"reset", "eye", "yaw", "pitch", "drag", "forward", "right", "up"});
  if (in["reset"].boolean(false)) camera.reset();
  if (in.has("eye")) camera.setEye(in["eye"].vec3(camera.eye()));
  if (in.has("yaw") || in.has("pitch")) {
    camera.setAngles(static_cast<float>(in["yaw"].number(camera.yawDeg(), -1e6, 1e6)),
                     static_cast<float>(in["pitch"].number(camera.pitchDeg(), -1e6, 1e6)));
  }
  if (in.has("drag")) {
    const reflect::JsonReader drag = in["drag"];
    drag.onlyKeys({"dx", "dy", "height"});
    if (!drag.has("height")) drag["height"].fail("missing (the canvas height in pixels)");
    camera.drag(static_cast<float>(drag["dx"].number(0, -1e6, 1e6)),
                static_cast<float>(drag["dy"].number(0, -1e6, 1e6)),
                static_cast<float>(drag["height"].number(1, 1e-3, 1e6)));
  }
  camera.move(static_cast<float>(in["forward"].number(0, -1e6, 1e6)));
  camera.strafe(static_cast<float>(in["right"].number(0, -1e6, 1e6)));
  camera.rise(static_cast<float>(in["up"].number(0, -1e6, 1e6)));
  if (!error.empty()) return replyError("rf_camera: " + error);
  state().demo->camera() = camera;
  return reply(cameraJson(camera));
}

}  // extern "C"
