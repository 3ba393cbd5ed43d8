// Rough mirrors (docs/rough.md) in the reference and in the exact mode, on rough-spheres (five
// mirror spheres, roughness 0 to 1): the reference's Monte Carlo noise, measured with two seeds,
// lies far below the errors it judges; the exact mode's fixed lobe rays come close to it; and
// roughness 0 changes nothing, in either, against frames the code before rough mirrors made.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "reference/reference_noise.h"
#include "rough_scenes.h"

namespace reflect {
namespace {

// Small frames: the five spheres cover some 1,400 pixels at 128x96, time 2 s.
constexpr int kWidth = 128;
constexpr int kHeight = 96;
constexpr double kTime = 2.0;
constexpr double kExactMinPsnr = 34.5;
// Measured at 128x96 (RoughPrefiltered below): the rough spheres 25.17, 26.38, 30.77 and
// 30.72 dB prefiltered, 1.0 to 7.6 dB above the same spheres drawn sharp; at this size their
// outlines weigh much (the perfect sphere itself is 24.5 dB there). Floors about 1 dB and half
// the smallest gain below.
constexpr double kPrefilteredMinPsnr = 24.0;
constexpr double kPrefilterGain = 0.5;

using testing::exactDemo;

Scene roughSpheres(bool roughnessZero = false) {
  return testing::shippedScene("rough-spheres", roughnessZero);
}

ReferenceFrame referenceWithSeed(const Demo& demo, uint32_t seed,
                                 int lobeSamples = ReferenceOptions{}.lobeSamples) {
  return testing::referenceWithSeed(demo, {kTime, kWidth, kHeight}, seed, lobeSamples);
}

double reflectorPsnr(const RgbaImage& image, const ReferenceFrame& reference) {
  auto metrics = imageErrorMetrics(image, reference.image, reference.reflectorMask);
  EXPECT_TRUE(metrics) << metrics.error();
  return metrics ? metrics.value().psnrDb : 0.0;
}

// Measured at 128x96, t = 2 s, 512 lobe samples: the noise 54.1 dB; against the rough reference
// the perfect mirror 25.8 dB, the exact mode with 16 lobe rays 36.8 dB. Both margins asserted are
// 10 dB (28 and 17 measured).
TEST(RoughReference, NoiseIsFarBelowTheErrorsItJudges) {
  auto demo = exactDemo(roughSpheres());
  const ReferenceFrame first = referenceWithSeed(*demo, 1);
  const ReferenceFrame second = referenceWithSeed(*demo, 2);
  auto noise = referenceNoise(first, second);
  ASSERT_TRUE(noise) << noise.error();
  ASSERT_GT(noise.value().difference.pixelCount, 1000u);
  // The perfect mirror (roughness ignored, as before rough mirrors) against the rough truth.
  auto plainDemo = testing::makeDemo(roughSpheres(true));
  const double plain = reflectorPsnr(referenceWithSeed(*plainDemo, 1).image, first);
  auto exact = measureAccuracy(*demo, kTime, kWidth, kHeight, &first);
  ASSERT_TRUE(exact) << exact.error();
  const double traced = exact.value().reflector.psnrDb;
  std::printf(
      "rough-spheres %dx%d: reference noise %.2f dB (difference of two seeds %.2f dB); the "
      "perfect mirror %.2f dB, the exact mode (16 lobe rays) %.2f dB against it\n",
      kWidth, kHeight, noise.value().psnrDb, noise.value().difference.psnrDb, plain, traced);
  EXPECT_GE(noise.value().psnrDb, plain + 10.0);
  EXPECT_GE(noise.value().psnrDb, traced + 10.0);
}

// Measured at 128x96, t = 2 s: 36.8 dB with 16 lobe rays (the perfect mirror: 25.8 dB); the
// threshold is some 2 dB below it.
TEST(RoughExactMode, LobeRaysMatchTheReference) {
  auto demo = exactDemo(roughSpheres());
  const ReferenceFrame reference = referenceWithSeed(*demo, 1);
  auto report = measureAccuracy(*demo, kTime, kWidth, kHeight, &reference);
  ASSERT_TRUE(report) << report.error();
  testing::saveOutput(report.value().referenceImage, "rough_spheres_reference.png");
  std::printf("rough-spheres %dx%d: the exact mode's reflector PSNR %.2f dB (max %d)\n", kWidth,
              kHeight, report.value().reflector.psnrDb, report.value().reflector.maxPixelError);
  EXPECT_GE(report.value().reflector.psnrDb, kExactMinPsnr);
}

// The prefiltered probes (captured and searched, as the default does where it captures), each
// rough sphere on its own pixels against the reference: issue 24's target is 35 dB at roughness
// 0.3 and above, which the prefilter misses (README, "Rough mirrors"); this holds what it reaches,
// and that it is well above the perfect mirror's picture of the same spheres (roughness ignored).
TEST(RoughPrefiltered, EachRoughSphereAgainstTheReference) {
  auto rough = testing::makeCapturingDemo(roughSpheres());
  const ReferenceFrame reference = referenceWithSeed(*rough, 1);
  auto prefiltered = measureAccuracy(*rough, kTime, kWidth, kHeight, &reference);
  ASSERT_TRUE(prefiltered) << prefiltered.error();
  auto sharp = testing::makeCapturingDemo(roughSpheres(true));
  auto image = renderFrameAt(*sharp, kTime, kWidth, kHeight);
  ASSERT_TRUE(image) << image.error();
  auto ignored = compareWithReference(image.value(), reference);
  ASSERT_TRUE(ignored) << ignored.error();
  const Scene scene = roughSpheres();
  ASSERT_EQ(prefiltered.value().perReflector.size(), 5u);
  for (size_t i = 0; i < 5; ++i) {
    const auto& [object, metrics] = prefiltered.value().perReflector[i];
    const double without = ignored.value().perReflector[i].second.psnrDb;
    const float roughness = scene.objects[static_cast<size_t>(object)].roughness;
    std::printf("roughness %.2f: prefiltered %.2f dB, roughness ignored %.2f dB\n", roughness,
                metrics.psnrDb, without);
    if (roughness == 0.0f) continue;
    EXPECT_GE(metrics.psnrDb, kPrefilteredMinPsnr) << "roughness " << roughness;
    EXPECT_GE(metrics.psnrDb, without + kPrefilterGain) << "roughness " << roughness;
  }
}

// tests/golden/rough_spheres_roughness0_*.png: rough-spheres at 128x96, t = 2 s, rendered by
// `reflect render --search exact --reference` built from the commit before rough mirrors were
// traced (c0617fa), which ignored roughness. Roughness 0 takes the same code (no lobe, no random
// point), so the pixels are the same, whatever the seed and the lobe samples.
RgbaImage golden(const std::string& name) {
  auto image = readPng(std::string(GOLDEN_DIR) + "/rough_spheres_roughness0_" + name + ".png");
  EXPECT_TRUE(image) << image.error();
  return image ? image.take() : RgbaImage{};
}

TEST(RoughReference, RoughnessZeroIsThePerfectMirrorOfBefore) {
  auto demo = exactDemo(roughSpheres(true));
  const ReferenceFrame reference = referenceWithSeed(*demo, 1);
  EXPECT_EQ(reference.image.pixels, referenceWithSeed(*demo, 7, 1).image.pixels);
  EXPECT_EQ(reference.image.pixels, golden("reference").pixels);
}

// ReferenceOptions::lobeSamples (reflect's --lobe-samples) reaches the tracer: 16 lobe rays
// instead of 512 change the rough spheres' pixels and nothing that is not a reflector.
TEST(RoughReference, LobeSamplesReachTheTracer) {
  const Scene scene = roughSpheres();
  auto demo = exactDemo(scene);
  const ReferenceFrame many = referenceWithSeed(*demo, 1);
  const ReferenceFrame few = referenceWithSeed(*demo, 1, 16);
  EXPECT_EQ(few.options.lobeSamples, 16);
  int roughPixels = 0, roughChanged = 0, plainChanged = 0;
  for (size_t p = 0; p < many.objectIds.size(); ++p) {
    const int id = many.objectIds[p];
    const bool changed =
        !std::equal(many.image.pixels.begin() + 4 * p, many.image.pixels.begin() + 4 * p + 4,
                    few.image.pixels.begin() + 4 * p);
    if (!many.reflectorMask[p]) {
      plainChanged += changed ? 1 : 0;
    } else if (id >= 0 && scene.objects[static_cast<size_t>(id)].roughness > 0.0f) {
      ++roughPixels;
      roughChanged += changed ? 1 : 0;
    }
  }
  std::printf("rough pixels %d, changed by 16 lobe samples %d\n", roughPixels, roughChanged);
  EXPECT_GT(roughPixels, 500);
  EXPECT_GT(roughChanged, roughPixels / 2);
  EXPECT_EQ(plainChanged, 0);
}

TEST(RoughExactMode, RoughnessZeroIsThePerfectMirrorOfBefore) {
  auto demo = exactDemo(roughSpheres(true));
  auto frame = renderFrameAt(*demo, kTime, kWidth, kHeight);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(frame.value().pixels, golden("exact").pixels);
}

}  // namespace
}  // namespace reflect
