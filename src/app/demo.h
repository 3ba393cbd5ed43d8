// The demo's state, independent of platform, and the one object the platform layers, the
// benchmarks and the tests hold: the scene, the camera, the clock and the settings, over three
// parts with a job each: the meshes (MeshLibrary: loading, levels of detail, the page's worker
// hand-off, revisions), the GL resources (DemoGraphics: the renderers and their lifetime, the
// error view's pass) and the frame (demo_frame.cpp: plan, capture, main pass, stats).
//
// First frame first: a loaded mesh is drawn as it was parsed, and its chunks and coarser levels
// are built after the first frame (see mesh_library.h).
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/demo_graphics.h"
#include "app/frame_record.h"
#include "app/frame_stats.h"
#include "app/inside_views.h"
#include "app/mesh_library.h"
#include "app/pick_overlay.h"
#include "core/accuracy_settings.h"
#include "core/animation_clock.h"
#include "core/bvh.h"
#include "core/camera.h"
#include "core/frame_planner.h"
#include "core/frame_steps.h"
#include "core/frustum.h"
#include "core/mesh_data.h"
#include "core/obj_loader.h"
#include "core/scene.h"
#include "core/skybox_faces.h"
#include "gfx/scene_renderer.h"

namespace reflect {

class Demo {
 public:
  explicit Demo(Scene scene);
  ~Demo();
  Demo(const Demo&) = delete;
  Demo& operator=(const Demo&) = delete;

  // Loads the OBJ at `path` as the scene's mesh `name`. On failure returns the message (naming
  // the file) and keeps the mesh it had; on success returns "". What the loader let pass with a
  // warning is in lastWarnings().
  std::string loadMesh(const std::string& name, const std::string& path);
  // The same for OBJ text already in memory; `source` names it in messages.
  std::string loadMeshText(const std::string& name, const std::string& text,
                           const std::string& source);
  // The same for a parse done elsewhere (the page streams files through an ObjStreamParser).
  std::string setLoadedMesh(const std::string& name, Result<LoadedMesh> loaded);
  // A mesh made in memory (generated scenes); chunks and levels of detail are built as for files.
  std::string setMeshData(const std::string& name, MeshData mesh);
  // Every scene mesh from `directory`, by file name. Returns "" or the first failure's message;
  // lastWarnings() holds the warnings of every file it loaded.
  std::string loadMeshesFrom(const std::string& directory);
  // The warnings of the last loadMesh, loadMeshText or loadMeshesFrom (each names its file; empty
  // when the files were clean or the load failed), for the caller to show.
  const std::vector<std::string>& lastWarnings() const { return meshes_.lastWarnings(); }
  // Mesh `name` as loaded (level 0; its triangles in chunk order once chunks are built), or null.
  // Coarser levels are index lists: levelTriangles() gives their sizes.
  const MeshData* meshLevel(const std::string& name, int lod) const;
  // "" or a notice that the capture's near plane lies outside a reflector with a probe of its
  // own, so that its captures leave out what passes nearer (core/capture_near.h); for a scene
  // whose meshes are loaded.
  std::string captureNearNotice() const;
  // Triangles of each level of mesh `name`, level 0 first (empty if there is no such mesh).
  std::vector<size_t> levelTriangles(const std::string& name) const;
  // Each level of mesh `name`, level 0 first: its triangles, chunks and the vertices its GPU copy
  // holds (level 0: all of the mesh's; a coarser level: the ones it uses).
  using LevelInfo = MeshLibrary::LevelInfo;
  std::vector<LevelInfo> levelInfo(const std::string& name) const {
    return meshes_.levelInfo(name);
  }

