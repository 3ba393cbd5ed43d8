#include "core/face_use.h"

#include <cstring>

#include "core/bitmap_font.h"
#include "core/cube_faces.h"
#include "core/cube_sampling.h"

namespace reflect {
namespace {

using Rgba = std::array<uint8_t, 4>;
constexpr Rgba kPanel{24, 24, 28, 255};
constexpr int kLine = kGlyphHeight + 4;
constexpr int kMargin = 6;

void paintPixel(uint8_t* pixel, const Rgba& rgba) {
  std::memcpy(pixel, rgba.data(), 4);
}

// A third of the frame's brightness: the scene stays recognisable behind the painted reflectors.
void dimPixel(uint8_t* pixel) {
  for (int c = 0; c < 3; ++c) pixel[c] = static_cast<uint8_t>(pixel[c] / 3);
}

std::string tracedLine(size_t pixels) {
  return "TRACED  " + std::to_string(pixels) + " PX  NO FACE READ";
}

void drawLegend(RgbaImage& view, const FaceUseCounts& counts,
                const std::array<FaceMark, 6>& marks) {
  std::vector<std::string> lines;
  for (int face = 0; face < 6; ++face) {
    lines.push_back(faceUseLine(face, counts.faces[static_cast<size_t>(face)],
                                marks[static_cast<size_t>(face)]));
  }
  lines.push_back(tracedLine(counts.traced));
  int widest = 0;
  for (const std::string& line : lines) widest = std::max(widest, textWidth(line, 1));
  const int height = static_cast<int>(lines.size()) * kLine + 2 * kMargin;
  const int top = view.height - height;
  fillRect(view, 0, top, widest + 2 * kGlyphAdvance + 2 * kMargin, height, kPanel);
  int y = top + kMargin;
  for (size_t i = 0; i < lines.size(); ++i) {
    fillRect(view, kMargin, y, kGlyphHeight, kGlyphHeight,
             i < 6 ? kFaceUseColours[i] : kFaceUseTraced);
    drawText(view, kMargin + 2 * kGlyphAdvance, y, lines[i], kLabelText);
    y += kLine;
  }
}

}  // namespace

int faceOfLookup(const glm::vec4& lookup) {
  if (lookup.a == kLookupMarkTraced) return -1;
  if (lookup.a != kLookupMarkProbe) return -2;
  return cubeFaceCoord(glm::vec3(lookup)).face;
}

FaceUseCounts paintFaceUse(RgbaImage& frame, const std::vector<glm::vec4>& lookups) {
  FaceUseCounts counts;
  const size_t pixels = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
  for (size_t p = 0; p < pixels && p < lookups.size(); ++p) {
    uint8_t* pixel = &frame.pixels[p * 4];
    const int face = faceOfLookup(lookups[p]);
    if (face >= 0) {
      paintPixel(pixel, kFaceUseColours[static_cast<size_t>(face)]);
      ++counts.faces[static_cast<size_t>(face)];
    } else if (face == -1) {
      paintPixel(pixel, kFaceUseTraced);
      ++counts.traced;
    } else {
      dimPixel(pixel);
    }
  }
  return counts;
}

std::string faceUseLine(int face, size_t pixels, const FaceMark& mark) {
  return std::string(kCubeFaces[static_cast<size_t>(face)].name) + "  " + std::to_string(pixels) +
         " PX  " + faceStatus(mark);
}

RgbaImage composeFaceUse(RgbaImage frame, const std::vector<glm::vec4>& lookups,
                         const std::array<FaceMark, 6>& marks, const std::string& title) {
  const FaceUseCounts counts = paintFaceUse(frame, lookups);
  fillRect(frame, 0, 0, textWidth(title, 1) + 2 * kMargin, kGlyphHeight + 2 * kMargin, kPanel);
  drawText(frame, kMargin, kMargin, title, kLabelText);
  drawLegend(frame, counts, marks);
  return frame;
}

}  // namespace reflect
