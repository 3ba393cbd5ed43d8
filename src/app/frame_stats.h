// What one frame cost: the numbers behind demo.stats(), the page's stats line and `reflect bench`.
#pragma once

#include <cstddef>
#include <string>

namespace reflect {

struct FrameStats {
  double frameMs = 0;    // capture + main pass
  double captureMs = 0;  // the six cube faces
  // "gpu-finish": times wait for the GPU to finish (a one-pixel read back), so they are what the
  // frame took end to end.
  // "cpu-submit": the rAF loop does not wait for the GPU; times are command submission only.
  const char* timing = "cpu-submit";
  int drawCalls = 0;
  size_t triangles = 0;
  int facesCaptured = 0;
  int cubeFaceSize = 0;
  double timeSeconds = 0;
  double orbitDegrees = 0;

  std::string toJson() const;
};

}  // namespace reflect
