// Pick a pixel: one mirror or glass pixel of the frame just drawn, explained. The view ray, the
// surface it meets, the reflected (glass: refracted in and out) ray, the probe centre, the
// course's lookup (the ray's direction read from the probe centre), the point where the current
// search lands, and the exact hit (the ray traced on the CPU through the scene's meshes, core's
// BVH); each lookup's angular error against the direction from the probe centre to the exact hit,
// and the colour each returns against the exact colour. One rule in one place: `reflect explain`
// prints this and the page's rf_explain_pixel returns it.
//
// Where each number comes from:
//  - the search's landing point is the GPU's own: the main pass drawn again with environment.frag
//    writing its `measured` (SceneRenderer::kOutputSearchPoint) into a float target;
//  - the lookups' colours are the probe's colour cube read back (readCubeFaces) and filtered on
//    the CPU (sampleCubeLinear) along each lookup's direction. The hierarchical search's own
//    filter keeps to one surface and may read the second layer: its colour here is the first
//    layer's, bilinear;
//  - the exact colour is what the reference shades (core/reference_shading.h's phongShade with
//    the scene's light, or the skybox / clear colour for a ray that meets nothing or meets
//    something past the capture's far plane);
//  - the pixel colours: the frame's own pixel (the main pass drawn again, colours into a float
//    target) against the exact environment put through the material's mix.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/demo.h"
#include "app/pixel_lobe.h"
#include "core/pixel_trace.h"

namespace reflect {

struct PixelExplanation {
  int x = 0, y = 0, width = 0, height = 0;
  double seconds = 0.0;
  // Empty when the numbers below explain a mirror or glass pixel; otherwise, in words, why there
  // are none (outside the frame, nothing there, not a mirror or glass, traced, the skybox).
  std::string message;
  bool outside = false;  // the pixel is not in the frame

  int object = -1;  // what the view ray meets (-1: nothing)
  // A probe-lit figure's pixel (message set): the probe whose irradiance lights it (its owner's
  // index) and E / pi at the surface's normal, the ambient light the figure's colour takes
  // there (the CPU's projection of the probe's faces read back: core/irradiance.h).
  int irradianceProbe = -1;
  glm::vec3 irradianceDirection{0.0f};  // what it is read along: the normal, or parallax-corrected
  float irradianceRadius = 0.0f;        // the surroundings' radius the scene set (0: none)
  glm::vec3 irradianceParallax{0.0f};   // where none is set: what the point sees less the centre
  glm::vec3 irradiance{0.0f};
  std::string mesh;
  Material material = Material::Phong;
  std::string search;    // the lookup the renderer drew it with: plain, linear or hierarchical
  LobeExplanation lobe;  // a rough mirror's lobe (pixel_lobe.h), also where message is set
  glm::vec3 eye{0.0f};
  glm::vec3 surfacePoint{0.0f};
  glm::vec3 normal{0.0f};     // the interpolated vertex normal, unit
  glm::vec3 viewRay{0.0f};    // from the eye to the surface point, unit
  glm::vec3 reflected{0.0f};  // reflect(view ray, normal): the mirror's ray, glass's reflection
  GlassRoute glass;           // glass: the refracted ray entering and leaving
  TraceRay lookupRay;         // what the lookups stand for: the mirror's ray, glass's leaving one

  glm::vec3 probeCentre{0.0f};
  glm::vec3 courseDirection{0.0f};  // the course's lookup: lookupRay's direction, from the centre
  bool searchAtInfinity = false;    // the search returned a direction (a miss, or plain)
  glm::vec3 searchPoint{0.0f};      // where the search landed (world), unless at infinity
  glm::vec3 searchDirection{0.0f};  // from the probe centre towards it, unit

  int exactObject = -1;            // what lookupRay really meets first (-1: the sky)
  bool exactBeyondFar = false;     // it meets exactObject past the capture's far plane
  glm::vec3 exactHit{0.0f};        // where (when exactObject >= 0)
  glm::vec3 exactDirection{0.0f};  // from the probe centre to the hit (the ray's own on a miss)
  double courseErrorDeg = 0.0;
  double searchErrorDeg = 0.0;

  // What each lookup returns (0..1) against what the exact ray sees. exactColour is unknown
  // (exactShaded false) where the ray meets another mirror, glass or cube-textured object.
  glm::vec3 courseColour{0.0f};
  glm::vec3 searchColour{0.0f};
  bool exactShaded = false;
  glm::vec3 exactColour{0.0f};
  // The pixel: the frame's own, and the exact environment mixed as the material mixes it.
  glm::vec3 frameColour{0.0f};
  glm::vec3 exactPixelColour{0.0f};
};

// Explains pixel (x, y) ((0, 0) the top-left pixel) of the width x height frame the demo drew last
// (call after Demo::frame at that size). Draws the main pass twice more off screen; time does not
// advance. Returns the explanation, or an error where GL failed.
Result<PixelExplanation> explainPixel(Demo& demo, int x, int y, int width, int height);

// The explanation as the CLI prints it: every point (x, y, z), each angular error, each colour as
// 0-255 RGB and its difference from the exact colour; or the message.
std::vector<std::string> explanationLines(const PixelExplanation& e);

// The explanation as 3D lines for the page (Demo::showPickedRays), each in its colour: the view
// ray white; glass's refracted ray inside yellow; the reflected (glass: leaving) ray blue, from
// the surface to its exact hit; the course's lookup red and the search's green, both from the
// probe centre; a small cross at the probe centre (red), the search's point (green) and the exact
// hit (blue). A lookup or ray with no end point (at infinity, to the sky) is drawn 5 units long.
// None for a pixel with nothing to explain.
std::vector<RaySegment> pickSegments(const PixelExplanation& e);

// A colour 0..1 as 0..255 (clamped, rounded): how the lines and the page show it.
glm::ivec3 colourBytes(const glm::vec3& colour);

}  // namespace reflect
