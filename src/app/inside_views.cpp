#include "app/inside_views.h"

#include "gfx/offscreen_target.h"

namespace reflect {

std::string InsideViews::draw(const SceneRenderer& renderer, const Scene& scene,
                              const FramePlan& plan, const LookupPass& drawLookups,
                              unsigned framebuffer, int width, int height) {
  if (!blit_) {
    Result<ImageBlit> blit = ImageBlit::create();
    if (!blit) return blit.error();
    blit_ = std::make_unique<ImageBlit>(blit.take());
  }
  Result<RgbaImage> image =
      view_ == InsideView::FaceUse
          ? composeFaceUseView(scene, plan, ages_, drawLookups,
                               readFramebuffer(framebuffer, width, height), probe_)
          : composeFacesView(renderer, scene, plan, ages_, channel_, width, height, probe_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  if (!image) {
    blit_->draw(messageImage(image.error(), width, height), width, height, kCrossBackground);
    return image.error();
  }
  blit_->draw(image.value(), width, height, kCrossBackground);
  return {};
}

std::string InsideViews::drawImage(const RgbaImage& image, unsigned framebuffer, int width,
                                   int height) {
  if (!blit_) {
    Result<ImageBlit> blit = ImageBlit::create();
    if (!blit) return blit.error();
    blit_ = std::make_unique<ImageBlit>(blit.take());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  blit_->draw(image, width, height, kCrossBackground);
  return {};
}

void InsideViews::release() {
  blit_.reset();
  ages_.clear();
}

}  // namespace reflect
