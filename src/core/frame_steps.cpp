#include "core/frame_steps.h"

#include "core/cube_faces.h"

namespace reflect {
namespace {

size_t trianglesOf(const std::vector<DrawItem>& draws) {
  size_t triangles = 0;
  for (const DrawItem& d : draws) triangles += d.triangles;
  return triangles;
}

// Which draws a capture pass makes (the renderer's pass 3 also skips flat meshes that face the
// probe, a rule on the GPU's meshes: the count here is the plan's).
const std::vector<DrawItem>& drawsOf(const FacePlan& face, StepPass pass) {
  return pass == StepPass::SecondLayer ? face.secondLayerDraws : face.draws;
}

std::string countText(int objects, size_t triangles) {
  return std::to_string(objects) + (objects == 1 ? " object, " : " objects, ") +
         std::to_string(triangles) + " triangles";
}

std::string probeName(const ProbePlan& probe) {
  return "the probe of object " + std::to_string(probe.reflector + 1);
}

FrameStep faceStep(const ProbePlan& probe, int probeIndex, const FacePlan& face, StepPass pass) {
  FrameStep step;
  step.pass = pass;
  step.probe = probeIndex;
  step.reflector = probe.reflector;
  step.face = face.face;
  const std::vector<DrawItem>& draws = drawsOf(face, pass);
  step.objects = static_cast<int>(draws.size());
  step.triangles = trianglesOf(draws);
  const char* layer = pass == StepPass::SecondLayer ? "layer 2" : "layer 1";
  step.label = std::string(stepPassName(pass)) + " (pass " +
               std::to_string(static_cast<int>(pass)) + ") into " + probeName(probe) + ", face " +
               kCubeFaces[static_cast<size_t>(face.face)].name + ", " + layer + ": " +
               countText(step.objects, step.triangles);
  return step;
}

}  // namespace

std::vector<StepPass> capturePasses(const FacePlan& face) {
  if (face.layers == 2) return {StepPass::Colour, StepPass::Backs, StepPass::SecondLayer};
  return {StepPass::Colour};
}

bool capturesDepths(const ProbePlan& probe, const AccuracySettings& accuracy) {
  return capturedSearch(accuracy.search) == Search::Hierarchical && !probe.plainLookupSuffices;
}

const char* stepPassName(StepPass pass) {
  switch (pass) {
    case StepPass::Colour:
      return "colour";
    case StepPass::SecondLayer:
      return "second layer";
    case StepPass::Backs:
      return "backs";
    case StepPass::DepthPyramid:
      return "depth pyramid";
    case StepPass::Main:
      break;
  }
  return "main pass";
}

std::vector<FrameStep> frameSteps(const FramePlan& plan, const AccuracySettings& accuracy,
                                  const std::vector<DrawItem>& mainDraws) {
  std::vector<FrameStep> steps;
  for (size_t p = 0; p < plan.probes.size(); ++p) {
    const ProbePlan& probe = plan.probes[p];
    if (probe.faces.empty()) continue;  // nothing redrawn: the renderer skips it whole
    for (const FacePlan& face : probe.faces) {
      for (StepPass pass : capturePasses(face)) {
        steps.push_back(faceStep(probe, static_cast<int>(p), face, pass));
      }
    }
    if (!capturesDepths(probe, accuracy)) continue;
    FrameStep pyramid;
    pyramid.pass = StepPass::DepthPyramid;
    pyramid.probe = static_cast<int>(p);
    pyramid.reflector = probe.reflector;
    pyramid.label = "depth pyramid of " + probeName(probe) +
                    ": every level, from the distances of the " +
                    std::to_string(probe.faces.size()) + " faces drawn (no scene triangles)";
    steps.push_back(pyramid);
  }
  FrameStep main;
  main.objects = static_cast<int>(mainDraws.size());
  main.triangles = trianglesOf(mainDraws);
  main.label = "main pass to the screen: " + countText(main.objects, main.triangles);
  steps.push_back(main);
  return steps;
}

}  // namespace reflect
