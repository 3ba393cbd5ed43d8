#include "core/cube_cross.h"

#include <algorithm>
#include <cstring>

#include "core/bitmap_font.h"
#include "core/cube_faces.h"

namespace reflect {
namespace {

using Rgba = std::array<uint8_t, 4>;
constexpr Rgba kCapturedFrame{70, 200, 100, 255};
constexpr Rgba kStaleFrame{235, 165, 40, 255};
constexpr Rgba kEmptyFrame{110, 110, 110, 255};
constexpr int kFrameWidth = 2;
constexpr int kLegendLine = kGlyphHeight + 4;
constexpr int kLegendHeight = 2 + kGlyphHeight + 6 + 6 * kLegendLine;  // title, then a line a face

std::string vectorText(const glm::vec3& v) {
  const auto component = [](float c) { return std::to_string(static_cast<int>(c)); };
  return "(" + component(v.x) + "," + component(v.y) + "," + component(v.z) + ")";
}

const Rgba& frameColour(const FaceMark& mark) {
  if (!mark.everCaptured) return kEmptyFrame;
  return mark.captured ? kCapturedFrame : kStaleFrame;
}

// The face's pixels into its square; a stale face at half brightness (alpha kept).
void copyFace(RgbaImage& view, const RgbaImage& face, int x, int y, bool dim) {
  for (int row = 0; row < face.height; ++row) {
    uint8_t* out = &view.pixels[(static_cast<size_t>(y + row) * static_cast<size_t>(view.width) +
                                 static_cast<size_t>(x)) *
                                4];
    std::memcpy(out, face.at(0, row), static_cast<size_t>(face.width) * 4);
    if (!dim) continue;
    for (int column = 0; column < face.width; ++column) {
      for (int c = 0; c < 3; ++c)
        out[column * 4 + c] = static_cast<uint8_t>(out[column * 4 + c] / 2);
    }
  }
}

void drawLegend(RgbaImage& view, const CrossGeometry& g, const std::array<FaceMark, 6>& marks,
                const std::string& title) {
  // The strip below the cross: always room for it, whatever the face size.
  const int left = g.margin;
  int y = 3 * (g.faceSize + 2 * g.margin) + 2;
  drawText(view, left, y, title, kLabelText);
  y += kGlyphHeight + 6;
  for (int face = 0; face < 6; ++face) {
    fillRect(view, left, y, kGlyphHeight, kGlyphHeight,
             frameColour(marks[static_cast<size_t>(face)]));
    drawText(view, left + kGlyphAdvance * 2, y,
             faceLabel(face) + "  " + faceStatus(marks[static_cast<size_t>(face)]), kLabelText);
    y += kLegendLine;
  }
}

}  // namespace

RgbaImage backgroundImage(int width, int height) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  fillRect(image, 0, 0, width, height, kCrossBackground);
  return image;
}

const char* facesChannelName(FacesChannel channel) {
  static const char* const kNames[] = {"colour", "distance", "layer2",
                                       "irradiance"};  // FacesChannel's order
  return kNames[static_cast<size_t>(channel)];
}

CrossGeometry crossGeometry(int faceSize) {
  CrossGeometry g;
  g.faceSize = faceSize;
  g.margin = kGlyphHeight + 2 * kFrameWidth + 2;  // a name line above the square, frames around
  const int pitch = faceSize + 2 * g.margin;
  g.width = 4 * pitch;
  g.height = 3 * pitch + kLegendHeight;
  for (size_t face = 0; face < 6; ++face) {
    g.squareOrigin[face] = {kCrossCells[face][0] * pitch + g.margin,
                            kCrossCells[face][1] * pitch + g.margin};
  }
  return g;
}

int crossShrinkFactor(int faceSize, int width, int height) {
  if (width <= 0 || height <= 0) return 1;
  int factor = 1;
  while (faceSize / (factor + 1) >= 8) {
    const CrossGeometry g = crossGeometry(faceSize / factor);
    if (g.width <= width && g.height <= height) break;
    ++factor;
  }
  return factor;
}

CubeFaces shrinkFaces(const CubeFaces& faces, int factor) {
  if (factor <= 1) return faces;
  CubeFaces small;
  for (size_t f = 0; f < 6; ++f) {
    const int size = faces[f].width / factor;
    RgbaImage& out = small[f];
    out.width = out.height = size;
    out.pixels.resize(static_cast<size_t>(size) * static_cast<size_t>(size) * 4);
    const int area = factor * factor;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int dy = 0; dy < factor; ++dy) {
            for (int dx = 0; dx < factor; ++dx)
              sum += faces[f].at(x * factor + dx, y * factor + dy)[c];
          }
          out.pixels[(static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)) *
                         4 +
                     static_cast<size_t>(c)] = static_cast<uint8_t>((sum + area / 2) / area);
        }
      }
    }
  }
  return small;
}

std::string faceLabel(int face) {
  const CubeFace& f = kCubeFaces[static_cast<size_t>(face)];
  return std::string(f.name) + "  LOOK " + vectorText(f.direction) + "  UP " + vectorText(f.up);
}

std::string faceStatus(const FaceMark& mark) {
  if (!mark.everCaptured) return "EMPTY";
  if (mark.captured) return "CAPTURED";
  return "STALE " + std::to_string(mark.ageFrames) + (mark.ageFrames == 1 ? " FRAME" : " FRAMES");
}

int labelledCrossWidth(const CrossGeometry& g, const std::array<FaceMark, 6>& marks,
                       const std::string& title) {
  int legend = textWidth(title, 1);
  for (int face = 0; face < 6; ++face) {
    const std::string line = faceLabel(face) + "  " + faceStatus(marks[static_cast<size_t>(face)]);
    legend = std::max(legend, 2 * kGlyphAdvance + textWidth(line, 1));
  }
  return std::max(g.width, legend + 2 * g.margin);
}

RgbaImage unfoldCross(const CubeFaces& faces, const std::array<FaceMark, 6>& marks, bool labels,
                      const std::string& title) {
  const CrossGeometry g = crossGeometry(faces[0].width);
  RgbaImage view;
  view.width = labels ? labelledCrossWidth(g, marks, title) : g.width;
  view.height = g.height;
  view.pixels.resize(static_cast<size_t>(view.width) * static_cast<size_t>(g.height) * 4);
  fillRect(view, 0, 0, view.width, g.height, kCrossBackground);
  for (size_t face = 0; face < 6; ++face) {
    const int x = g.squareOrigin[face][0];
    const int y = g.squareOrigin[face][1];
    // The mark: a frame just outside the square.
    fillRect(view, x - kFrameWidth, y - kFrameWidth, g.faceSize + 2 * kFrameWidth,
             g.faceSize + 2 * kFrameWidth, frameColour(marks[face]));
    const bool stale = marks[face].everCaptured && !marks[face].captured;
    copyFace(view, faces[face], x, y, stale);
    if (labels)
      drawText(view, x, y - kFrameWidth - 1 - kGlyphHeight, kCubeFaces[face].name, kLabelText);
  }
  if (labels) drawLegend(view, g, marks, title);
  return view;
}

}  // namespace reflect
