// Inside the frame: the teaching views a frame can be shown as instead of its picture (the
// view setting `inside`): the faces view (faces_view.h) and the face-use view (face_use_view.h).
// Each frame the demo tells it what the frame planned (afterFrame); when a view is on, draw() puts
// that view on the framebuffer over the finished frame. With the views off nothing here runs and
// nothing is allocated: the normal frame is untouched.
#pragma once

#include <functional>
#include <memory>

#include "app/face_use_view.h"
#include "app/faces_view.h"
#include "core/face_ages.h"
#include "core/settings_schema.h"
#include "gfx/image_blit.h"

namespace reflect {

class InsideViews {
 public:
  void set(InsideView view, FacesChannel channel) {
    view_ = view;
    channel_ = channel;
  }
  // Which probe the views show: the frame's Nth (faces_view.h shownProbe).
  void setProbe(int probe) { probe_ = probe; }
  bool on() const { return view_ != InsideView::Off; }
  // Every frame, views on or off: the faces' ages must be known when the view is turned on.
  void afterFrame(const FramePlan& plan) { ages_.advance(plan); }
  const FaceAges& ages() const { return ages_; }
  // Draws the view into `framebuffer` (width x height), which holds the finished frame.
  // `drawLookups` renders the same frame's lookup directions into a float framebuffer (the
  // face-use view reads them). Returns "" or why the view could not be made (then a message image
  // is drawn in its place, so the screen says it too).
  using LookupPass = std::function<void(unsigned framebuffer, int width, int height)>;
  std::string draw(const SceneRenderer& renderer, const Scene& scene, const FramePlan& plan,
                   const LookupPass& drawLookups, unsigned framebuffer, int width, int height);
  // Puts `image` on `framebuffer` (width x height) as the views are shown, centred on their
  // background (step through a frame). Returns "" or why it could not.
  std::string drawImage(const RgbaImage& image, unsigned framebuffer, int width, int height);
  // The GL objects are freed and the cubes' ages start over (their cubes are gone too).
  void release();

 private:
  InsideView view_ = InsideView::Off;
  FacesChannel channel_ = FacesChannel::Colour;
  int probe_ = 1;
  FaceAges ages_;
  std::unique_ptr<ImageBlit> blit_;  // made on the first draw
};

}  // namespace reflect
