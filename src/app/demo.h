// The demo's state, independent of platform: the scene, its meshes (kept on the CPU so a lost GL
// context can be rebuilt), the camera, the clock, the frame planner, the renderer and the last
// frame's stats.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_stats.h"
#include "core/accuracy_settings.h"
#include "core/animation_clock.h"
#include "core/bvh.h"
#include "core/camera.h"
#include "core/frame_planner.h"
#include "core/frustum.h"
#include "core/mesh_data.h"
#include "core/obj_loader.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/error_view.h"
#include "gfx/exact_tracer.h"
#include "gfx/gpu_timer.h"
#include "gfx/scene_renderer.h"

namespace reflect {

class Demo {
 public:
  explicit Demo(Scene scene);

  // Loads the OBJ at `path` as the scene's mesh `name`. On failure returns the message (naming
  // the file) and keeps the mesh it had; on success returns "". What the loader let pass with a
  // warning is in lastWarnings().
  std::string loadMesh(const std::string& name, const std::string& path);
  // The same for OBJ text already in memory (the page fetches files); `source` names it in
  // messages.
  std::string loadMeshText(const std::string& name, const std::string& text,
                           const std::string& source);
  // A mesh made in memory (generated scenes); levels of detail and chunks are built as for files.
  std::string setMeshData(const std::string& name, MeshData mesh);
  // Every scene mesh from `directory`, by file name. Returns "" or the first failure's message;
  // lastWarnings() holds the warnings of every file it loaded.
  std::string loadMeshesFrom(const std::string& directory);
  // The warnings of the last loadMesh, loadMeshText or loadMeshesFrom (each names its file; empty
  // when the files were clean or the load failed), for the caller to show.
  const std::vector<std::string>& lastWarnings() const { return lastWarnings_; }
  bool hasAllMeshes() const;
  // The next coarser level of mesh `name`, as indices into its level-0 vertices (the page
  // simplifies with npm's meshoptimizer). Returns "" or a message.
  std::string addLodLevel(const std::string& name, const std::vector<uint32_t>& indices);
  const MeshData* meshLevel(const std::string& name, int lod) const;

  // Adds an object (its mesh must be loaded first, e.g. with loadMeshText). Returns "" or why not.
  std::string addObject(const SceneObject& object);
  // Changes object `index`'s material from a scene-file "material" object. Returns "" or an error.
  std::string setMaterialJson(int index, const std::string& json);

  // The static cube map of the scene's skybox (kept on the CPU for a context restore).
  std::string setSkybox(CubeFaces faces);
  bool hasSkybox() const { return skybox_.has_value(); }
  // Its faces (what the skybox pass samples), or nullptr.
  const CubeFaces* skyboxFaces() const { return skybox_ ? &*skybox_ : nullptr; }

  // Creates the GL resources from the CPU-side data. Call once a context is current, and again
  // after a lost context is restored. Returns "" or a message.
  std::string initGraphics();
  // The context is gone: forget GL names without calling GL.
  void loseGraphics();
  // Frees the GL resources (the context stays); initGraphics makes them again.
  void releaseGraphics();
  bool graphicsReady() const { return renderer_ != nullptr; }

  // Advances the clock by dt seconds and renders one complete frame (planned capture, then main
  // pass) into `framebuffer` (0 = the canvas). With `waitForGpu`, timings include the GPU's work.
  const FrameStats& frame(double dtSeconds, unsigned framebuffer, int width, int height,
                          bool waitForGpu);

  LookCamera& camera() { return camera_; }
  const LookCamera& camera() const { return camera_; }
  AnimationClock& clock() { return clock_; }
  const Scene& scene() const { return scene_; }
  const FrameStats& lastStats() const { return stats_; }
  const PlannerSettings& plannerSettings() const { return plannerSettings_; }
  const AccuracySettings& accuracySettings() const { return accuracy_; }
  // Rebuilds the GL resources when they exist (programs and capture targets depend on it).
  // Returns "" or a message.
  std::string setAccuracySettings(const AccuracySettings& settings);
  // Renders the main view with mirrors and glass writing the direction they look up (RGB) into
  // `framebuffer` (a float target), for the accuracy measurement. Time does not advance.
  void renderLookupDirections(unsigned framebuffer, int width, int height);
  // Where each scene object (in the scene's order) lands on a width x height view now: its
  // bounding box projected by the camera (see screenBox), in fractions of the view.
  std::vector<ScreenBox> screenBoxes(int width, int height) const;
  void setPlannerSettings(const PlannerSettings& settings);
  // The live error view (show error): each frame is also rendered in the exact mode off screen,
  // compared with the current mode's on the GPU, and drawn as a heat map over the reflectors;
  // the numbers are in the frame's stats. Returns "" or a message.
  std::string setShowError(bool on);
  bool showError() const { return showError_; }
  // Mesh `name`'s tree for the exact mode (built when the mesh loaded), or null.
  const MeshBvh* meshBvh(const std::string& name) const;
  // Sets the capture face size for the next initGraphics, clamped to 1..kMaxCubeFaceSize;
  // returns a message when it had to clamp.
  std::string setCubeFaceSize(int size);
  static constexpr int kMaxCubeFaceSize = 4096;  // 6 x 4096^2 x 4 bytes = 400 MB already
  // The live cube map of the scene's first reflector (0 before the first capture), for tests.
  unsigned environmentTexture() const;
  // The renderer (null before initGraphics), for tests that read its captures back.
  const SceneRenderer* renderer() const { return renderer_.get(); }

 private:
  std::string adopt(const std::string& name, Result<MeshData> mesh);
  std::string adoptLoaded(const std::string& name, Result<LoadedMesh> loaded);
  std::vector<PlannedObject> plannedObjects(double seconds) const;
  // Everything besides the objects that the captures depend on, as values.
  CaptureContext captureContext() const;
  // The main pass's draws for a width x height viewport (view LOD, if on).
  std::vector<DrawItem> viewDraws(const std::vector<PlannedObject>& objects, int width,
                                  int height) const;
  // The exact mode's tracer (in the exact mode and with the error view), the error view's
  // renderer and targets: made, or dropped, as the settings ask. Returns "" or a message.
  std::string setUpExact();
  // The error view's pass: the exact frame, the comparison into `framebuffer`, the numbers.
  void renderErrorView(const std::vector<PlannedObject>& objects, const ViewParams& view,
                       const std::vector<DrawItem>& draws, unsigned framebuffer);

  Scene scene_;
  std::map<std::string, std::vector<MeshData>> meshes_;  // levels of detail, 0 = as loaded
  std::map<std::string, uint32_t> meshRevisions_;
  std::vector<std::string> lastWarnings_;
  std::optional<CubeFaces> skybox_;
  LookCamera camera_;
  AnimationClock clock_;
  FramePlanner planner_;
  PlannerSettings plannerSettings_;
  AccuracySettings accuracy_;
  uint64_t skyboxContent_ = 0;  // contentHash(*skybox_): captures compare it by value
  std::unique_ptr<SceneRenderer> renderer_;
  std::unique_ptr<GpuTimer> gpuTimer_;
  FrameStats stats_;
  std::map<std::string, std::shared_ptr<const MeshBvh>> bvhs_;  // level 0's, by mesh name
  std::unique_ptr<ExactTracer> exactTracer_;
  std::unique_ptr<SceneRenderer> exactRenderer_;  // the error view's exact pass
  std::unique_ptr<ErrorView> errorView_;
  FramePlanner exactPlanner_;
  bool showError_ = false;
};

}  // namespace reflect