  // Who builds chunks and levels of detail: a thread of this demo (native), or the caller (the
  // page's worker, through levelJobs and the three calls after it).
  using LevelBuilds = MeshLibrary::LevelBuilds;
  void setLevelBuilds(LevelBuilds builds) { meshes_.setLevelBuilds(builds); }
  // Nothing left to build: every mesh chunked and, while a LOD setting is on, its levels built.
  bool lodReady() const { return meshes_.lodReady(); }
  // Background: starts what is left and waits for it (it is taken in before this returns).
  void waitForLevels() { meshes_.waitForLevels(); }
  // Chunks and levels are built only once a frame draws them (noteLevelUse); levelsWanted: some
  // are wanted and not built yet. askForLevels: want all the LOD settings could draw, as
  // waitForLevels does (the page's demo.lodReady(), before it waits for its worker).
  bool levelsWanted() const { return meshes_.levelsWanted(); }
  void askForLevels() { meshes_.askForLevels(); }
  // What is left to build, for an external builder: each mesh (with its revision, which the
  // answers must carry) and whether its chunks, its coarser levels or both are wanted.
  using LevelJob = MeshLibrary::LevelJob;
  std::vector<LevelJob> levelJobs() const { return meshes_.levelJobs(); }
  // Mesh `name`'s triangles in chunk order (a reordering of its indices) and the chunks' triangle
  // counts. Returns "" or why not (a stale revision, counts that do not add up, bad indices).
  // The indices are copied over the mesh's own (as many): no second array of them is allocated.
  std::string setMeshChunks(const std::string& name, uint32_t revision,
                            std::span<const uint32_t> indices,
                            const std::vector<uint32_t>& chunkTriangles) {
    return meshes_.setMeshChunks(name, revision, indices, chunkTriangles);
  }
  // The next coarser level of mesh `name`: indices into its level-0 vertices, in chunk order.
  std::string addLodLevel(const std::string& name, uint32_t revision, std::vector<uint32_t> indices,
                          const std::vector<uint32_t>& chunkTriangles) {
    return meshes_.addLodLevel(name, revision, std::move(indices), chunkTriangles);
  }
  // Every coarser level of mesh `name` has been given (there may be none).
  std::string finishLevels(const std::string& name, uint32_t revision) {
    return meshes_.finishLevels(name, revision);
  }

  // Bytes of the meshes as the GPU holds them (every level's vertices and indices as uploaded),
  // and as this demo keeps them on the CPU (level 0's arrays, the coarser levels' index lists and
  // every chunk table, by capacity).
  size_t meshGpuBytes() const { return meshes_.gpuBytes(); }
  size_t meshCpuBytes() const { return meshes_.cpuBytes(); }

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
  // The context is gone: marks its names dead (markGlContextLost), so that freeing the GL
  // resources forgets them without calling GL; initGraphics makes them again.
  void loseGraphics();
  // Frees the GL resources (the context stays); initGraphics makes them again.
  void releaseGraphics();
  bool graphicsReady() const { return graphics_.ready(); }

  // Advances the clock by dt seconds and renders one complete frame (planned capture, then main
  // pass) into `framebuffer` (0 = the canvas). With `waitForGpu`, timings include the GPU's work.
  const FrameStats& frame(double dtSeconds, unsigned framebuffer, int width, int height,
                          bool waitForGpu);

