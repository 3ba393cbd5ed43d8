// Demo's frame: the frame record (the one place a frame is laid out and planned), then its
// drawing: the course's own file for the course preset, or the general renderer's captures, main
// pass and error view; the frame's stats.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/demo.h"
#include "core/presets.h"
#include "core/probe_layout.h"
#include "core/settings_schema.h"
#include "gfx/gl.h"

namespace reflect {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Runs `draw` inside the GPU timer's query for `pass`, then, when asked, waits for the GPU, so
// that the CPU's clock sees the pass's whole cost too.
template <typename Draw>
auto timedPass(GpuTimer& timer, GpuTimer::Pass pass, bool waitForGpu, Draw draw) {
  timer.begin(pass);
  auto counts = draw();
  timer.end();
  if (waitForGpu) reflect::waitForGpu();
  return counts;
}

}  // namespace

CaptureContext Demo::captureContext() const {
  return CaptureContext{camera_.eye(),
                        scene_.capture.faceSize,
                        scene_.capture.near,
                        scene_.capture.far,
                        scene_.light,
                        scene_.clearColour,
                        skyboxContent_,
                        accuracy_,
                        plannerSettings_.captureLod,
                        skybox_ ? (*skybox_)[0].width : 0};
}

std::vector<PlannedObject> Demo::plannedObjects(double seconds) const {
  std::vector<PlannedObject> planned;
  planned.reserve(scene_.objects.size());
  for (const SceneObject& object : scene_.objects) {
    PlannedObject p;
    meshes_.describe(object.mesh, p);
    p.model = scene_.modelMatrix(object, seconds);
    p.colour = object.colour;
    p.look = object.look();
    p.probed = object.needsLiveProbe();
    p.probeLit = object.probeLit();
    p.ownsLightProbe = object.ownsLightProbe();
    p.probeGroup = object.probeGroup;
    p.probeCentre = capturePoint(object.probeCentre, accuracy_.captureAtOrigin);
    planned.push_back(p);
  }
  return planned;
}

std::vector<DrawItem> Demo::viewDraws(const std::vector<PlannedObject>& objects, int width,
                                      int height) const {
  const PlannerView view = plannerView(width, height);
  return planViewDraws(objects, view.eye, view.pixelsPerTangent, plannerSettings_);
}

PlannerView Demo::plannerView(int width, int height) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return PlannerView{
      camera_.eye(),
      0.5f * static_cast<float>(height) / std::tan(glm::radians(camera_.fovYDeg(aspect)) * 0.5f),
      static_cast<float>(width) * static_cast<float>(height)};
}

ViewParams Demo::viewParams(int width, int height) const {
  return ViewParams{camera_.view(),
                    camera_.projection(static_cast<float>(width) / static_cast<float>(height)),
                    camera_.eye()};
}

std::vector<ScreenBox> Demo::screenBoxes(int width, int height) const {
  const float aspect = height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
  const glm::mat4 viewProjection = camera_.projection(aspect) * camera_.view();
  std::vector<ScreenBox> boxes;
  for (const PlannedObject& object : plannedObjects(clock_.seconds())) {
    boxes.push_back(screenBox(object.localBounds, object.model, viewProjection));
  }
  return boxes;
}

bool Demo::drawsCourseFrame() const {
  // The course's file draws the plain frame; the views that look inside it read the general
  // renderer's captures and plan, which the GL test holds to the same pixels.
  const Preset& course = *findPreset("course");
  return courseFrameAllowed_ && course.planner == plannerSettings_ &&
         course.accuracy == accuracy_ && CourseFrame::whyNot(scene_).empty() && !showError_ &&
         !inside_.on() && !pick_.on() && !stepCallback_;
}

FrameRecord Demo::record(int width, int height, Planning planning) {
  FrameRecord f;
  f.seconds = clock_.seconds();
  f.width = width;
  f.height = height;
  f.objects = plannedObjects(f.seconds);
  f.context = captureContext();
  f.view = viewParams(width, height);
  f.mainDraws = viewDraws(f.objects, width, height);
  const PlannerView view = plannerView(width, height);
  if (planning == Planning::NextFrame) {
    f.course = drawsCourseFrame();
    // The course's file draws into its own cube: the general renderer's holds nothing the
    // planner could remember.
    if (lastFrame_.course && !f.course) planner_.invalidate();
    f.plan = planner_.plan(f.objects, f.context, plannerSettings_, view);
  } else {
    FramePlanner firstFrame;  // a first frame's planner: every face it needs, nothing remembered
    firstFrame.setCosts(planner_.costs());
    f.plan = firstFrame.plan(f.objects, f.context, plannerSettings_, view);
  }
  if (showError_ && planning == Planning::NextFrame) {
    if (graphics_.errorView().takeRemade()) exactPlanner_.invalidate();
    CaptureContext exact = f.context;
    exact.accuracy.search = Search::Exact;
    exact.captureLod = 0.0f;
    f.exactPlan = exactPlanner_.plan(f.objects, exact, PlannerSettings{});
  }
  return f;
}

