// Pick a pixel on the page: the explanation of one mirror or glass pixel of the frame on the
// canvas (app/pixel_explain.h, the same code `reflect explain` prints), and its rays drawn as 3D
// lines over the following frames until the pick is cleared.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <string>

#include "app/pixel_explain.h"
#include "platform/web/web_state.h"

namespace {

using nlohmann::json;
using namespace reflect::web;  // the bridge's helpers: web_state.h

json vec(const glm::vec3& v) {
  return {v.x, v.y, v.z};
}

json bytes(const glm::vec3& colour) {
  const glm::ivec3 c = reflect::colourBytes(colour);
  return {c.r, c.g, c.b};
}

// The numbers of an explanation (in the units explanationLines prints them: points in world
// units, angles in degrees, colours 0-255), and its lines.
json explanationJson(const reflect::PixelExplanation& e) {
  json out = {{"x", e.x},
              {"y", e.y},
              {"width", e.width},
              {"height", e.height},
              {"seconds", e.seconds},
              {"message", e.message},
              {"outside", e.outside},
              {"object", e.object}};
  out["lines"] = reflect::explanationLines(e);
  if (e.irradianceProbe >= 0) {  // a probe-lit figure: the light its normal takes
    out.update({{"irradianceProbe", e.irradianceProbe},
                {"normal", vec(e.normal)},
                {"irradianceDirection", vec(e.irradianceDirection)},
                {"irradianceRadius", e.irradianceRadius},
                {"irradianceParallax", vec(e.irradianceParallax)},
                {"irradiance", vec(e.irradiance)},
                {"irradianceBytes", bytes(e.irradiance)}});
  }
  if (!e.message.empty()) return out;
  out.update({{"mesh", e.mesh},
              {"material", reflect::materialName(e.material)},
              {"search", e.search},
              {"eye", vec(e.eye)},
              {"surfacePoint", vec(e.surfacePoint)},
              {"normal", vec(e.normal)},
              {"viewRay", vec(e.viewRay)},
              {"reflected", vec(e.reflected)},
              {"lookupOrigin", vec(e.lookupRay.origin)},
              {"lookupDirection", vec(e.lookupRay.direction)},
              {"probeCentre", vec(e.probeCentre)},
              {"courseDirection", vec(e.courseDirection)},
              {"courseErrorDeg", e.courseErrorDeg},
              {"searchAtInfinity", e.searchAtInfinity},
              {"searchPoint", vec(e.searchPoint)},
              {"searchDirection", vec(e.searchDirection)},
              {"searchErrorDeg", e.searchErrorDeg},
              {"exactObject", e.exactObject},
              {"exactBeyondFar", e.exactBeyondFar},
              {"exactHit", vec(e.exactHit)},
              {"exactDirection", vec(e.exactDirection)},
              {"courseColour", bytes(e.courseColour)},
              {"searchColour", bytes(e.searchColour)},
              {"exactShaded", e.exactShaded},
              {"exactColour", bytes(e.exactColour)},
              {"frameColour", bytes(e.frameColour)},
              {"exactPixelColour", bytes(e.exactPixelColour)}});
  if (e.material == reflect::Material::Glass) {
    out["glass"] = {{"totalAtEntry", e.glass.totalAtEntry},
                    {"inside", vec(e.glass.inside)},
                    {"exited", e.glass.exited},
                    {"exitPoint", vec(e.glass.exitPoint)},
                    {"leaving", vec(e.glass.leaving)}};
  }
  return out;
}

}  // namespace

extern "C" {

// Explains pixel {"x", "y"} of the frame last drawn on the canvas ((0, 0) its top-left pixel, in
// drawing-buffer pixels), and shows its rays over the frames that follow; {"clear": true} hides
// them. Returns the explanation (explanationJson: its numbers and "lines", the text `reflect
// explain` prints), {} after a clear, or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* rf_explain_pixel(const char* request) {
  auto r = parseRequest(request, "rf_explain_pixel");
  if (!r) return replyError(r.error());
  if (!state().demo) return replyError("rf_explain_pixel: no scene");
  std::string error;
  const reflect::JsonReader in(r.value(), "", &error);
  in.onlyKeys({"x", "y", "clear"});
  if (in["clear"].boolean(false)) {
    state().demo->showPickedRays({});
    return replyDone();
  }
  if (!in.has("x") || !in.has("y")) return replyError("rf_explain_pixel: x and y are needed");
  const int x = in["x"].integer(0, -1000000, 1000000);
  const int y = in["y"].integer(0, -1000000, 1000000);
  if (!error.empty()) return replyError("rf_explain_pixel: " + error);
  int width = 0, height = 0;
  emscripten_webgl_get_drawing_buffer_size(state().context, &width, &height);
  auto explained = reflect::explainPixel(*state().demo, x, y, width, height);
  if (!explained) return replyError("rf_explain_pixel: " + explained.error());
  state().demo->showPickedRays(reflect::pickSegments(explained.value()));
  return reply(explanationJson(explained.value()));
}

}  // extern "C"
