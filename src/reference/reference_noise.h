// The reference's own noise: where it estimates by Monte Carlo (a rough mirror's lobe), one
// rendering is the truth plus noise, and an error it judges is only meaningful well above that
// noise. Two renderings with independent seeds differ by the difference of two independent
// noises, whose variance is twice one's: one estimate's noise has the difference's PSNR plus
// 10 log10(2) = 3.01 dB. docs/rough.md reports it.
#pragma once

#include "core/error_metrics.h"
#include "core/result.h"
#include "core/scene.h"
#include "reference/reference_renderer.h"

namespace reflect {

struct ReferenceNoise {
  ImageErrorMetrics difference;  // between the two renderings, over the reflector pixels
  double psnrDb = kPsnrCapDb;    // of one rendering's noise over them (difference + 3.01 dB)
  int lobeSamples = 0;           // each rendering's lobe rays a pixel
};

// Whether any object of `scene` is a rough mirror (the reference has noise at all).
bool hasRoughMirror(const Scene& scene);

// The noise of `a` from `b`: the same frame (size, camera, scene, lobe samples) rendered with
// another seed. Fails when they are not.
Result<ReferenceNoise> referenceNoise(const ReferenceFrame& a, const ReferenceFrame& b);

// Renders the frame (renderReference's arguments) with options.seed and options.seed + 1 and
// measures the noise of one of them.
Result<ReferenceNoise> measureReferenceNoise(const Scene& scene, const MeshLookup& meshes,
                                             const CubeFaces* skybox, const LookCamera& camera,
                                             double seconds, int width, int height,
                                             const ReferenceOptions& options = {});

}  // namespace reflect
