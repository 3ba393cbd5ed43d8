#include "app/faces_view.h"

#include <algorithm>
#include <cctype>

#include "core/bitmap_font.h"
#include "gfx/cube_readback.h"

namespace reflect {
namespace {

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string titleOf(const Scene& scene, const FramePlan& plan, const ProbePlan& probe,
                    FacesChannel channel) {
  const int reflector = probe.reflector;
  std::string mesh = reflector >= 0 && static_cast<size_t>(reflector) < scene.objects.size()
                         ? scene.objects[static_cast<size_t>(reflector)].mesh
                         : std::string();
  std::string which;
  if (plan.probes.size() > 1) {
    which = "  " + std::to_string(&probe - plan.probes.data() + 1) + " OF " +
            std::to_string(plan.probes.size()) + " PROBES";
  }
  return upper("probe of object " + std::to_string(reflector + 1) + " (" + mesh + ")" + which +
               "  channel " + facesChannelName(channel));
}

}  // namespace

const ProbePlan* shownProbe(const FramePlan& plan, int probe) {
  if (plan.probes.empty()) return nullptr;
  const size_t index = static_cast<size_t>(std::max(probe, 1) - 1);
  return &plan.probes[std::min(index, plan.probes.size() - 1)];
}

Result<RgbaImage> composeFacesView(const SceneRenderer& renderer, const Scene& scene,
                                   const FramePlan& plan, const FaceAges& ages,
                                   FacesChannel channel, int fitWidth, int fitHeight, int probe) {
  const ProbePlan* shown = shownProbe(plan, probe);
  if (shown == nullptr) {
    return Result<RgbaImage>::failure(
        "no cube map this frame: every reflector's rays were traced (search: planned found "
        "tracing cheaper, or search: exact). To see the faces, set search to plain, linear or "
        "hierarchical, or apply the course preset");
  }
  const int reflector = shown->reflector;
  const CubeCaptureTarget* target = renderer.probeTarget(reflector);
  if (target == nullptr) {
    return Result<RgbaImage>::failure("the probe of object " + std::to_string(reflector + 1) +
                                      " has not been captured yet");
  }
  Result<CubeFaces> faces = readCubeFaces(*target, channel);
  if (!faces) return Result<RgbaImage>::failure(faces.error());
  const int factor = crossShrinkFactor(target->faceSize(), fitWidth, fitHeight);
  std::string title = titleOf(scene, plan, *shown, channel);
  if (factor > 1) title += "  SHOWN AT 1/" + std::to_string(factor);
  return unfoldCross(shrinkFaces(faces.value(), factor), ages.marks(reflector), true, title);
}

RgbaImage messageImage(const std::string& text, int width, int height) {
  RgbaImage image = backgroundImage(width, height);
  drawWrappedText(image, 12, upper(text), {235, 235, 235, 255});
  return image;
}

}  // namespace reflect
