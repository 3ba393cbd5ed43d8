// The demo's state, independent of platform: the scene, its meshes (kept on the CPU so a lost GL
// context can be rebuilt), the camera, the clock, the frame planner, the renderer and the last
// frame's stats.
//
// First frame first: a loaded mesh is drawn as it was parsed. Its chunks (the capture's culling
// units) and, when a LOD setting is on, its coarser levels are built afterwards: natively on a
// background thread started after the first frame and taken in at the start of a later frame
// (waitForLevels() waits for them, for tests and benchmarks); in the page by a Web Worker, which
// hands them in through setMeshChunks / addLodLevel / finishLevels (LevelBuilds::External).
// Coarser levels are kept as index lists over level 0's vertices, and built only while a LOD
// setting is on.
#pragma once

#include <future>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/frame_stats.h"
#include "app/inside_views.h"
#include "core/accuracy_settings.h"
#include "core/animation_clock.h"
#include "core/bvh.h"
#include "core/camera.h"
#include "core/frame_planner.h"
#include "core/frustum.h"
#include "core/mesh_data.h"
#include "core/mesh_lod.h"
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
  const std::vector<std::string>& lastWarnings() const { return lastWarnings_; }
  bool hasAllMeshes() const;
  // Mesh `name` as loaded (level 0; its triangles in chunk order once chunks are built), or null.
  // Coarser levels are index lists: levelTriangles() gives their sizes.
  const MeshData* meshLevel(const std::string& name, int lod) const;
  // Triangles of each level of mesh `name`, level 0 first (empty if there is no such mesh).
  std::vector<size_t> levelTriangles(const std::string& name) const;
  // Each level of mesh `name`, level 0 first: its triangles, chunks and the vertices its GPU copy
  // holds (level 0: all of the mesh's; a coarser level: the ones it uses).
  struct LevelInfo {
    size_t triangles = 0;
    size_t chunks = 0;
    size_t vertices = 0;
  };
  std::vector<LevelInfo> levelInfo(const std::string& name) const;

  // Who builds chunks and levels of detail: a thread of this demo (native), or the caller (the
  // page's worker, through levelJobs and the three calls after it).
  enum class LevelBuilds { Background, External };
  void setLevelBuilds(LevelBuilds builds) { levelBuilds_ = builds; }
  // Nothing left to build: every mesh chunked and, while a LOD setting is on, its levels built.
  bool lodReady() const;
  // Background: starts what is left and waits for it (it is taken in before this returns).
  void waitForLevels();
  // What is left to build, for an external builder: each mesh (with its revision, which the
  // answers must carry) and whether its chunks, its coarser levels or both are wanted.
  struct LevelJob {
    std::string name;
    uint32_t revision = 0;
    bool chunks = false;
    bool coarser = false;
  };
  std::vector<LevelJob> levelJobs() const;
  // Mesh `name`'s triangles in chunk order (a reordering of its indices) and the chunks' triangle
  // counts. Returns "" or why not (a stale revision, counts that do not add up, bad indices).
  // The indices are copied over the mesh's own (as many): no second array of them is allocated.
  std::string setMeshChunks(const std::string& name, uint32_t revision,
                            std::span<const uint32_t> indices,
                            const std::vector<uint32_t>& chunkTriangles);
  // The next coarser level of mesh `name`: indices into its level-0 vertices, in chunk order.
  std::string addLodLevel(const std::string& name, uint32_t revision, std::vector<uint32_t> indices,
                          const std::vector<uint32_t>& chunkTriangles);
  // Every coarser level of mesh `name` has been given (there may be none).
  std::string finishLevels(const std::string& name, uint32_t revision);

  // Bytes of the meshes as the GPU holds them (every level's vertices and indices as uploaded),
  // and as this demo keeps them on the CPU (level 0's arrays, the coarser levels' index lists and
  // every chunk table, by capacity).
  size_t meshGpuBytes() const;
  size_t meshCpuBytes() const;

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
  // What the last frame planned: its probes and their faces, the reflectors it traced.
  const FramePlan& lastPlan() const { return lastPlan_; }
  // Time spent building the exact mode's trees so far (load-time accounting).
  double bvhBuildMs() const { return bvhBuildMs_; }
  // What the planner weighed for each probe in the last frame (search: planned).
  const std::vector<MethodChoice>& methodChoices() const { return planner_.choices(); }
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
  // Inside the frame: show the frame as a teaching view (the faces view) instead of its picture.
  void setInsideView(InsideView view, FacesChannel channel) { inside_.set(view, channel); }
  const InsideViews& insideViews() const { return inside_; }
  // The view settings the demo draws by (show error, the inside views); "" or a message.
  std::string setViewSettings(const ViewSettings& view) {
    inside_.set(view.inside, view.facesChannel);
    return setShowError(view.showError);
  }
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
  // A coarser level: its triangles over level 0's vertices, in chunk order.
  struct CoarseLevel {
    std::vector<uint32_t> indices;
    std::vector<MeshChunk> chunks;
    size_t vertices = 0;  // distinct vertices it uses: what its GPU copy holds
  };
  struct MeshEntry {
    std::shared_ptr<MeshData> base;  // shared with a background build that reads it
    std::vector<CoarseLevel> coarser;
    bool chunked = false;
    bool levelsBuilt = false;          // coarser levels made (possibly none: small meshes)
    std::future<BuiltLevels> pending;  // a background build under way
  };

  std::string adopt(const std::string& name, Result<MeshData> mesh);
  std::string adoptLoaded(const std::string& name, Result<LoadedMesh> loaded);
  bool needsLevels() const;
  // Starts a background build for every mesh with work left and none under way.
  void startBuilds();
  // Takes in the builds that are done (all of them, waiting, with `wait`).
  void collectBuilds(bool wait);
  // The mesh `name` at `revision`, or the reason it is not.
  MeshEntry* entryAt(const std::string& name, uint32_t revision, std::string* problem);
  // Uploads every level of `name` to the renderer (level 0 first: it drops the old levels).
  // Mesh `name`'s tree for the exact mode, built from `mesh` on first need.
  std::shared_ptr<const MeshBvh> bvhFor(const std::string& name,
                                        std::shared_ptr<const MeshData> mesh);
  void uploadLevels(const std::string& name, const MeshEntry& entry);
  std::vector<PlannedObject> plannedObjects(double seconds) const;
  // Everything besides the objects that the captures depend on, as values.
  CaptureContext captureContext() const;
  // The main pass's draws for a width x height viewport (view LOD, if on).
  std::vector<DrawItem> viewDraws(const std::vector<PlannedObject>& objects, int width,
                                  int height) const;
  // What the planner knows of the camera for a width x height viewport.
  PlannerView plannerView(int width, int height) const;
  // Whether the settings may trace some reflector's rays (search exact or planned).
  bool mayTrace() const;
  // The exact mode's tracer (in the exact mode and with the error view), the error view's
  // renderer and targets: made, or dropped, as the settings ask. Returns "" or a message.
  std::string setUpExact();
  // The error view's pass: the exact frame, the comparison into `framebuffer`, the numbers.
  void renderErrorView(const std::vector<PlannedObject>& objects, const ViewParams& view,
                       const std::vector<DrawItem>& draws, unsigned framebuffer);

  Scene scene_;
  std::map<std::string, MeshEntry> meshes_;
  std::map<std::string, uint32_t> meshRevisions_;
  // Builds of meshes since replaced: their results are dropped once they are done (a future of
  // std::async would wait for its thread if it were destroyed before).
  std::vector<std::future<BuiltLevels>> abandoned_;
  LevelBuilds levelBuilds_ = LevelBuilds::Background;
  bool firstFrameDrawn_ = false;
  std::vector<std::string> lastWarnings_;
  std::optional<CubeFaces> skybox_;
  LookCamera camera_;
  AnimationClock clock_;
  FramePlanner planner_;
  // The reflectors the last frame traced: a pass that reads the frame's cubes again
  // (renderLookupDirections) draws each the same way.
  std::vector<ProbeLayout> lastTraced_;
  FramePlan lastPlan_;
  PlannerSettings plannerSettings_;
  AccuracySettings accuracy_;
  uint64_t skyboxContent_ = 0;  // contentHash(*skybox_): captures compare it by value
  std::unique_ptr<SceneRenderer> renderer_;
  InsideViews inside_;
  std::unique_ptr<GpuTimer> gpuTimer_;
  FrameStats stats_;
  std::map<std::string, std::shared_ptr<const MeshBvh>> bvhs_;  // level 0's, by mesh name
  std::unique_ptr<ExactTracer> exactTracer_;
  std::unique_ptr<SceneRenderer> exactRenderer_;  // the error view's exact pass
  std::unique_ptr<ErrorView> errorView_;
  FramePlanner exactPlanner_;
  bool showError_ = false;
  double bvhBuildMs_ = 0.0;
};

}  // namespace reflect
