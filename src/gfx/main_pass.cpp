#include "gfx/main_pass.h"

#include "core/frustum.h"

namespace reflect {

PassCounts drawMainPass(const PassDrawer& drawer, const SkyboxPass* sky, const Scene& scene,
                        const FramePlan& plan, const ViewParams& camera,
                        const std::vector<DrawItem>& draws, const MainTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(0, 0, target.width, target.height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // the ground quad is seen from both sides; solids: DrawPass::cullReach
  glClearColor(scene.clearColour.r, scene.clearColour.g, scene.clearColour.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const DrawPass pass{scene,
                      plan,
                      camera.projection * camera.view,
                      camera.eye,
                      camera.eye,
                      {},  // layer 0: the main pass
                      target.outputDirections,
                      nearPlaneReach(camera.projection)};
  PassCounts counts = drawer.draw(pass, draws);
  if (sky) sky->draw(camera.projection, camera.view, pass.capture);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  checkGlError("main pass");
  return counts;
}

}  // namespace reflect
