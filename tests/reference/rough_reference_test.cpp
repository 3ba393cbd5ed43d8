// Rough mirrors and frosted glass (docs/rough.md) in the reference, the exact mode and the
// captured probes (lobe taps, and the prefiltered levels), one body for both: rough-spheres (five
// mirror spheres, roughness 0 to 1) and frosted-glass (five glass spheres, index 1.5, roughness 0
// to 1). The reference's Monte Carlo noise, measured with two seeds, lies far below the errors it
// judges; the exact mode's fixed lobe rays come close to it; the captured probes are well above the
// picture that ignores roughness, sphere by sphere. Then, for mirrors, roughness 0 changes nothing,
// in the reference or in the exact mode, against frames the code before rough mirrors made (for
// glass the goldens of the glass scenes, glass-sphere and skybox, drawn by the programs of before,
// hold it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/frame_planner.h"
#include "reference/reference_noise.h"
#include "rough_scenes.h"

namespace reflect {
namespace {

using testing::exactDemo;

// What one rough sphere's prefiltered probe is held to: its PSNR against the reference, and its
// gain over the same sphere drawn with roughness ignored.
struct SphereFloor {
  float roughness;
  double minPsnrDb;
  double minGainDb;
};

// One scene of rough spheres, the size and time its frames are made at, and its floors.
struct RoughCase {
  std::string name;   // the test's: "mirrors" or "glass"
  std::string scene;  // the shipped scene
  int width, height;  // small frames: the spheres cover some 1,400 (mirrors) or 2,000 pixels
  // The reference's noise is held at least this far above the errors it judges (the exact mode's
  // and the picture with roughness ignored).
  double noiseMarginDb;
  double exactMinPsnrDb;  // the exact mode (16 lobe rays) against the reference
  // The spheres of roughness > 0, in scene order: with lobe taps (the default), and from the
  // prefiltered levels (lobeTaps 0).
  std::vector<SphereFloor> tapped;
  std::vector<SphereFloor> spheres;
};

constexpr double kTime = 2.0;
constexpr double kNarrowTracedFloorDb = 39.0;  // RoughNarrowLobe, below
constexpr double kNarrowGainFloorDb = 6.9;
constexpr double kNarrowGlassFloorDb = 38.5;  // RoughNarrowLobe, frosted glass
constexpr double kNarrowGlassGainFloorDb = 4.6;

// rough-spheres at 128x96, t = 2 s, 512 lobe samples: the noise 54.1 dB; against the rough
// reference the mirror with roughness ignored 25.8 dB, the exact mode with 16 lobe rays 36.8 dB
// (its floor some 2 dB below). At this size the spheres' outlines weigh much (the perfect sphere
// itself is 24.5 dB there).
// frosted-glass at 160x120, t = 2 s, 512 lobe samples: the noise 55.6 dB; the glass with
// roughness ignored 26.0 dB and the exact mode 38.0 dB (its floor 2 dB below). The 0.5 sphere has
// sonic just behind it, magnified by the lens: his centre 1.2 from the sphere's, his nearest parts
// inside the near plane of 1 the scene's probes had, which left them out of its capture (23.59 dB
// with lobe taps, 22.12 from the prefiltered levels); the scene's near plane is 0.5 now, inside
// its spheres (radius 0.6).
// The captured spheres (EachSphereAgainstTheReference, which prints them), each held about 0.3 dB
// under its PSNR and its gain over the same sphere with roughness ignored, as measured at those
// sizes (hierarchical search). With lobe taps: mirrors 24.83 dB (gain 0.54), 24.81 (-0.25), 29.75
// (6.59) and 29.77 (6.46) at roughness 0.25, 0.5, 0.75 and 1 with the scene's near plane at 0.5;
// at 1, which cut each neighbour's nearest cap out of the captures, 24.59 (0.47), 24.68 (-0.45),
// 29.60 (6.39) and 29.42 (5.83) (each quarter of the lobe searched,
// a wide lobe's taps checked against the depths, the rough probes captured at 32 texels a face,
// lobeTapFaceSize; at the scene's 128 texels 24.86 (-0.28), 30.02 (6.80) and 29.68 (6.09): the
// floors for 0.5, 0.75 and 1 were lowered by 0.15, 0.4 and 0.3 dB for the smaller faces, which
// cost the frame 0.75x at 512x512 and move the held-out PSNRs by +0.07, +0.04 and -0.48 dB,
// README; with the quarters alone 29.29 (5.70) at 1; with the central ray's distance for every
// tap, before, 24.64 (0.52), 24.80 (-0.33), 29.73 (6.51) and 30.12 (6.53)); glass 35.73
// (2.12), 29.28 (7.70), 31.13 (6.31) and 35.17 (9.92) with one distance for the light through;
// with its quarters searched, 35.61 (2.00), 30.37 (8.79), 31.20 (6.38) and 35.15 (9.91), the
// floor at 0.25 0.1 dB lower for them (near plane 1, one distance: 34.31 (1.74), 23.59 (6.27),
// 31.08 (6.44) and 35.70 (10.50); the floor at 1 is 0.55 dB lower for the nearer plane). At this
// size and in this first frame the mirrors' taps measure under the prefiltered levels, and the 0.5
// mirror under the same sphere drawn sharp (why is not established: every tap read at level 0
// measured 24.52 / 27.58 / 30.66 / 31.87 here, where at 512x512 it lost 1.6 to 5 dB). At 512x512
// over held-out times the taps are 0.4 to 6.4 dB over the prefiltered levels (README, "Rough
// mirrors"); these floors hold what this frame reaches. From the prefiltered levels: mirrors 25.41
// dB (gain 1.13), 26.39 (1.33), 30.78 (7.62) and 30.72 (7.41) (near plane 1: 25.17 (1.05), 26.38
// (1.24), 30.77 (7.56), 30.72 (7.13)); glass 33.70 (0.10), 29.73 (8.14), 30.36 (5.54) and 29.57
// (4.33) (near plane 1: 33.77 (1.20), 22.12 (4.80), 30.41 (5.77), 29.57 (4.37); the 0.25 sphere's
// gain floor went from 0.9 to -0.2 dB because the sphere drawn sharp gained 1 dB from the nearer
// plane and its prefiltered levels did not).
const std::vector<RoughCase> kCases = {
    {"mirrors",
     "rough-spheres",
     128,
     96,
     10.0,
     34.5,
     {{0.25f, 24.5, 0.25}, {0.5f, 24.5, -0.55}, {0.75f, 29.45, 6.3}, {1.0f, 29.45, 6.15}},
     {{0.25f, 25.1, 0.85}, {0.5f, 26.1, 1.05}, {0.75f, 30.45, 7.3}, {1.0f, 30.4, 7.1}}},
    {"glass",
     "frosted-glass",
     160,
     120,
     10.0,
     36.0,
     {{0.25f, 35.3, 1.7}, {0.5f, 30.05, 8.45}, {0.75f, 30.9, 6.05}, {1.0f, 34.85, 9.6}},
     {{0.25f, 33.4, -0.2}, {0.5f, 29.4, 7.8}, {0.75f, 30.05, 5.25}, {1.0f, 29.25, 4.05}}},
};

// Test names and failures show the case, not the struct's bytes.
void PrintTo(const RoughCase& c, std::ostream* out) {
  *out << c.name;
}

ReferenceFrame referenceWithSeed(const Demo& demo, const RoughCase& c, uint32_t seed,
                                 int lobeSamples = ReferenceOptions{}.lobeSamples) {
  return testing::referenceWithSeed(demo, {kTime, c.width, c.height}, seed, lobeSamples);
}

// The case's reference of seed 1, made once for the tests below (each is seconds of tracing).
const ReferenceFrame& reference(const RoughCase& c) {
  static std::map<std::string, ReferenceFrame> frames;
  auto it = frames.find(c.name);
  if (it == frames.end()) {
    auto demo = testing::makeDemo(testing::shippedScene(c.scene));
    it = frames.emplace(c.name, referenceWithSeed(*demo, c, 1)).first;
  }
  return it->second;
}

// The same spheres with roughness ignored, drawn by the exact mode or from captured probes,
// against the rough reference.
AccuracyReport roughnessIgnored(const RoughCase& c, bool capturing) {
  const Scene sharp = testing::shippedScene(c.scene, true);
  auto demo = capturing ? testing::makeCapturingDemo(sharp) : exactDemo(sharp);
  auto image = renderFrameAt(*demo, kTime, c.width, c.height);
  EXPECT_TRUE(image) << image.error();
  auto report = compareWithReference(image ? image.take() : RgbaImage{}, reference(c));
  EXPECT_TRUE(report) << report.error();
  return report ? report.take() : AccuracyReport{};
}

class RoughLobe : public ::testing::TestWithParam<RoughCase> {};

TEST_P(RoughLobe, NoiseIsFarBelowTheErrorsItJudges) {
  const RoughCase& c = GetParam();
  auto demo = exactDemo(testing::shippedScene(c.scene));
  const ReferenceFrame second = referenceWithSeed(*demo, c, 2);
  auto noise = referenceNoise(reference(c), second);
  ASSERT_TRUE(noise) << noise.error();
  ASSERT_GT(noise.value().difference.pixelCount, 1000u);
  const double ignored = roughnessIgnored(c, false).reflector.psnrDb;
  auto exact = measureAccuracy(*demo, kTime, c.width, c.height, &reference(c));
  ASSERT_TRUE(exact) << exact.error();
  const double traced = exact.value().reflector.psnrDb;
  std::printf(
      "%s %dx%d: reference noise %.2f dB (difference of two seeds %.2f dB); roughness ignored "
      "%.2f dB, the exact mode (16 lobe rays) %.2f dB against it\n",
      c.scene.c_str(), c.width, c.height, noise.value().psnrDb, noise.value().difference.psnrDb,
      ignored, traced);
  EXPECT_GE(noise.value().psnrDb, ignored + c.noiseMarginDb);
  EXPECT_GE(noise.value().psnrDb, traced + c.noiseMarginDb);
}

TEST_P(RoughLobe, ExactModeLobeRaysMatchTheReference) {
  const RoughCase& c = GetParam();
  auto demo = exactDemo(testing::shippedScene(c.scene));
  auto report = measureAccuracy(*demo, kTime, c.width, c.height, &reference(c));
  ASSERT_TRUE(report) << report.error();
  std::string file = c.scene + "_reference.png";
  std::replace(file.begin(), file.end(), '-', '_');
  testing::saveOutput(report.value().referenceImage, file);
  std::printf("%s %dx%d: the exact mode's reflector PSNR %.2f dB (max %d)\n", c.scene.c_str(),
              c.width, c.height, report.value().reflector.psnrDb,
              report.value().reflector.maxPixelError);
  EXPECT_GE(report.value().reflector.psnrDb, c.exactMinPsnrDb);
}

// The captured probes (searched, as the default does where it captures), each rough sphere on its
// own pixels against the reference, and its gain over the same sphere drawn with roughness
// ignored; `lobeTaps` 0 reads the prefiltered levels. Issue 35's target is 36 dB at every
// roughness from 0.25 (README, "Rough mirrors"): these hold what each reaches at this size.
void eachSphereAgainstTheReference(const RoughCase& c, int lobeTaps,
                                   const std::vector<SphereFloor>& floors) {
  auto demo = testing::makeCapturingDemo(testing::shippedScene(c.scene));
  AccuracySettings settings = demo->accuracySettings();
  settings.lobeTaps = lobeTaps;
  ASSERT_EQ(demo->setAccuracySettings(settings), "");
  auto captured = measureAccuracy(*demo, kTime, c.width, c.height, &reference(c));
  ASSERT_TRUE(captured) << captured.error();
  const AccuracyReport ignored = roughnessIgnored(c, true);
  const Scene scene = testing::shippedScene(c.scene);
  ASSERT_EQ(captured.value().perReflector.size(), 5u);
  ASSERT_EQ(ignored.perReflector.size(), 5u);
  const char* how = lobeTaps > 0 ? "lobe taps" : "prefiltered";
  size_t rough = 0;
  for (size_t i = 0; i < 5; ++i) {
    const auto& [object, metrics] = captured.value().perReflector[i];
    const double without = ignored.perReflector[i].second.psnrDb;
    const float roughness = scene.objects[static_cast<size_t>(object)].roughness;
    std::printf("%s, roughness %.2f: %s %.2f dB, roughness ignored %.2f dB, gain %.2f dB\n",
                c.name.c_str(), roughness, how, metrics.psnrDb, without, metrics.psnrDb - without);
    if (roughness == 0.0f) continue;
    ASSERT_LT(rough, floors.size()) << "roughness " << roughness;
    const SphereFloor& floor = floors[rough++];
    ASSERT_EQ(roughness, floor.roughness);
    EXPECT_GE(metrics.psnrDb, floor.minPsnrDb) << how << ", roughness " << roughness;
    EXPECT_GE(metrics.psnrDb - without, floor.minGainDb) << how << ", roughness " << roughness;
  }
  EXPECT_EQ(rough, floors.size());
}

TEST_P(RoughLobe, LobeTapsEachSphereAgainstTheReference) {
  const RoughCase& c = GetParam();
  eachSphereAgainstTheReference(c, AccuracySettings{}.lobeTaps, c.tapped);
}

TEST_P(RoughLobe, PrefilteredEachSphereAgainstTheReference) {
  const RoughCase& c = GetParam();
  eachSphereAgainstTheReference(c, 0, c.spheres);
}

// The default (search: planned) traces the 0.25 mirror, a lobe too narrow for taps, with
// narrowLobeRays rays where the weighing would capture it: that sphere on its own pixels against
// the reference, and against the same frame with narrowLobeRays 0 (its taps). At 128x96 the
// weighing traces every sphere (a small frame), so this frame is larger, and it is the second
// frame (defaultSpheres). Measured at 320x240, t = 2 s: 39.28 dB traced, 32.07 dB with taps (a
// gain of 7.21 dB); the floors hold them about 0.3 dB under. With the scene's near plane at 1,
// which left each neighbour's nearest cap out of the captures, the taps were at 30.65 dB and the
// gain 8.63: the gain's floor went from 8.3 to 6.9 because the taps it is measured over gained.
// (Measured in a first frame, where the neighbours in the captures had no captures of their own,
// the taps were at 24.57 dB.)
// The spheres it captures take lobe taps, each quarter of the lobe searched for its own distance
// (docs/rough.md, "Lobe taps"), a wide lobe's taps (roughness 1, and 0.75 a little) checked
// against the probe's depths, captured at 32 texels a face (lobeTapFaceSize): in the same frame
// 39.03, 41.17 and 39.89 dB at roughness 0.5, 0.75 and 1, and 36.88 at 0.5 with one lobe
// distance. With the near plane at 1: 38.21, 40.96 and 39.14, one distance 36.19; before the
// smaller faces, at the scene's 128 texels: 37.84, 41.38 and 39.71; the quarters without the
// check: 37.84, 41.34 and 38.28; with the central ray's distance for every tap, lobeQuarters
// false, the default before: 35.86, 39.96 and 37.01. The floors hold them, and the gain at 0.5,
// about 0.3 dB under.
constexpr int kNarrowWidth = 320;
constexpr int kNarrowHeight = 240;
const std::map<float, double> kDefaultFloorsDb = {{0.5f, 38.7}, {0.75f, 40.85}, {1.0f, 39.6}};
constexpr double kQuartersGainFloorDb = 1.85;  // at roughness 0.5: 39.03 against 36.88 dB

// Each rough sphere's PSNR in the default's frame of `sceneName` (rough-spheres unless said) at
// 320x240, with `narrowLobeRays` and `lobeQuarters`.
std::map<float, double> defaultSpheres(int narrowLobeRays, bool lobeQuarters = true,
                                       const std::string& sceneName = "rough-spheres") {
  static std::map<std::string, std::pair<Scene, ReferenceFrame>> cases;
  auto found = cases.find(sceneName);
  if (found == cases.end()) {
    Scene shipped = testing::shippedScene(sceneName);
    auto exact = exactDemo(shipped);
    ReferenceFrame frame = testing::referenceWithSeed(*exact, {kTime, kNarrowWidth, kNarrowHeight},
                                                      1, ReferenceOptions{}.lobeSamples);
    found = cases.emplace(sceneName, std::make_pair(std::move(shipped), std::move(frame))).first;
  }
  const Scene& scene = found->second.first;
  const ReferenceFrame& reference = found->second.second;
  auto demo = testing::makeDemo(scene);
  AccuracySettings settings = demo->accuracySettings();
  EXPECT_EQ(settings.search, Search::Planned);
  settings.narrowLobeRays = narrowLobeRays;
  settings.lobeQuarters = lobeQuarters;
  EXPECT_EQ(demo->setAccuracySettings(settings), "");
  // A frame first, as the sweep's timed frames do: the spheres' captures show each other, and in
  // a first frame the neighbours they show have no captures of their own yet.
  EXPECT_TRUE(renderFrameAt(*demo, kTime, kNarrowWidth, kNarrowHeight));
  auto report = measureAccuracy(*demo, kTime, kNarrowWidth, kNarrowHeight, &reference);
  EXPECT_TRUE(report) << report.error();
  std::map<float, double> spheres;
  if (!report) return spheres;
  for (const auto& [object, metrics] : report.value().perReflector) {
    const float roughness = scene.objects[static_cast<size_t>(object)].roughness;
    if (roughness == 0.25f) {
      const SceneObject::Look look = scene.objects[static_cast<size_t>(object)].look();
      EXPECT_EQ(demo->lastPlan().traces(object), narrowLobeRays > 0);
      EXPECT_EQ(demo->lastPlan().lobeRaysOf(object),
                narrowLobeRays > 0 ? narrowLobeRaysOf(look, settings) : 0);
    } else if (roughness > 0.0f) {
      EXPECT_FALSE(demo->lastPlan().traces(object)) << "roughness " << roughness;
    }
    spheres[roughness] = metrics.psnrDb;
  }
  return spheres;
}

TEST(RoughNarrowLobe, TheDefaultTracesTheNarrowLobeAndGainsOverItsTaps) {
  const double traced = defaultSpheres(AccuracySettings{}.narrowLobeRays)[0.25f];
  const double tapped = defaultSpheres(0)[0.25f];
  std::printf(
      "rough-spheres %dx%d, roughness 0.25: traced with %d lobe rays %.2f dB, taps %.2f dB\n",
      kNarrowWidth, kNarrowHeight, AccuracySettings{}.narrowLobeRays, traced, tapped);
  EXPECT_GE(traced, kNarrowTracedFloorDb);
  EXPECT_GE(traced - tapped, kNarrowGainFloorDb);
}

// Frosted glass's 0.25 sphere is traced for its narrow lobe too, with half the rays for each of
// its lobes (narrowLobeRaysOf): its light through, which the lens turns into a few sharp copies
// of what lies behind when read by taps. The other spheres are captured as before: the traced
// one, seen in their captures, traces one ray each way through the Phong objects. Measured at
// 320x240, t = 2 s: 38.79 dB traced with 4 rays a lobe, 33.85 dB with taps (a gain of 4.94 dB);
// the floors hold them about 0.3 dB under. The others: 30.83 / 36.26 / 34.87 dB at 0.5 / 0.75 / 1
// against 30.81 / 35.95 / 34.87 with the 0.25 sphere captured and tapped.
TEST(RoughNarrowLobe, NarrowFrostedGlassIsTracedAndGainsOverItsTaps) {
  const int rays = AccuracySettings{}.narrowLobeRays;
  const std::map<float, double> traced = defaultSpheres(rays, true, "frosted-glass");
  const std::map<float, double> tapped = defaultSpheres(0, true, "frosted-glass");
  for (const auto& [roughness, db] : traced) {
    std::printf("frosted-glass %dx%d, roughness %.2f: the default %.2f dB, taps only %.2f dB\n",
                kNarrowWidth, kNarrowHeight, roughness, db, tapped.at(roughness));
  }
  EXPECT_GE(traced.at(0.25f), kNarrowGlassFloorDb);
  EXPECT_GE(traced.at(0.25f) - tapped.at(0.25f), kNarrowGlassGainFloorDb);
  // The spheres still captured lose nothing to the traced one in their captures.
  for (float roughness : {0.5f, 0.75f, 1.0f}) {
    EXPECT_GE(traced.at(roughness), tapped.at(roughness) - 0.1) << "roughness " << roughness;
  }
}

TEST(RoughDefault, TheCapturedRoughMirrorsHoldTheirFloors) {
  const std::map<float, double> spheres = defaultSpheres(AccuracySettings{}.narrowLobeRays);
  std::map<float, double> oneDistance = defaultSpheres(AccuracySettings{}.narrowLobeRays, false);
  for (const auto& [roughness, floor] : kDefaultFloorsDb) {
    ASSERT_EQ(spheres.count(roughness), 1u) << "roughness " << roughness;
    std::printf(
        "rough-spheres %dx%d, roughness %.2f: the default %.2f dB, one lobe distance %.2f\n",
        kNarrowWidth, kNarrowHeight, roughness, spheres.at(roughness), oneDistance[roughness]);
    EXPECT_GE(spheres.at(roughness), floor) << "roughness " << roughness;
  }
  // The quarters' gain where the target was missed without them.
  EXPECT_GE(spheres.at(0.5f) - oneDistance[0.5f], kQuartersGainFloorDb);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, RoughLobe, ::testing::ValuesIn(kCases),
                         [](const auto& param) { return param.param.name; });

// The mirrors' own: roughness 0 is the perfect mirror of before, and the lobe samples reach the
// tracer.
constexpr int kWidth = 128;
constexpr int kHeight = 96;

Scene roughSpheres(bool roughnessZero = false) {
  return testing::shippedScene("rough-spheres", roughnessZero);
}

ReferenceFrame referenceWithSeed(const Demo& demo, uint32_t seed,
                                 int lobeSamples = ReferenceOptions{}.lobeSamples) {
  return testing::referenceWithSeed(demo, {kTime, kWidth, kHeight}, seed, lobeSamples);
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