  LookCamera& camera() { return camera_; }
  const LookCamera& camera() const { return camera_; }
  AnimationClock& clock() { return clock_; }
  const Scene& scene() const { return scene_; }
  const FrameStats& lastStats() const { return stats_; }
  // What the last frame planned: its probes and their faces, the reflectors it traced.
  const FramePlan& lastPlan() const { return lastFrame_.plan; }
  // Under the course preset the course's own file draws the frame (course/course_frame.cpp);
  // off, the general renderer does (the test that holds the two to the same pixels).
  void allowCourseFrame(bool on) { courseFrameAllowed_ = on; }
  // The last frame's record (frame_record.h): what it drew, planned once.
  const FrameRecord& lastFrame() const { return lastFrame_; }
  // The general renderer's captures of the last frame's plan, when the course's own file drew it
  // (the faces view and the lookups read the general renderer's cubes). Otherwise nothing to do.
  void ensureGeneralCaptures();
  // Time spent building the exact mode's trees so far (load-time accounting).
  double bvhBuildMs() const { return meshes_.bvhBuildMs(); }
  // What the planner weighed for each probe in the last frame (search: planned).
  const std::vector<MethodChoice>& methodChoices() const { return planner_.choices(); }
  const PlannerSettings& plannerSettings() const { return plannerSettings_; }
  const AccuracySettings& accuracySettings() const { return accuracy_; }
  // Rebuilds the GL resources when they exist (programs and capture targets depend on it).
  // Returns "" or a message.
  std::string setAccuracySettings(const AccuracySettings& settings);
  // Renders the last frame's main view with mirrors and glass writing the direction they look up
  // (RGB) into `framebuffer` (a float target), for the accuracy measurement. Time does not
  // advance; nothing is drawn before the first frame.
  // `output` (SceneRenderer::kOutput...): what they write; pick a pixel reads the search's landing
  // point (kOutputSearchPoint) and the frame's own colours (kOutputColour) this way.
  void renderLookupDirections(unsigned framebuffer, int width, int height,
                              int output = SceneRenderer::kOutputDirection);
  // Where each scene object (in the scene's order) lands on a width x height view now: its
  // bounding box projected by the camera (see screenBox), in fractions of the view.
  std::vector<ScreenBox> screenBoxes(int width, int height) const;
  void setPlannerSettings(const PlannerSettings& settings);
  // The live error view (show error): each frame is also rendered in the exact mode off screen,
  // compared with the current mode's on the GPU, and drawn as a heat map over the reflectors;
  // the numbers are in the frame's stats. Returns "" or a message.
  std::string setShowError(bool on);
  // Inside the frame: show the frame as a teaching view (the faces view) instead of its picture.
  void setInsideView(InsideView view, FacesChannel channel) { inside_.set(view, channel); }
  const InsideViews& insideViews() const { return inside_; }
  // The view settings the demo draws by (show error, the inside views); "" or a message.
  std::string setViewSettings(const ViewSettings& view) {
    inside_.set(view.inside, view.facesChannel);
    inside_.setProbe(view.facesProbe);
    return setShowError(view.showError);
  }
  bool showError() const { return showError_; }
  // Pick a pixel: rays drawn as 3D lines over each frame (app/pixel_explain.h's pickSegments);
  // none turns them off.
  void showPickedRays(std::vector<RaySegment> segments) { pick_.show(std::move(segments)); }
  const PickOverlay& pickOverlay() const { return pick_; }
  // Step through a frame (demo_steps.cpp): while set, each frame's capture tells `callback` of
  // each step just drawn (`index` in lastSteps()'s order, of `count`), and stops there when it
  // returns false. Unset (the default), frames run as they always do.
  using StepCallback = std::function<bool(const FrameStep& step, int index, int count)>;
  void setStepCallback(StepCallback callback) { stepCallback_ = std::move(callback); }
  // The last frame's steps (core/frame_steps.h): its captures' passes, then its main pass.
  std::vector<FrameStep> lastSteps() const;
  // The page's stepping (paused): the frame now, as a first frame draws it (a fresh planner:
  // every face it needs), drawn into `framebuffer` up to step `step` (clamped to the steps): a
  // capture step's image (frame_step_view.h) in place of the picture, or at the main step the
  // frame itself. The demo's own planner, plan and stats are left as they were. Returns the
  // steps, or why none could be drawn.
  Result<std::vector<FrameStep>> drawFrameStep(int step, unsigned framebuffer, int width,
                                               int height);
  // Mesh `name`'s tree for the exact mode (built when the mesh loaded), or null.
  const MeshBvh* meshBvh(const std::string& name) const { return meshes_.builtBvh(name); }
  // Sets the capture face size for the next initGraphics, clamped to 1..kMaxCubeFaceSize;
  // returns a message when it had to clamp.
  std::string setCubeFaceSize(int size);
  static constexpr int kMaxCubeFaceSize = 4096;  // 6 x 4096^2 x 4 bytes = 400 MB already
  // The live cube map of the scene's first reflector (0 before the first capture), for tests.
  unsigned environmentTexture() const;
  // The renderer (null before initGraphics), for tests that read its captures back.
  const SceneRenderer* renderer() const { return graphics_.renderer(); }
  // The GPU's meshes, which every renderer draws from (null before initGraphics), for tests.
  const MeshBuffers* gpuMeshes() const { return graphics_.meshes(); }

