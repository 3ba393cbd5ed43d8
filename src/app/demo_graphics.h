// The demo's GL resources and their lifetime: the one GPU copy of the meshes that every renderer
// draws from, the main renderer, the GPU timer, the exact mode's tracer, the error view's pass and
// the course's own frame (made the first time the course preset draws).
// Made from the CPU side (init), freed (release), and made again after a lost context.
#pragma once

#include <memory>

#include "app/error_view_pass.h"
#include "app/mesh_library.h"
#include "core/accuracy_settings.h"
#include "core/result.h"
#include "core/skybox_faces.h"
#include "course/course_frame.h"
#include "gfx/exact_tracer.h"
#include "gfx/gpu_timer.h"
#include "gfx/mesh_buffer.h"
#include "gfx/scene_renderer.h"

namespace reflect {

class DemoGraphics {
 public:
  // Makes the main renderer for `accuracy` (the meshes, when there are none yet, from `library`,
  // which uploads into them from now on), then what setUpExact makes. Returns "" or a message.
  std::string init(const AccuracySettings& accuracy, bool showError, MeshLibrary& library,
                   const CubeFaces* skybox);
  // The exact mode's tracer (when `accuracy` may trace, or with the error view) and the error
  // view's pass: made, or left unused, as the settings ask. Returns "" or a message.
  std::string setUpExact(const AccuracySettings& accuracy, bool showError, MeshLibrary& library,
                         const CubeFaces* skybox);
  // A new sky for every renderer and the tracer. Returns "" or a message.
  std::string setSkybox(const CubeFaces& faces);
  // Mesh `name` was replaced: the tracer, when there is one, takes its new tree.
  void meshReplaced(const std::string& name, MeshLibrary& library);
  // Frees the GL resources. After a lost context (markGlContextLost) the same call forgets the
  // names instead: each handle knows its context is gone.
  void release(MeshLibrary& library);

  bool ready() const { return renderer_ != nullptr; }
  SceneRenderer* renderer() const { return renderer_.get(); }
  GpuTimer& timer() const { return *timer_; }
  ExactTracer* tracer() const { return tracer_.get(); }
  ErrorViewPass& errorView() { return errorView_; }
  // The course's frame for `faceSize` faces: made on first use, made again for another size.
  Result<CourseFrame*> courseFrame(int faceSize);
  const MeshBuffers* meshes() const { return meshes_.get(); }

 private:
  std::unique_ptr<MeshBuffers> meshes_;
  std::unique_ptr<SceneRenderer> renderer_;
  std::unique_ptr<GpuTimer> timer_;
  std::unique_ptr<ExactTracer> tracer_;
  ErrorViewPass errorView_;
  std::unique_ptr<CourseFrame> course_;
  int courseFaceSize_ = 0;
};

}  // namespace reflect
