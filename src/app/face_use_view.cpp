#include "app/face_use_view.h"

#include "app/faces_view.h"
#include "core/face_use.h"
#include "gfx/offscreen_target.h"

namespace reflect {
namespace {

std::string titleOf(const Scene& scene, const FramePlan& plan, const ProbePlan* shown) {
  if (shown == nullptr) return "FACE USE  NO PROBE THIS FRAME: THE REFLECTORS WERE TRACED";
  const int reflector = shown->reflector;
  const std::string mesh = static_cast<size_t>(reflector) < scene.objects.size()
                               ? scene.objects[static_cast<size_t>(reflector)].mesh
                               : std::string();
  std::string title =
      "FACE USE  MARKS: PROBE OF OBJECT " + std::to_string(reflector + 1) + " (" + mesh + ")";
  if (plan.probes.size() > 1) {
    title += ", " + std::to_string(shown - plan.probes.data() + 1) + " OF " +
             std::to_string(plan.probes.size()) + " PROBES";
  }
  return title;
}

}  // namespace

Result<RgbaImage> composeFaceUseView(
    const Scene& scene, const FramePlan& plan, const FaceAges& ages,
    const std::function<void(unsigned framebuffer, int width, int height)>& drawLookups,
    RgbaImage frame, int probe) {
  const int width = frame.width;
  const int height = frame.height;
  Result<OffscreenTarget> lookups = OffscreenTarget::create(width, height, true);
  if (!lookups) {
    return Result<RgbaImage>::failure("the face-use view needs a float render target: " +
                                      lookups.error());
  }
  drawLookups(lookups.value().framebuffer(), width, height);
  const ProbePlan* shown = shownProbe(plan, probe);
  return composeFaceUse(std::move(frame), lookups.value().readFloatsRgba(),
                        ages.marks(shown ? shown->reflector : -1), titleOf(scene, plan, shown));
}

}  // namespace reflect