void Demo::ensureGeneralCaptures() {
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || !lastFrame_.course || generalCaptured_) return;
  generalCaptured_ = true;
  Result<PassCounts> capture = renderer->capture(scene_, lastFrame_.plan, lastFrame_.view.eye);
  if (!capture) std::fprintf(stderr, "capture failed: %s\n", capture.error().c_str());
}

void Demo::renderLookupDirections(unsigned framebuffer, int width, int height, int output) {
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || width < 1 || height < 1 || lastFrame_.empty()) return;
  ensureGeneralCaptures();
  const FrameRecord& f = lastFrame_;
  const bool sameSize = width == f.width && height == f.height;
  renderer->drawMain(scene_, f.plan, sameSize ? f.view : viewParams(width, height),
                     sameSize ? f.mainDraws : viewDraws(f.objects, width, height), framebuffer,
                     width, height, output);
}

void Demo::startStats(bool waitForGpu, int width, int height) {
  stats_ = FrameStats{};
  stats_.timeSeconds = clock_.seconds();
  stats_.orbitDegrees = clock_.orbitDegrees();
  stats_.timing = waitForGpu ? "gpu-finish" : "cpu-submit";
  stats_.policy = policyName(plannerSettings_.policy);
  stats_.cubeFaceSize = scene_.capture.faceSize;
  stats_.width = width;
  stats_.height = height;
  stats_.lodReady = lodReady();
  stats_.meshBytes = meshGpuBytes();
  stats_.meshCpuBytes = meshCpuBytes();
}

void Demo::capturePass(const FrameRecord& f, bool waitForGpu) {
  GpuTimer& timer = graphics_.timer();
  timer.begin(GpuTimer::kCapture);
  // The prefilter's own time, when the frame waits for the GPU (benches): waits on both sides.
  // So is the irradiance projection's.
  std::chrono::steady_clock::time_point stageStart;
  double filterMs = 0.0, irradianceMs = 0.0;
  if (waitForGpu) {
    graphics_.renderer()->setPrefilterTiming([&](SceneRenderer::AfterCapture stage, bool starting) {
      reflect::waitForGpu();
      if (starting) {
        stageStart = std::chrono::steady_clock::now();
        return;
      }
      (stage == SceneRenderer::AfterCapture::Prefilter ? filterMs : irradianceMs) =
          millisecondsSince(stageStart);
    });
  }
  Result<PassCounts> capture =
      stepCallback_ ? captureInSteps(f) : graphics_.renderer()->capture(scene_, f.plan, f.view.eye);
  timer.end();
  if (!capture) {
    stats_.error = "capture failed: " + capture.error();
    std::fprintf(stderr, "%s\n", stats_.error.c_str());
    planner_.invalidate();  // nothing it planned was drawn
  } else {
    stats_.captureDrawCalls = capture.value().drawCalls;
    stats_.captureTriangles = capture.value().triangles;
    stats_.filterSamples = graphics_.renderer()->lastFilterSamples();
    stats_.filterMs = filterMs;
    stats_.irradianceMs = irradianceMs;
    stats_.irradianceProjections = graphics_.renderer()->lastIrradianceProjections();
  }
  graphics_.renderer()->setPrefilterTiming(nullptr);
  if (waitForGpu) reflect::waitForGpu();
}

