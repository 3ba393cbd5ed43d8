// What one frame cost: the numbers behind demo.stats(), the page's stats line and `reflect bench`.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace reflect {

struct FrameStats {
  double frameMs = 0;    // capture + main pass
  double captureMs = 0;  // the planned cube faces (and the rough levels filtered after them)
  // Rough mirrors' filtering, part of captureMs: the prefilter pass's GGX samples taken (texels x
  // samples) and, when the frame waits for the GPU (timing "gpu-finish"), the time of that pass
  // and of the box chains the lobe taps read.
  double filterSamples = 0;
  double filterMs = 0;
  // Probe-lit objects' irradiance, part of captureMs: probes projected, and (timing "gpu-finish")
  // the projection's time.
  int irradianceProjections = 0;
  double irradianceMs = 0;
  // "gpu-finish": times wait for the GPU to finish, so they are what the frame took end to end.
  // "cpu-submit": the display loop does not wait for the GPU; times are command submission only.
  const char* timing = "cpu-submit";
  // From GPU timer queries where the extension exists (a frame or two late); -1 where it does not.
  double gpuFrameMs = -1;
  double gpuCaptureMs = -1;
  const char* policy = "when-changed";
  int probes = 0;            // probes captured (or kept) this frame
  int tracedReflectors = 0;  // reflectors whose rays were traced: no probe, no face
  int facesCaptured = 0;
  bool courseFrame = false;  // drawn by the course's own file (src/course/course_frame.cpp)
  int captureDrawCalls = 0;
  size_t captureTriangles = 0;
  int mainDrawCalls = 0;
  size_t mainTriangles = 0;
  int cubeFaceSize = 0;
  int width = 0;  // the frame's size in pixels (in the page: the WebGL drawing buffer's)
  int height = 0;
  double timeSeconds = 0;
  double orbitDegrees = 0;
  // Every mesh's chunks and (while a LOD setting is on) levels are built and in use.
  bool lodReady = true;
  size_t meshBytes = 0;     // the meshes as the GPU holds them (Demo::meshGpuBytes)
  size_t meshCpuBytes = 0;  // and as the demo keeps them on the CPU (Demo::meshCpuBytes)
  std::string error;        // what went wrong this frame (the page shows it), or empty
  // The live error view (show error): this frame's reflectors against the exact mode's.
  bool errorView = false;
  double errorPsnrDb = 0;        // reflector PSNR (99, the cap, when identical)
  double errorRmse = 0;          // 0..255 over R, G, B
  size_t errorPixelsOver32 = 0;  // reflector pixels off by more than 32 levels
  size_t errorReflectorPixels = 0;
  int errorMax = 0;
  double errorViewMs = 0;  // the exact pass, the comparison and its read-back

  int drawCalls() const { return captureDrawCalls + mainDrawCalls; }
  size_t triangles() const { return captureTriangles + mainTriangles; }
  // The numbers by name (demo.stats() in the page); "error" only when there is one; the error
  // view's as {"errorView": {psnrDb, rmse, pixelsOver32, reflectorPixels, max, ms}} when it is on.
  nlohmann::json toJson() const;
};

}  // namespace reflect
