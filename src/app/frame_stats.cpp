#include "app/frame_stats.h"

namespace reflect {

nlohmann::json FrameStats::toJson() const {
  nlohmann::json json = {{"frameMs", frameMs},
                         {"captureMs", captureMs},
                         {"filterSamples", filterSamples},
                         {"filterMs", filterMs},
                         {"irradianceProjections", irradianceProjections},
                         {"irradianceMs", irradianceMs},
                         {"timing", timing},
                         {"gpuFrameMs", gpuFrameMs},
                         {"gpuCaptureMs", gpuCaptureMs},
                         {"policy", policy},
                         {"probes", probes},
                         {"tracedReflectors", tracedReflectors},
                         {"facesCaptured", facesCaptured},
                         {"courseFrame", courseFrame},
                         {"drawCalls", drawCalls()},
                         {"triangles", triangles()},
                         {"captureDrawCalls", captureDrawCalls},
                         {"captureTriangles", captureTriangles},
                         {"mainDrawCalls", mainDrawCalls},
                         {"mainTriangles", mainTriangles},
                         {"cubeFaceSize", cubeFaceSize},
                         {"width", width},
                         {"height", height},
                         {"time", timeSeconds},
                         {"orbitDegrees", orbitDegrees},
                         {"lodReady", lodReady},
                         {"meshBytes", meshBytes},
                         {"meshCpuBytes", meshCpuBytes}};
  if (!error.empty()) json["error"] = error;
  if (errorView) {
    json["errorView"] = {{"psnrDb", errorPsnrDb},
                         {"rmse", errorRmse},
                         {"pixelsOver32", errorPixelsOver32},
                         {"reflectorPixels", errorReflectorPixels},
                         {"max", errorMax},
                         {"ms", errorViewMs}};
  }
  return json;
}

}  // namespace reflect
