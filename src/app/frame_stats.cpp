#include "app/frame_stats.h"

#include <cstdio>

namespace reflect {

std::string FrameStats::toJson() const {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "{\"frameMs\":%.4f,\"captureMs\":%.4f,\"timing\":\"%s\",\"drawCalls\":%d,"
                "\"triangles\":%zu,\"facesCaptured\":%d,\"cubeFaceSize\":%d,\"time\":%.6f,"
                "\"orbitDegrees\":%.6f}",
                frameMs, captureMs, timing, drawCalls, triangles, facesCaptured, cubeFaceSize,
                timeSeconds, orbitDegrees);
  return buffer;
}

}  // namespace reflect
