// The explanation of a pixel in words and numbers, as `reflect explain` prints it.
#include <cstdio>

#include "app/pixel_explain.h"
#include "app/text_line.h"
#include "core/settings_schema.h"

namespace reflect {
namespace {

std::string point(const glm::vec3& p) {
  return formatLine("(%.4f, %.4f, %.4f)", p.x, p.y, p.z);
}

std::string rgb(const glm::vec3& colour) {
  const glm::ivec3 c = colourBytes(colour);
  return formatLine("rgb(%d, %d, %d)", c.r, c.g, c.b);
}

// A colour and its difference from `exact`, channel by channel in 0-255 levels.
std::string against(const glm::vec3& colour, const glm::vec3& exact, bool exactKnown) {
  if (!exactKnown) return rgb(colour);
  const glm::ivec3 d = colourBytes(colour) - colourBytes(exact);
  return rgb(colour) + formatLine(", off the exact by (%+d, %+d, %+d)", d.r, d.g, d.b);
}

void glassLines(const PixelExplanation& e, std::vector<std::string>& lines) {
  if (e.glass.totalAtEntry) {
    lines.push_back(
        "  refracted: none, total internal reflection at entry; the lookups follow "
        "the reflected ray");
    return;
  }
  lines.push_back("  refracted entering: direction " + point(e.glass.inside));
  if (e.glass.exited) {
    lines.push_back("  refracted leaving: from " + point(e.glass.exitPoint) + " along " +
                    point(e.glass.leaving) +
                    formatLine(" (%d internal reflections)", e.glass.internalReflections));
  } else {
    lines.push_back(
        "  refracted leaving: it does not leave (one surface, or no far side met); "
        "the lookups follow " +
        point(e.glass.leaving) + " from " + point(e.glass.exitPoint));
  }
}

}  // namespace

std::vector<std::string> explanationLines(const PixelExplanation& e) {
  std::vector<std::string> lines;
  lines.push_back(
      formatLine("pixel %d,%d of %dx%d at t=%.3f s", e.x, e.y, e.width, e.height, e.seconds));
  if (!e.message.empty()) {
    lines.push_back("  " + e.message);
    for (const std::string& line : lobeLines(e.lobe, false)) lines.push_back(line);
    return lines;
  }
  lines.push_back("  object " + std::to_string(e.object + 1) + " (" + e.mesh + "), " +
                  materialName(e.material) + ", search " + e.search);
  lines.push_back("  eye " + point(e.eye));
  lines.push_back("  view ray " + point(e.viewRay) + " meets the surface at " +
                  point(e.surfacePoint) + ", normal " + point(e.normal));
  lines.push_back("  reflected: direction " + point(e.reflected));
  for (const std::string& line : lobeLines(e.lobe, true)) lines.push_back(line);
  if (e.material == Material::Glass) glassLines(e, lines);
  lines.push_back("  probe centre " + point(e.probeCentre));
  lines.push_back("  course lookup: direction " + point(e.courseDirection) +
                  " from the probe centre" +
                  formatLine(", angular error %.3f deg", e.courseErrorDeg));
  if (e.searchAtInfinity) {
    lines.push_back("  search (" + e.search + "): at infinity, direction " +
                    point(e.searchDirection) +
                    formatLine(", angular error %.3f deg", e.searchErrorDeg));
  } else {
    lines.push_back("  search (" + e.search + "): lands at " + point(e.searchPoint) +
                    ", direction " + point(e.searchDirection) +
                    formatLine(", angular error %.3f deg", e.searchErrorDeg));
  }
  if (e.exactObject < 0) {
    lines.push_back("  exact: meets nothing (the sky), direction " + point(e.exactDirection));
  } else {
    lines.push_back("  exact hit: object " + std::to_string(e.exactObject + 1) + " at " +
                    point(e.exactHit) +
                    (e.exactBeyondFar ? " (past the capture's far plane: "
                                        "the probe sees the sky there)"
                                      : "") +
                    ", direction from the probe centre " + point(e.exactDirection));
  }
  lines.push_back("  colour, course lookup: " +
                  against(e.courseColour, e.exactColour, e.exactShaded));
  lines.push_back("  colour, search: " + against(e.searchColour, e.exactColour, e.exactShaded));
  lines.push_back(e.exactShaded ? "  colour, exact: " + rgb(e.exactColour)
                                : std::string("  colour, exact: not traced further (the ray "
                                              "meets another mirror, glass or cube-textured "
                                              "object)"));
  lines.push_back(
      "  pixel, this frame: " + against(e.frameColour, e.exactPixelColour, e.exactShaded) +
      (e.exactShaded ? "; exact pixel " + rgb(e.exactPixelColour) : std::string()));
  return lines;
}

}  // namespace reflect
