#include "app/frame_step_view.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/bitmap_font.h"
#include "core/cube_cross.h"
#include "gfx/cube_readback.h"

namespace reflect {
namespace {

constexpr int kMargin = 12;

// Draws `text` (upper case, the font's) word-wrapped from the top-left margin; returns the first
// row below it.
int drawTitle(RgbaImage& image, const std::string& text) {
  std::string shown = text;
  for (char& c : shown) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return drawWrappedText(image, kMargin, shown, {235, 235, 235, 255}) + kMargin;
}

// Copies `content` into `image` centred in the rows from `top` down (cut where it is larger).
void paste(RgbaImage& image, const RgbaImage& content, int top) {
  const int left = std::max(0, (image.width - content.width) / 2);
  const int y0 = top + std::max(0, (image.height - top - content.height) / 2);
  const int columns = std::min(content.width, image.width - left);
  for (int y = 0; y < content.height && y0 + y < image.height; ++y) {
    std::memcpy(&image.pixels[(static_cast<size_t>(y0 + y) * static_cast<size_t>(image.width) +
                               static_cast<size_t>(left)) *
                              4],
                content.at(0, y), static_cast<size_t>(std::max(columns, 0)) * 4);
  }
}

// The smallest whole factor that fits `size` texels into `room` pixels.
int shrinkToFit(int size, int room) {
  return room <= 0 ? 1 : std::max(1, (size + room - 1) / room);
}

// What the step drew, as the probe holds it now, shrunk to fit width x room.
Result<RgbaImage> stepContent(const CubeCaptureTarget& target, const FrameStep& step, int width,
                              int room) {
  if (step.pass == StepPass::DepthPyramid) {
    Result<CubeFaces> faces = readCubeFaces(target, FacesChannel::Distance);
    if (!faces) return Result<RgbaImage>::failure(faces.error());
    std::array<FaceMark, 6> marks{};
    for (FaceMark& mark : marks) mark.captured = true;  // no dimming: the step is about depths
    const int factor = crossShrinkFactor(target.faceSize(), width, room);
    return unfoldCross(shrinkFaces(faces.value(), factor), marks, true, "");
  }
  CubeFaces one;
  if (step.pass == StepPass::Backs) {
    Result<RgbaImage> backs = readBacksFace(target, step.face);
    if (!backs) return backs;
    one[0] = backs.take();
  } else {
    Result<CubeFaces> faces =
        readCubeFaces(target, step.pass == StepPass::SecondLayer ? FacesChannel::SecondLayer
                                                                 : FacesChannel::Colour);
    if (!faces) return Result<RgbaImage>::failure(faces.error());
    one[0] = std::move(faces.value()[static_cast<size_t>(step.face)]);
  }
  const int factor = std::max(shrinkToFit(one[0].width, width), shrinkToFit(one[0].height, room));
  return shrinkFaces(one, factor)[0];
}

}  // namespace

std::string stepTitle(const FrameStep& step, int index, int count) {
  return "step " + std::to_string(index + 1) + " of " + std::to_string(count) + ": " + step.label;
}

Result<RgbaImage> captureStepImage(const SceneRenderer& renderer, const FrameStep& step, int index,
                                   int count, int width, int height) {
  if (step.pass == StepPass::Main) {
    return Result<RgbaImage>::failure("the main pass's step is the frame itself");
  }
  const CubeCaptureTarget* target = renderer.probeTarget(step.reflector);
  if (target == nullptr) {
    return Result<RgbaImage>::failure("the probe of object " + std::to_string(step.reflector + 1) +
                                      " has no target");
  }
  RgbaImage image = backgroundImage(width, height);
  const int top = drawTitle(image, stepTitle(step, index, count));
  Result<RgbaImage> content = stepContent(*target, step, width - 2 * kMargin, height - top);
  if (!content) return content;
  paste(image, content.value(), top);
  return image;
}

}  // namespace reflect
