// State shared by the page's entry points (web_main.cpp: context, frames, input; web_scenes.cpp:
// loading scenes, models and skyboxes). Only the web platform layer includes this.
#pragma once

#include <emscripten/html5.h>

#include <memory>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/image.h"

namespace reflect::web {

struct PendingScene {
  std::unique_ptr<Demo> demo;
  std::vector<RgbaImage> skyboxImages;  // 6 faces, or 1 cross, as they arrive
  std::vector<bool> skyboxReceived;
};

struct WebState {
  std::unique_ptr<Demo> demo;  // what the page shows
  PendingScene pending;        // a scene being loaded; replaces `demo` only once it is complete
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
  std::string returnText;  // storage for strings handed back to JavaScript
};

WebState& state();
// Keeps `text` alive until the next call and returns it for JavaScript.
const char* returnText(std::string text);

}  // namespace reflect::web
