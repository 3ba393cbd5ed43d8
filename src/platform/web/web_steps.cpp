// Step through a frame, the page's export: the panel's step control (and the . key) draws one step
// of the frame now into the canvas, through Demo::drawFrameStep, the same steps, labels and
// images as `reflect render --steps`.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>

#include "core/frame_steps.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using namespace reflect::web;  // the bridge's helpers: web_state.h

json stepJson(const reflect::FrameStep& step) {
  return {{"label", step.label},
          {"pass", reflect::stepPassName(step.pass)},
          {"face", step.face},
          {"objects", step.objects},
          {"triangles", step.triangles}};
}

}  // namespace

extern "C" {

// {"step": k} (0 first) draws step k of the frame now into the canvas: a capture step's image, or
// at the last step the frame. Returns {"step": k (clamped), "count": n, "steps": [{label, pass,
// face, objects, triangles}]}, or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_frame_step(const char* request) {
  auto r = parseRequest(request, "rf_frame_step");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("rf_frame_step: no scene yet");
  std::string error;
  const reflect::JsonReader in(r.value(), "", &error);
  const int step = static_cast<int>(in["step"].number(0, 0, 1e6));
  if (!error.empty()) return replyError("rf_frame_step: " + error);
  int width = 0, height = 0;  // the drawing buffer's size, as rf_frame draws at
  emscripten_webgl_get_drawing_buffer_size(state().context, &width, &height);
  auto steps = state().demo->drawFrameStep(step, 0, width, height);
  if (!steps) return replyError("rf_frame_step: " + steps.error());
  json list = json::array();
  for (const reflect::FrameStep& s : steps.value()) list.push_back(stepJson(s));
  const int count = static_cast<int>(list.size());
  return reply({{"step", std::min(step, count - 1)}, {"count", count}, {"steps", list}});
}

}  // extern "C"
