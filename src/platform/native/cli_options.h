// The `reflect` command line, parsed into plain values (no GL, so it is unit-tested). CLI11 parses
// it as designed: the subcommands render, bench and help (cli_options.cpp), each command's options
// and help (cli_commands), the settings table's options (cli_settings: a setting added to
// core/settings_schema.h is an option here, named in kebab case, facesPerFrame ->
// --faces-per-frame, checked with the page's messages), what each value must be (cli_validators)
// and how a mistake is worded (cli_failure, CLI11's failure-message hook).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bench/bench_commands.h"
#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/result.h"
#include "core/settings_schema.h"

namespace reflect {

struct CliOptions {
  std::string command;    // "render", "explain", "bench" or "help"
  std::string helpTopic;  // help: "" (every command), "render" or "bench"
  int width = 800;
  int height = 800;
  bool sizeSet = false;                // --size given (the sweep otherwise renders at its own size)
  double time = 0.0;                   // render
  std::string out = "frame.png";       // render
  std::string referenceOut;            // render: also write the ray-traced reference of the frame
  std::string errorViewOut;            // render: also write the error view (heat map) of the frame
  std::string facesOut;                // render: also write the faces view (view.facesChannel)
  std::string faceUseOut;              // render: also write the face-use view
  glm::ivec2 pixel{0};                 // explain: the pixel (x, y), (0, 0) the top-left one
  std::string stepsDir;                // render: also write the frame's steps, one PNG each
  std::string assets;                  // a folder with the course's models, by their file names
  std::string scene = "ex12-2";        // a shipped scene's name, or a .json path
  std::vector<std::string> materials;  // --material INDEX:NAME=VALUE,... (cli_materials.h)
  std::string preset;                  // --preset: a named preset (core/presets.h), or ""
  std::optional<int> cubeSize;         // otherwise the scene's capture.faceSize
  float yawDeg = 0.0f;
  float pitchDeg = 0.0f;
  std::optional<glm::vec3> eye;  // otherwise the scene's camera eye
  PlannerSettings planner;
  AccuracySettings accuracy;
  bool policySet = false;         // bench: time just this policy instead of comparing them all
  std::optional<int> frames;      // bench: otherwise the mode's default
  std::optional<int> warmup;      // bench: otherwise the mode's default
  int accuracyFrames = 60;        // bench: frames compared with every-frame
  bool growth = false;            // bench: frame time against reflectors and triangles
  bool sweep = false;             // bench: accuracy settings against the ray-traced reference
  bool costs = false;             // bench: the planner's cost model's units, measured
  bool lodSweep = false;          // bench: capture LOD values against full detail
  bool viewLodSweep = false;      // bench: view LOD values against the full-detail view
  std::vector<double> times;      // the sweeps: the scene times measured (empty: their own)
  std::vector<std::string> only;  // sweep: just these settings, by name
  std::string csv;                // sweep: CSV output
  std::string svg;                // sweep: SVG plot output
  ViewSettings view;              // bench: the budget (--budget); render: --faces-channel
  bool budgetSet = false;         // bench: pick the most accurate search within view.budget ms

  // render --reference, bench --sweep: the reference's lobe rays a rough pixel (unset: its own
  // default, ReferenceOptions::lobeSamples).
  std::optional<int> lobeSamples;

  // bench: which mode the options select, and the options it takes.
  BenchMode benchMode() const;
  BenchCommandOptions benchOptions() const;
};

// `args` without the program name. Every failure says what was expected, e.g.
// "--cube: 100000 is not in 1..4096", "render: unknown option --bogus".
Result<CliOptions> parseCli(const std::vector<std::string>& args);

// The help text: "" for an overview and every command's options, or one command's.
std::string cliHelp(const std::string& command = "");

}  // namespace reflect
