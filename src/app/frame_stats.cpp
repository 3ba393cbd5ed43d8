#include "app/frame_stats.h"

#include <cstdio>

namespace reflect {

std::string jsonQuote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string FrameStats::toJson() const {
  char buffer[768];
  std::snprintf(buffer, sizeof buffer,
                "{\"frameMs\":%.4f,\"captureMs\":%.4f,\"timing\":\"%s\",\"gpuFrameMs\":%.4f,"
                "\"gpuCaptureMs\":%.4f,\"policy\":\"%s\","
                "\"probes\":%d,\"facesCaptured\":%d,\"drawCalls\":%d,\"triangles\":%zu,"
                "\"captureDrawCalls\":%d,\"captureTriangles\":%zu,\"mainDrawCalls\":%d,"
                "\"mainTriangles\":%zu,\"cubeFaceSize\":%d,\"width\":%d,\"height\":%d,"
                "\"time\":%.6f,\"orbitDegrees\":%.6f}",
                frameMs, captureMs, timing, gpuFrameMs, gpuCaptureMs, policy, probes, facesCaptured,
                drawCalls(), triangles(), captureDrawCalls, captureTriangles, mainDrawCalls,
                mainTriangles, cubeFaceSize, width, height, timeSeconds, orbitDegrees);
  std::string json = buffer;
  if (!error.empty()) json.insert(json.size() - 1, ",\"error\":" + jsonQuote(error));
  return json;
}

}  // namespace reflect
