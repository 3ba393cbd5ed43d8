// Shared set-up for the GL tests: one headless EGL context for the whole run, and a Demo with
// the project's own models.
#pragma once

#include <memory>
#include <string>

#include "app/demo.h"
#include "core/image.h"

namespace reflect::testing {

// A Demo of `scene` with the project's models loaded and its GL resources created.
std::unique_ptr<Demo> makeDemo(Scene scene);
// The same, its mirrors drawn from a captured probe searched by the hierarchical search (the
// default, search: planned, traces them where that is the cheaper): for tests of the capture.
std::unique_ptr<Demo> makeCapturingDemo(Scene scene);
// Writes `image` to the test output folder (for looking at) and returns the path.
std::string saveOutput(const RgbaImage& image, const std::string& fileName);

}  // namespace reflect::testing
