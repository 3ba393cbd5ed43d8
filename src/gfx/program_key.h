// Which program draws an object in a pass, as a value: the shader variant is a key built from the
// settings and the object, looked up in the renderer's cache (scene_renderer.h), and turned into
// the shader's #defines in one place (defines()). Each variant compiles only what it uses: a
// software rasteriser (SwiftShader, llvmpipe) runs every branch a shader has, taken or not, for
// every pixel, so a branch switched by a uniform costs as much as one that runs.
#pragma once

#include <compare>
#include <string>

#include "core/accuracy_settings.h"

namespace reflect {

enum class Look : int {
  Phong,         // phong.frag
  Environment,   // environment.frag: mirror and glass
  CubeTextured,  // cube_textured.frag: Ex12-1's cube
};

struct ProgramKey {
  Look look = Look::Phong;
  // A capture pass: the fragment also writes its distance and depth codes and may peel
  // (capture_output.glsl); the main pass writes the colour alone.
  bool capture = false;
  // Environment: how the ray finds what it meets (never Search::Planned: the planner resolves
  // that per reflector before a program is picked).
  Search search = Search::Plain;
  // Environment: glass, which refracts (a mirror's program has no refraction at all).
  bool refracts = false;
  // Environment, a glass mesh that is not a sphere: it leaves through its interior map.
  bool glassExit = false;
  // Search::Exact: the general tracer (rays that meet other mirrors, glass or cube-textured
  // objects, glass crossed inside); without it, a ray meets Phong surfaces or the sky only, and
  // the program holds one trace and one Phong.
  bool traceGeneral = false;
  // Search::Exact: the entries of the walk's stack (core/bvh.h traceStackFor); 0 the largest.
  int traceStack = 0;
  // Environment, a rough mirror (SceneObject::rough()): its reflection is averaged over a GGX
  // lobe, read from the probe's prefiltered levels or, traced, by lobe rays (ROUGH 1). Mirrors of
  // roughness 0 keep the program they had, so their pixels cannot change.
  bool rough = false;
  // A rough reader of a live probe with lobe taps (AccuracySettings::lobeTaps > 0): it samples
  // its lobe from the capture's box chain (ROUGH_TAPS 1), not from prefiltered levels.
  bool roughTaps = false;
  // Phong in the main pass, a probe-lit object (SceneObject::probeLit): its ambient is its probe's
  // irradiance (AMBIENT_PROBE 1). Captures draw it with the constant ambient (one bounce).
  bool probeLight = false;

  auto operator<=>(const ProgramKey&) const = default;

  const char* fragmentFile() const;
  // Whether the fragment shader may run at mediump when the settings ask for it: not the exact
  // tracer, which would lose the triangles (its precision is set here, not in its GLSL).
  bool allowsMediump() const { return search != Search::Exact; }
  // "#define CAPTURE_OUTPUT 1\n#define SEARCH_PLAIN 0\n..." for the fragment shader, the search's
  // value named as in C++ (SEARCH == SEARCH_EXACT), never a bare number.
  std::string defines() const;
  // "environment.frag (main, exact, general)" for messages.
  std::string describe() const;
};

}  // namespace reflect
