#include "reference/reference_noise.h"

#include <algorithm>
#include <cmath>

namespace reflect {

bool hasRoughMirror(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const SceneObject& o) { return o.rough(); });
}

Result<ReferenceNoise> referenceNoise(const ReferenceFrame& a, const ReferenceFrame& b) {
  using Out = Result<ReferenceNoise>;
  if (a.image.width != b.image.width || a.image.height != b.image.height ||
      a.reflectorMask != b.reflectorMask) {
    return Out::failure("reference noise: the two renderings are not of the same frame");
  }
  if (a.options.lobeSamples != b.options.lobeSamples || a.options.seed == b.options.seed) {
    return Out::failure(
        "reference noise: the two renderings need the same lobe samples and different seeds");
  }
  auto difference = imageErrorMetrics(a.image, b.image, a.reflectorMask);
  if (!difference) return Out::failure(difference.error());
  ReferenceNoise noise;
  noise.difference = difference.value();
  noise.lobeSamples = a.options.lobeSamples;
  noise.psnrDb = std::min(difference.value().psnrDb + 10.0 * std::log10(2.0), kPsnrCapDb);
  return noise;
}

Result<ReferenceNoise> measureReferenceNoise(const Scene& scene, const MeshLookup& meshes,
                                             const CubeFaces* skybox, const LookCamera& camera,
                                             double seconds, int width, int height,
                                             const ReferenceOptions& options) {
  ReferenceOptions other = options;
  other.seed = options.seed + 1;
  auto a = renderReference(scene, meshes, skybox, camera, seconds, width, height, options);
  if (!a) return Result<ReferenceNoise>::failure(a.error());
  auto b = renderReference(scene, meshes, skybox, camera, seconds, width, height, other);
  if (!b) return Result<ReferenceNoise>::failure(b.error());
  return referenceNoise(a.value(), b.value());
}

}  // namespace reflect
