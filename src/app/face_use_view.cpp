#include "app/face_use_view.h"

#include "core/face_use.h"
#include "gfx/offscreen_target.h"

namespace reflect {
namespace {

std::string titleOf(const Scene& scene, const FramePlan& plan) {
  if (plan.probes.empty()) return "FACE USE  NO PROBE THIS FRAME: THE REFLECTORS WERE TRACED";
  const int reflector = plan.probes.front().reflector;
  const std::string mesh = static_cast<size_t>(reflector) < scene.objects.size()
                               ? scene.objects[static_cast<size_t>(reflector)].mesh
                               : std::string();
  std::string title =
      "FACE USE  MARKS: PROBE OF OBJECT " + std::to_string(reflector + 1) + " (" + mesh + ")";
  if (plan.probes.size() > 1) {
    title += " OF " + std::to_string(plan.probes.size()) + " PROBES";
  }
  return title;
}

}  // namespace

Result<RgbaImage> composeFaceUseView(
    const Scene& scene, const FramePlan& plan, const FaceAges& ages,
    const std::function<void(unsigned framebuffer, int width, int height)>& drawLookups,
    RgbaImage frame) {
  const int width = frame.width;
  const int height = frame.height;
  Result<OffscreenTarget> lookups = OffscreenTarget::create(width, height, true);
  if (!lookups) {
    return Result<RgbaImage>::failure("the face-use view needs a float render target: " +
                                      lookups.error());
  }
  drawLookups(lookups.value().framebuffer(), width, height);
  const int reflector = plan.probes.empty() ? -1 : plan.probes.front().reflector;
  return composeFaceUse(std::move(frame), lookups.value().readFloatsRgba(), ages.marks(reflector),
                        titleOf(scene, plan));
}

}  // namespace reflect
