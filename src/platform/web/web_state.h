// State and conventions shared by the page's entry points (web_main.cpp: context, frames, clock,
// camera; web_scenes.cpp: scenes, models, skyboxes, added objects; web_settings.cpp: the settings
// schema, planner, accuracy and materials). Only the web platform layer includes this.
//
// What crosses the bridge is JSON, built and parsed with nlohmann-json: every export takes one
// JSON object (its request; plus a pointer and length where a file's bytes go) and returns JSON.
// An action returns {} when it worked, {"error": "..."} when it did not (nothing changed), and may
// add {"notice": "..."}. web/wasm_bridge.js is the only JavaScript that calls these.
#pragma once

#include <emscripten/html5.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/image.h"
#include "core/json_reader.h"
#include "core/obj_stream.h"
#include "core/result.h"
#include "core/settings_schema.h"

namespace reflect::web {

struct PendingScene {
  std::unique_ptr<Demo> demo;
  std::vector<RgbaImage> skyboxImages;  // 6 faces, or 1 cross, as they arrive
  std::vector<bool> skyboxReceived;
};

// An OBJ file being streamed in (rf_mesh_stream_*): the page feeds each piece of the download as
// it arrives, so the text is never whole in wasm memory.
struct MeshStream {
  std::string name;      // the mesh it becomes
  bool pending = false;  // of the scene being loaded (else of the current one)
  ObjStreamParser parser;
};

struct WebState {
  std::unique_ptr<Demo> demo;  // what the page shows
  PendingScene pending;        // a scene being loaded; replaces `demo` only once it is complete
  std::map<int, MeshStream> streams;
  int nextStream = 1;
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
  std::string reply;  // storage for the JSON handed back to JavaScript
  ViewSettings view;  // show error, auto and its budget (showError is also the demo's)
};

WebState& state();

// The request of export `function`: a JSON object (an empty or null text reads as {}).
Result<nlohmann::json> parseRequest(const char* text, const char* function);
// Keeps `value` (as JSON text) until the next call and returns it for JavaScript. Numbers that are
// floats in C++ are written with the fewest digits that give the same float (0.78, not
// 0.7799999713897705); text that is not valid UTF-8 is repaired, never a failure.
const char* reply(const nlohmann::json& value);
// A float as the fewest digits that read back as it: 0.78f as "0.78".
std::string shortestText(float value);
// {"error": message}, or {} for an empty message.
const char* replyError(const std::string& message);
// {} or {"notice": notice}.
const char* replyDone(const std::string& notice = {});

}  // namespace reflect::web