void Demo::drawGeneral(const FrameRecord& f, unsigned framebuffer, bool waitForGpu,
                       std::chrono::steady_clock::time_point start) {
  SceneRenderer& renderer = *graphics_.renderer();
  ExactTracer* tracer = graphics_.tracer();
  if (tracer && (!f.plan.traced.empty() || f.exactPlan)) {
    tracer->prepare(scene_, f.plan, f.view.eye);
  }
  capturePass(f, waitForGpu);
  stats_.captureMs = millisecondsSince(start);
  ErrorViewPass& errorPass = graphics_.errorView();
  const bool errorView = f.exactPlan && errorPass.prepare(f.width, f.height);
  const unsigned target = errorView ? errorPass.currentFramebuffer() : framebuffer;
  const PassCounts main = timedPass(graphics_.timer(), GpuTimer::kMain, waitForGpu, [&] {
    return renderer.drawMain(scene_, f.plan, f.view, f.mainDraws, target, f.width, f.height);
  });
  stats_.frameMs = millisecondsSince(start);
  stats_.mainDrawCalls = main.drawCalls;
  stats_.mainTriangles = main.triangles;
  stats_.probes = static_cast<int>(f.plan.probes.size());
  for (const ProbeLayout& t : f.plan.traced) {
    stats_.tracedReflectors += static_cast<int>(t.members.size());
  }
  stats_.facesCaptured = f.plan.facesCaptured();
  if (stats_.error.empty() && !renderer.programError().empty()) {
    stats_.error = "a shader did not build: " + renderer.programError();
  }
  if (errorView && !errorPass.render(scene_, f, framebuffer, stats_)) {
    exactPlanner_.invalidate();  // nothing the exact plan captured was drawn
  }
}

void Demo::drawCourse(const FrameRecord& f, unsigned framebuffer, bool waitForGpu,
                      std::chrono::steady_clock::time_point start) {
  Result<CourseFrame*> made = graphics_.courseFrame(scene_.capture.faceSize);
  if (!made) {
    stats_.error = "the course's frame: " + made.error();
    std::fprintf(stderr, "%s\n", stats_.error.c_str());
    return;
  }
  CourseFrame& course = *made.value();
  const MeshBuffers& meshes = *graphics_.meshes();
  GpuTimer& timer = graphics_.timer();
  const PassCounts capture = timedPass(timer, GpuTimer::kCapture, waitForGpu, [&] {
    return course.captureFaces(scene_, f.seconds, meshes, f.view.eye);
  });
  stats_.captureMs = millisecondsSince(start);
  const PassCounts main = timedPass(timer, GpuTimer::kMain, waitForGpu, [&] {
    return course.drawMain(scene_, f.seconds, meshes, f.view.view, f.view.projection, f.view.eye,
                           framebuffer, f.width, f.height);
  });
  stats_.frameMs = millisecondsSince(start);
  stats_.captureDrawCalls = capture.drawCalls;
  stats_.captureTriangles = capture.triangles;
  stats_.mainDrawCalls = main.drawCalls;
  stats_.mainTriangles = main.triangles;
  stats_.probes = 1;
  stats_.facesCaptured = 6;
  stats_.courseFrame = true;
}

const FrameStats& Demo::frame(double dtSeconds, unsigned framebuffer, int width, int height,
                              bool waitForGpu) {
  meshes_.collectFinished();  // levels built since the last frame join this one
  clock_.advance(dtSeconds);
  startStats(waitForGpu, width, height);
  if (!graphics_.renderer() || width < 1 || height < 1) return stats_;  // hidden canvas

  const auto start = std::chrono::steady_clock::now();  // the frame's time includes its plan
  lastFrame_ = record(width, height, Planning::NextFrame);
  noteLevelUse(lastFrame_.plan);  // chunks and levels are built once a frame draws them
  generalCaptured_ = !lastFrame_.course;
  if (lastFrame_.course) {
    drawCourse(lastFrame_, framebuffer, waitForGpu, start);
  } else {
    drawGeneral(lastFrame_, framebuffer, waitForGpu, start);
  }
  GpuTimer& timer = graphics_.timer();
  timer.endFrame();
  if (timer.lastMs(GpuTimer::kCapture) && timer.lastMs(GpuTimer::kMain)) {
    stats_.gpuCaptureMs = *timer.lastMs(GpuTimer::kCapture);
    stats_.gpuFrameMs = stats_.gpuCaptureMs + *timer.lastMs(GpuTimer::kMain);
  }
  if (pick_.on()) {
    const ViewParams& view = lastFrame_.view;
    const std::string error = pick_.draw(view.projection * view.view, framebuffer, width, height);
    if (!error.empty() && stats_.error.empty()) stats_.error = "pick a pixel: " + error;
  }
  inside_.afterFrame(lastFrame_.plan);
  if (inside_.on()) {
    const auto lookups = [this](unsigned target, int w, int h) {
      renderLookupDirections(target, w, h);
    };
    inside_.draw(*graphics_.renderer(), scene_, lastFrame_.plan, lookups, framebuffer, width,
                 height);
  }
  if (!firstFrameDrawn_) {
    // The first frame is on screen: now build what the meshes were drawn without.
    firstFrameDrawn_ = true;
    meshes_.allowBuilds();
  }
  return stats_;
}

}  // namespace reflect
