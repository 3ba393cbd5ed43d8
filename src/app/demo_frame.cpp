// Demo's frame: the scene at time t, the plan, the captures, the main pass (and the error view's
// pass when it is on), and the frame's stats.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/demo.h"
#include "core/probe_layout.h"
#include "core/settings_schema.h"
#include "gfx/gl.h"

namespace reflect {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
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

void Demo::renderLookupDirections(unsigned framebuffer, int width, int height, int output) {
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || width < 1 || height < 1) return;
  const std::vector<PlannedObject> objects = plannedObjects(clock_.seconds());
  FramePlan plan = FramePlanner::layout(objects, captureContext());
  // Each reflector the way the last frame drew it: traced, or from its probe.
  std::erase_if(plan.probes, [&](const ProbePlan& probe) {
    return std::any_of(lastTraced_.begin(), lastTraced_.end(),
                       [&](const ProbeLayout& t) { return t.reflector == probe.reflector; });
  });
  plan.traced = lastTraced_;
  renderer->drawMain(scene_, clock_.seconds(), plan, viewParams(width, height),
                     viewDraws(objects, width, height), framebuffer, width, height, output);
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

void Demo::capturePass(const FramePlan& plan, bool waitForGpu) {
  GpuTimer& timer = graphics_.timer();
  timer.begin(GpuTimer::kCapture);
  graphics_.renderer()->setTimePrefilter(waitForGpu);
  Result<PassCounts> capture = stepCallback_ ? captureInSteps(plan)
                                             : graphics_.renderer()->capture(
                                                   scene_, stats_.timeSeconds, plan, camera_.eye());
  timer.end();
  if (!capture) {
    stats_.error = "capture failed: " + capture.error();
    std::fprintf(stderr, "%s\n", stats_.error.c_str());
    planner_.invalidate();  // nothing it planned was drawn
  } else {
    stats_.captureDrawCalls = capture.value().drawCalls;
    stats_.captureTriangles = capture.value().triangles;
    stats_.filterSamples = graphics_.renderer()->lastFilterSamples();
    stats_.filterMs = graphics_.renderer()->lastFilterMs();
  }
  if (waitForGpu) reflect::waitForGpu();
  stats_.probes = static_cast<int>(plan.probes.size());
  stats_.tracedReflectors = 0;
  for (const ProbeLayout& t : plan.traced) {
    stats_.tracedReflectors += static_cast<int>(t.members.size());
  }
  stats_.facesCaptured = plan.facesCaptured();
}

const FrameStats& Demo::frame(double dtSeconds, unsigned framebuffer, int width, int height,
                              bool waitForGpu) {
  meshes_.collectFinished();  // levels built since the last frame join this one
  clock_.advance(dtSeconds);
  startStats(waitForGpu, width, height);
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || width < 1 || height < 1) return stats_;  // hidden canvas: nothing to draw

  const auto start = std::chrono::steady_clock::now();
  const std::vector<PlannedObject> objects = plannedObjects(stats_.timeSeconds);
  const FramePlan plan =
      planner_.plan(objects, captureContext(), plannerSettings_, plannerView(width, height));
  lastTraced_ = plan.traced;
  noteLevelUse(plan);
  ExactTracer* tracer = graphics_.tracer();
  if (tracer && (!plan.traced.empty() || showError_)) {
    tracer->prepare(scene_, stats_.timeSeconds, plan, camera_.eye());
  }
  capturePass(plan, waitForGpu);
  stats_.captureMs = millisecondsSince(start);

  const ViewParams view = viewParams(width, height);
  ErrorViewPass& errorPass = graphics_.errorView();
  const bool errorView = showError_ && errorPass.prepare(width, height);
  const std::vector<DrawItem> draws = viewDraws(objects, width, height);
  GpuTimer& timer = graphics_.timer();
  timer.begin(GpuTimer::kMain);
  const PassCounts main =
      renderer->drawMain(scene_, stats_.timeSeconds, plan, view, draws,
                         errorView ? errorPass.currentFramebuffer() : framebuffer, width, height);
  timer.end();
  timer.endFrame();
  if (waitForGpu) reflect::waitForGpu();
  stats_.frameMs = millisecondsSince(start);
  if (timer.lastMs(GpuTimer::kCapture) && timer.lastMs(GpuTimer::kMain)) {
    stats_.gpuCaptureMs = *timer.lastMs(GpuTimer::kCapture);
    stats_.gpuFrameMs = stats_.gpuCaptureMs + *timer.lastMs(GpuTimer::kMain);
  }
  stats_.mainDrawCalls = main.drawCalls;
  stats_.mainTriangles = main.triangles;
  if (stats_.error.empty() && !renderer->programError().empty()) {
    stats_.error = "a shader did not build: " + renderer->programError();
  }
  if (errorView) {
    errorPass.render(scene_, objects, captureContext(), view, draws, framebuffer, stats_);
  }
  if (pick_.on()) {
    const std::string error = pick_.draw(view.projection * view.view, framebuffer, width, height);
    if (!error.empty() && stats_.error.empty()) stats_.error = "pick a pixel: " + error;
  }
  lastPlan_ = plan;
  inside_.afterFrame(plan);
  if (inside_.on()) {
    const auto lookups = [this](unsigned target, int w, int h) {
      renderLookupDirections(target, w, h);
    };
    inside_.draw(*renderer, scene_, plan, lookups, framebuffer, width, height);
  }
  if (!firstFrameDrawn_) {
    // The first frame is on screen: now build what the meshes were drawn without.
    firstFrameDrawn_ = true;
    meshes_.allowBuilds();
  }
  return stats_;
}

}  // namespace reflect
