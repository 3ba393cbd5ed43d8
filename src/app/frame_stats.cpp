#include "app/frame_stats.h"

#include <cstdio>

namespace reflect {

std::string FrameStats::toJson() const {
  char buffer[768];
  std::snprintf(buffer, sizeof buffer,
                "{\"frameMs\":%.4f,\"captureMs\":%.4f,\"timing\":\"%s\",\"gpuFrameMs\":%.4f,"
                "\"gpuCaptureMs\":%.4f,\"policy\":\"%s\","
                "\"probes\":%d,\"facesCaptured\":%d,\"drawCalls\":%d,\"triangles\":%zu,"
                "\"captureDrawCalls\":%d,\"captureTriangles\":%zu,\"mainDrawCalls\":%d,"
                "\"mainTriangles\":%zu,\"cubeFaceSize\":%d,\"time\":%.6f,\"orbitDegrees\":%.6f}",
                frameMs, captureMs, timing, gpuFrameMs, gpuCaptureMs, policy, probes, facesCaptured, drawCalls(),
                triangles(), captureDrawCalls, captureTriangles, mainDrawCalls, mainTriangles,
                cubeFaceSize, timeSeconds, orbitDegrees);
  return buffer;
}

}  // namespace reflect
