#include "gfx/program_key.h"

#include <cctype>

#include "core/bvh.h"
#include "core/ggx.h"
#include "core/trace_limits.h"

namespace reflect {
namespace {

std::string define(const std::string& name, int value) {
  return "#define " + name + " " + std::to_string(value) + "\n";
}

// "SEARCH_HIERARCHICAL"
std::string searchMacro(Search search) {
  std::string name = "SEARCH_";
  for (const char* c = searchName(search); *c; ++c) {
    name += *c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
  }
  return name;
}

}  // namespace

const char* ProgramKey::fragmentFile() const {
  switch (look) {
    case Look::Phong:
      return "phong.frag";
    case Look::Environment:
      return "environment.frag";
    case Look::CubeTextured:
      return "cube_textured.frag";
  }
  return "phong.frag";
}

std::string ProgramKey::defines() const {
  std::string out = define("CAPTURE_OUTPUT", capture ? 1 : 0);
  if (look == Look::Phong) out += define("AMBIENT_PROBE", probeLight ? 1 : 0);
  if (look != Look::Environment) return out;
  for (Search s : kSearches) out += define(searchMacro(s), static_cast<int>(s));
  out += "#define SEARCH " + searchMacro(search) + "\n";
  out += define("DISTANCE_ITERATIONS", 2);
  out += define("REFRACTS", refracts ? 1 : 0);
  out += define("GLASS_EXIT", glassExit ? 1 : 0);
  out += define("EXACT_GENERAL", traceGeneral ? 1 : 0);
  out += define("ROUGH", rough ? 1 : 0);
  out += define("ROUGH_TAPS", roughTaps ? 1 : 0);
  // A float the shader compares with: written with its decimals (0.5 -> "0.500000").
  out += "#define WIDE_LOBE_ALPHA " + std::to_string(kWideLobeAlpha) + "\n";

  if (search == Search::Exact) {
    // The atlas's layout and the rays' limits, from the C++ that writes and checks them.
    out += define("EXACT_WIDTH_SHIFT", kBvhTextureWidthShift);
    out += define("EXACT_INSTANCE_TEXELS", kInstanceTexels);
    out += define("EXACT_TRIANGLE_TEXELS", kTriangleTexels);
    out += define("EXACT_TESTED_TRIANGLES", kTestedTriangles);
    // The deepest walk of both levels the scene's trees allow.
    out += define("EXACT_STACK", traceStack > 0 ? traceStack : 2 * kBvhMaxDepth + 2);
    out += define("EXACT_MAX_BOUNCES", kMaxBounces);
    out += define("EXACT_MAX_INTERNAL", kMaxInternalReflections);
  }
  return out;
}

std::string ProgramKey::describe() const {
  std::string s = std::string(fragmentFile()) + " (" + (capture ? "capture" : "main");
  if (probeLight) s += ", probe-lit";
  if (look == Look::Environment) {
    s += std::string(", ") + searchName(search);
    if (refracts) s += ", refracts";
    if (glassExit) s += ", glass exit";
    if (traceGeneral) s += ", general";
    if (rough) s += roughTaps ? ", rough taps" : ", rough";
  }
  return s + ")";
}

}  // namespace reflect
