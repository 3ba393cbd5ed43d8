// The live error view's half of a frame (show error): the same frame rendered again in the exact
// mode off screen by a second renderer, which draws from the same GPU meshes as the first, then
// compared with the current mode's on the GPU (ErrorView) and shown as a heat map. The exact
// frame's plan is the frame record's (Demo::record plans it beside the frame's own).
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "app/frame_record.h"
#include "app/frame_stats.h"
#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/error_view.h"
#include "gfx/exact_tracer.h"
#include "gfx/mesh_buffer.h"
#include "gfx/scene_renderer.h"

namespace reflect {

class ErrorViewPass {
 public:
  // Makes what is missing for `current` (the settings the frame is drawn with): the exact-mode
  // renderer, remade when those settings changed, drawing `meshes` with `tracer`; and the
  // comparison. Returns "" or a message.
  std::string setUp(const AccuracySettings& current, const MeshBuffers* meshes,
                    const CubeFaces* skybox, ExactTracer* tracer);
  // Its renderer's sky (when it has a renderer). Returns "" or a message.
  std::string setSkybox(const CubeFaces& faces);
  // Sized for a width x height frame and ready to draw it.
  bool prepare(int width, int height);
  // Where the current mode's frame goes while the view is on.
  unsigned currentFramebuffer() const { return view_->currentFramebuffer(); }
  // The record's exact frame (its exactPlan, drawn with its camera and main draws), the comparison
  // into `framebuffer`, and the numbers into `stats`. False when its capture failed (nothing the
  // exact plan asked for was drawn: the caller's planner must forget it).
  bool render(const Scene& scene, const FrameRecord& frame, unsigned framebuffer,
              FrameStats& stats);
  // Whether its exact renderer was made anew since the last call: the planner of its frames must
  // then forget what it captured.
  bool takeRemade() { return std::exchange(remade_, false); }
  // Frees its GL resources (or forgets them, after a lost context).
  void release();

 private:
  std::unique_ptr<SceneRenderer> renderer_;  // the exact pass
  std::unique_ptr<ErrorView> view_;
  ExactTracer* tracer_ = nullptr;  // not owned
  bool remade_ = false;
};

}  // namespace reflect