 private:
  std::string adoptLoaded(const std::string& name, Result<LoadedMesh> loaded);
  std::string adopt(const std::string& name, Result<MeshData> mesh);
  // Called by frame() with its plan: from the first plan that captures a probe (or that traces
  // one whose capture levels could make the cheaper), the meshes' chunks and capture LOD's levels
  // are wanted.
  void noteLevelUse(const FramePlan& plan);
  std::vector<PlannedObject> plannedObjects(double seconds) const;
  // The one place a frame is laid out and planned (demo_frame.cpp). NextFrame: the frame the demo
  // draws next, by its planner (which remembers what it captured); FirstFrame: the frame now as a
  // first frame plans it, every face it needs, the planner left untouched (the page's steps).
  enum class Planning { NextFrame, FirstFrame };
  FrameRecord record(int width, int height, Planning planning);
  // Whether the course preset's frame is drawn by the course's own file (course/course_frame.cpp).
  bool drawsCourseFrame() const;
  // A record drawn by the general renderer (captures, main pass, error view) or by the course's
  // file; `start`: when the frame began, for its stats.
  void drawGeneral(const FrameRecord& f, unsigned framebuffer, bool waitForGpu,
                   std::chrono::steady_clock::time_point start);
  void drawCourse(const FrameRecord& f, unsigned framebuffer, bool waitForGpu,
                  std::chrono::steady_clock::time_point start);
  // Everything besides the objects that the captures depend on, as values.
  CaptureContext captureContext() const;
  // The main pass's draws for a width x height viewport (view LOD, if on).
  std::vector<DrawItem> viewDraws(const std::vector<PlannedObject>& objects, int width,
                                  int height) const;
  // What the planner knows of the camera for a width x height viewport.
  PlannerView plannerView(int width, int height) const;
  ViewParams viewParams(int width, int height) const;
  // The frame's stats before anything is drawn: time, settings, sizes, meshes.
  void startStats(bool waitForGpu, int width, int height);
  // The captures of the record's plan into the probes, timed; their counts and any error into the
  // stats.
  void capturePass(const FrameRecord& f, bool waitForGpu);
  // The capture of the record's plan telling stepCallback_ of each step (demo_steps.cpp).
  Result<PassCounts> captureInSteps(const FrameRecord& f);

  Scene scene_;
  MeshLibrary meshes_;
  std::optional<CubeFaces> skybox_;
  LookCamera camera_;
  AnimationClock clock_;
  PlannerSettings plannerSettings_;
  AccuracySettings accuracy_;
  uint64_t skyboxContent_ = 0;  // contentHash(*skybox_): captures compare it by value
  bool showError_ = false;
  DemoGraphics graphics_;
  InsideViews inside_;  // the teaching views (after graphics_: their GL objects go first)
  PickOverlay pick_;    // pick a pixel's rays (after graphics_, as inside_)
  // The frame's state: the planners (the frame's and the error view's exact frame's), the last
  // frame's record and what it measured.
  FramePlanner planner_;
  FramePlanner exactPlanner_;
  bool firstFrameDrawn_ = false;
  FrameRecord lastFrame_;
  bool generalCaptured_ = false;  // the general renderer holds the last record's captures
  bool courseFrameAllowed_ = true;
  FrameStats stats_;
  StepCallback stepCallback_;  // step through a frame: unset unless asked for
};

}  // namespace reflect
