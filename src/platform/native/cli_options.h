// The `reflect` command line, parsed into plain values (no GL, so it is unit-tested).
#pragma once

#include <string>
#include <vector>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/result.h"

namespace reflect {

struct CliOptions {
  std::string command;  // "render", "bench" or "help"
  int width = 800;
  int height = 800;
  double time = 0.0;
  std::string out = "frame.png";
  std::string assets;            // a folder with the course's models, by their file names
  std::string scene = "ex12-2";  // a scene name from assets/scenes, or a .json path
  int frames = 120;              // bench: frames to time
  int warmup = 10;               // bench: frames not timed
  int cubeSize = 256;
  bool cubeSizeSet = false;  // otherwise the scene's capture.faceSize
  float yawDeg = 0.0f;
  float pitchDeg = 0.0f;
  // Capture planning. `policySet`: bench times just this policy instead of comparing them all.
  PlannerSettings planner;
  AccuracySettings accuracy;
  bool policySet = false;
  int accuracyFrames = 60;
  bool growth = false;       // bench: frame time against reflectors and triangles
  bool sweep = false;        // bench: accuracy settings against the ray-traced reference
  std::string referenceOut;  // render: also write the ray-traced reference of the same frame
  std::string csv;           // sweep: CSV output
  std::string svg;           // sweep: SVG plot output
};

Result<CliOptions> parseCli(const std::vector<std::string>& args);
const char* cliHelp();

}  // namespace reflect
