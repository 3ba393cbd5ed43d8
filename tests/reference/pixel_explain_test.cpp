// Pick a pixel (app/pixel_explain.h) against independent answers: the exact hit it reports is
// Embree's first hit for the same ray; the course's lookup at the sphere's centre pixel is the
// analytic reflection off a true sphere; the frame colour it reports is the frame's own pixel;
// pixels with nothing to explain say so in words.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "app/headless_frames.h"
#include "app/pixel_explain.h"
#include "app/text_line.h"
#include "core/reference_shading.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"
#include "reference/ray_query.h"

namespace reflect {
namespace {

constexpr int kSize = 400;

// Pixels of the default scene's mirror sphere at 400 x 400 (reflect render --size 400x400
// --search hierarchical), at t = 0: its reflections of mario, the floor, sonic, the sky (twice) and
// the floor (twice more); at t = 2 (sonic has moved in front of the first pixel, which is left out)
// the figures have moved on: three of the rest reflect the sky, three the floor.
struct TimedPixel {
  double seconds;
  glm::ivec2 pixel;
};
constexpr TimedPixel kMirrorPixels[] = {
    {0.0, {233, 240}}, {0.0, {200, 260}}, {0.0, {174, 232}}, {0.0, {200, 200}}, {0.0, {170, 215}},
    {0.0, {215, 262}}, {0.0, {185, 262}}, {2.0, {200, 260}}, {2.0, {174, 232}}, {2.0, {200, 200}},
    {2.0, {170, 215}}, {2.0, {215, 262}}, {2.0, {185, 262}}};
// Pixels of the glass sphere (glass-sphere.json), through its middle, above it and near its foot.
constexpr glm::ivec2 kGlassPixels[] = {{200, 210}, {190, 200}, {215, 262}, {185, 262}};

// Hit points agree to 1e-3 world units (the scene is 10 units across; both are single-precision
// traces of the same triangles, started 1e-4 off the surface).
constexpr float kHitTolerance = 1e-3f;

Result<PixelExplanation> explainAt(Demo& demo, double seconds, glm::ivec2 pixel) {
  const Result<RgbaImage> frame = renderFrameAt(demo, seconds, kSize, kSize);
  EXPECT_TRUE(frame) << frame.error();
  return explainPixel(demo, pixel.x, pixel.y, kSize, kSize);
}

// Embree's first hit along the explanation's lookup ray against every object of the scene.
void expectEmbreeAgrees(const Demo& demo, const PixelExplanation& e) {
  ASSERT_EQ(e.message, "") << "pixel " << e.x << "," << e.y;
  const MeshLookup meshes = [&demo](const std::string& name) { return demo.meshLevel(name, 0); };
  const QueryRay ray{e.lookupRay.origin, e.lookupRay.direction, 1e-4f};
  auto hits = embreeFirstHits(demo.scene(), meshes, e.seconds, {ray});
  ASSERT_TRUE(hits) << hits.error();
  const QueryHit& theirs = hits.value()[0];
  std::printf(
      "t=%.1f pixel %d,%d: explained object %d at (%.4f %.4f %.4f), Embree object %d t %g\n",
      e.seconds, e.x, e.y, e.exactObject, e.exactHit.x, e.exactHit.y, e.exactHit.z, theirs.object,
      theirs.t);
  EXPECT_EQ(e.exactObject, theirs.object) << "pixel " << e.x << "," << e.y;
  if (theirs.object < 0 || e.exactObject != theirs.object) return;
  const glm::vec3 embreeHit = ray.origin + theirs.t * ray.direction;
  EXPECT_LT(glm::length(e.exactHit - embreeHit), kHitTolerance) << "pixel " << e.x << "," << e.y;
}

TEST(PixelExplain, TheExactHitIsEmbreesFirstHitOffTheMirror) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  int metSomething = 0;
  for (const TimedPixel& at : kMirrorPixels) {
    Result<PixelExplanation> e = explainAt(*demo, at.seconds, at.pixel);
    ASSERT_TRUE(e) << e.error();
    EXPECT_EQ(e.value().material, Material::Mirror);
    expectEmbreeAgrees(*demo, e.value());
    metSomething += e.value().exactObject >= 0 ? 1 : 0;
  }
  // Not every ray may miss: 5 rays at t = 0 and 3 at t = 2 meet the floor or a figure.
  EXPECT_EQ(metSomething, 8);
}

TEST(PixelExplain, TheExactHitIsEmbreesFirstHitThroughGlass) {
  Result<Scene> scene = loadNamedScene("glass-sphere");
  ASSERT_TRUE(scene) << scene.error();
  auto demo = testing::makeCapturingDemo(scene.take());
  for (const glm::ivec2& pixel : kGlassPixels) {
    Result<PixelExplanation> e = explainAt(*demo, 2.0, pixel);
    ASSERT_TRUE(e) << e.error();
    EXPECT_EQ(e.value().material, Material::Glass);
    EXPECT_TRUE(e.value().glass.exited) << "pixel " << pixel.x << "," << pixel.y;
    // The ray leaves from the sphere's far side, the other side of its centre from the eye.
    EXPECT_LT(e.value().glass.exitPoint.z, e.value().surfacePoint.z);
    expectEmbreeAgrees(*demo, e.value());
  }
}

// The sphere's true centre and radius: its mesh's bounds placed by its model.
struct Sphere {
  glm::vec3 centre;
  float radius;
};
Sphere trueSphere(const Demo& demo, int object) {
  const SceneObject& o = demo.scene().objects[static_cast<size_t>(object)];
  const Bounds& b = demo.meshLevel(o.mesh, 0)->bounds;
  const glm::mat4 model = demo.scene().modelMatrix(o, 0.0);
  const glm::vec3 lo(model * glm::vec4(b.min, 1.0f)), hi(model * glm::vec4(b.max, 1.0f));
  return {(lo + hi) * 0.5f, (hi.x - lo.x) * 0.5f};
}

TEST(PixelExplain, TheCourseLookupIsTheAnalyticReflectionAtTheSphereCentrePixel) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const Sphere sphere = trueSphere(*demo, 3);
  const glm::mat4 viewProj = demo->camera().projection(1.0f) * demo->camera().view();
  const glm::vec4 clip = viewProj * glm::vec4(sphere.centre, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const glm::ivec2 pixel(static_cast<int>((ndc.x * 0.5f + 0.5f) * kSize),
                         static_cast<int>((0.5f - ndc.y * 0.5f) * kSize));
  Result<PixelExplanation> e = explainAt(*demo, 0.0, pixel);
  ASSERT_TRUE(e) << e.error();
  ASSERT_EQ(e.value().message, "");
  // The same pixel's ray against the true sphere, in closed form.
  const TraceRay view = *pixelRay(demo->camera(), pixel.x, pixel.y, kSize, kSize);
  const glm::vec3 offset = view.origin - sphere.centre;
  const float b = glm::dot(offset, view.direction);
  const float c = glm::dot(offset, offset) - sphere.radius * sphere.radius;
  const float t = -b - std::sqrt(b * b - c);
  const glm::vec3 hit = view.origin + t * view.direction;
  const glm::vec3 analytic =
      glm::reflect(glm::normalize(hit - demo->camera().eye()), glm::normalize(hit - sphere.centre));
  const double degrees = angleDegrees(e.value().courseDirection, analytic);
  std::printf(
      "sphere centre pixel %d,%d (radius %.3f): course lookup %.3f deg from the analytic "
      "reflection\n",
      pixel.x, pixel.y, sphere.radius, degrees);
  // The mesh is a tessellated sphere: its interpolated normals are off the true sphere's by a
  // fraction of a degree at most (0.011 measured), and its flat facets lie inside the true
  // surface, by 0.0126 here (of a radius of 1.27).
  EXPECT_LT(degrees, 0.5);
  EXPECT_LT(glm::length(e.value().surfacePoint - hit), 0.02f);
}

TEST(PixelExplain, TheFrameColourIsTheFramesOwnPixel) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const Result<RgbaImage> frame = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(frame) << frame.error();
  for (const TimedPixel& at : kMirrorPixels) {
    if (at.seconds != 0.0) continue;
    const glm::ivec2 pixel = at.pixel;
    Result<PixelExplanation> e = explainPixel(*demo, pixel.x, pixel.y, kSize, kSize);
    ASSERT_TRUE(e) << e.error();
    const size_t p = (static_cast<size_t>(pixel.y) * kSize + static_cast<size_t>(pixel.x)) * 4;
    const glm::ivec3 drawn(frame.value().pixels[p], frame.value().pixels[p + 1],
                           frame.value().pixels[p + 2]);
    const glm::ivec3 explained = colourBytes(e.value().frameColour);
    // RGBA8 rounds where the float target keeps the value: at most one level apart.
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(drawn[k] - explained[k]), 1) << pixel.x;
  }
}

TEST(PixelExplain, PixelsWithNothingToExplainSaySoPlainly) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  Result<PixelExplanation> mario = explainAt(*demo, 0.0, {320, 280});
  ASSERT_TRUE(mario) << mario.error();
  EXPECT_EQ(mario.value().object, 2);
  EXPECT_EQ(mario.value().message,
            "object 3 (mario.obj) is phong, not a mirror or glass: it looks nothing up");
  Result<PixelExplanation> sky = explainPixel(*demo, 10, 10, kSize, kSize);
  ASSERT_TRUE(sky) << sky.error();
  EXPECT_EQ(sky.value().message,
            "the view ray meets nothing there: the pixel shows the background");
  Result<PixelExplanation> outside = explainPixel(*demo, kSize, 3, kSize, kSize);
  ASSERT_TRUE(outside) << outside.error();
  EXPECT_TRUE(outside.value().outside);
  EXPECT_EQ(outside.value().message,
            "pixel 400,3 is outside the 400x400 frame (x 0..399, y 0..399)");
  EXPECT_EQ(explanationLines(outside.value()).back(), "  " + outside.value().message);
  // The default search (planned) traces the sphere here: no probe lookup to explain.
  auto traced = testing::makeDemo(makeDynamicReflectionScene());
  Result<PixelExplanation> t = explainAt(*traced, 0.0, {200, 200});
  ASSERT_TRUE(t) << t.error();
  EXPECT_NE(t.value().message.find("traced exactly"), std::string::npos) << t.value().message;
}

// rough-spheres at 400 x 400, t = 2 s: a pixel below the middle of the roughness-0.5 sphere
// (object 6) and one of the perfect sphere (object 4) (reflect explain --scene rough-spheres
// --size 400x400 --time 2 --pixel X,Y).
constexpr glm::ivec2 kHalfRoughPixel{200, 225};
constexpr glm::ivec2 kPerfectPixel{43, 225};
constexpr glm::ivec2 kRoughestPixel{340, 225};  // the roughness-1 sphere (object 7)

std::string joinedLines(const PixelExplanation& e) {
  std::string text;
  for (const std::string& line : explanationLines(e)) text += line + "\n";
  return text;
}

Scene roughSpheres() {
  Result<Scene> scene = loadNamedScene("rough-spheres");
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

// Captured (search: hierarchical): roughness 0.5 samples its lobe with 16 taps from its probe's
// capture, 32 texels a face (the scene's 128 halved while a tap covers 4 texels: lobeTapFaceSize);
// with lobe taps off (the scene's 128 texels) it reads level 0.5 x 5 = 2.5 of its prefiltered
// levels, between level 2 (32 texels) and 3 (16). The rays explained are the lobe's centre.
TEST(PixelExplain, ARoughMirrorNamesItsLobeAndHowItIsRead) {
  auto demo = testing::makeCapturingDemo(roughSpheres());
  Result<PixelExplanation> e = explainAt(*demo, 2.0, kHalfRoughPixel);
  ASSERT_TRUE(e) << e.error();
  ASSERT_EQ(e.value().message, "");
  EXPECT_EQ(e.value().object, 5);
  const LobeExplanation& taps = e.value().lobe;
  EXPECT_EQ(taps.source, LobeExplanation::Source::LobeTaps);
  EXPECT_EQ(taps.lobeTaps, 16);
  EXPECT_EQ(taps.tapFaceSize, 32);
  const std::string tapText = joinedLines(e.value());
  EXPECT_NE(tapText.find("roughness 0.50, GGX alpha 0.2500"), std::string::npos) << tapText;
  EXPECT_NE(tapText.find("16 lobe taps (lobeTaps) around the reflected ray for this view"),
            std::string::npos)
      << tapText;
  EXPECT_NE(tapText.find("probe's capture (32x32 faces, its box chain)"), std::string::npos)
      << tapText;
  EXPECT_TRUE(taps.quartersSearched);
  EXPECT_NE(tapText.find("towards where a search of its quarter of the lobe met the scene"),
            std::string::npos)
      << tapText;
  EXPECT_FALSE(taps.tapsChecked);  // alpha 0.25: not a wide lobe
  EXPECT_EQ(tapText.find("a wide lobe"), std::string::npos) << tapText;

  // The roughness-1 sphere: a wide lobe, whose taps are checked against the depths.
  Result<PixelExplanation> wide = explainAt(*demo, 2.0, kRoughestPixel);
  ASSERT_TRUE(wide) << wide.error();
  EXPECT_EQ(wide.value().object, 7);
  EXPECT_EQ(wide.value().lobe.roughness, 1.0f);
  EXPECT_TRUE(wide.value().lobe.tapsChecked);
  const std::string wideText = joinedLines(wide.value());
  EXPECT_NE(wideText.find("met the scene (a wide lobe: each tap blended towards where the central "
                          "ray met the scene, as far as the probe's depths hold that point "
                          "better)"),
            std::string::npos)
      << wideText;

  AccuracySettings prefiltered = demo->accuracySettings();
  prefiltered.lobeTaps = 0;
  ASSERT_EQ(demo->setAccuracySettings(prefiltered), "");
  e = explainAt(*demo, 2.0, kHalfRoughPixel);
  ASSERT_TRUE(e) << e.error();
  ASSERT_EQ(e.value().message, "");
  const LobeExplanation& lobe = e.value().lobe;
  EXPECT_EQ(lobe.source, LobeExplanation::Source::Prefiltered);
  EXPECT_EQ(lobe.roughness, 0.5f);
  EXPECT_EQ(lobe.alpha, 0.25f);
  EXPECT_EQ(lobe.levels.lower, 2);
  EXPECT_EQ(lobe.levels.upper, 3);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("roughness 0.50 x 5 levels = level 2.50, blended trilinearly between "
                      "level 2 (32x32 faces) and level 3 (16x16 faces)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("are the lobe's centre"), std::string::npos) << text;

  Result<PixelExplanation> perfect = explainAt(*demo, 2.0, kPerfectPixel);
  ASSERT_TRUE(perfect) << perfect.error();
  ASSERT_EQ(perfect.value().message, "");
  EXPECT_EQ(perfect.value().object, 3);
  EXPECT_EQ(perfect.value().lobe.source, LobeExplanation::Source::None);
  const std::string sharp = joinedLines(perfect.value());
  EXPECT_EQ(sharp.find("lobe"), std::string::npos) << sharp;
  EXPECT_EQ(sharp.find("rough"), std::string::npos) << sharp;
}

// search: exact traces the rough sphere: its lobe rays are named, with nothing drawn.
TEST(PixelExplain, ATracedRoughMirrorNamesItsLobeRays) {
  auto demo = testing::makeDemo(roughSpheres());
  AccuracySettings exact;
  exact.search = Search::Exact;
  ASSERT_EQ(demo->setAccuracySettings(exact), "");
  Result<PixelExplanation> e = explainAt(*demo, 2.0, kHalfRoughPixel);
  ASSERT_TRUE(e) << e.error();
  EXPECT_NE(e.value().message.find("traced exactly"), std::string::npos) << e.value().message;
  EXPECT_EQ(e.value().lobe.source, LobeExplanation::Source::Traced);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("roughness 0.50, GGX alpha 0.2500"), std::string::npos) << text;
  EXPECT_NE(text.find("traced with 16 lobe rays"), std::string::npos) << text;
  EXPECT_EQ(text.find("lobe's centre"), std::string::npos) << text;
}

// The default traces the roughness-0.25 sphere (its lobe too narrow for taps, which the
// weighing would have read): the pixel names its narrowLobeRays and why.
TEST(PixelExplain, ANarrowLobeNamesItsOwnRaysAndWhy) {
  constexpr glm::ivec2 kNarrowPixel{121, 225};
  auto demo = testing::makeDemo(roughSpheres());
  ASSERT_EQ(demo->accuracySettings().search, Search::Planned);
  Result<PixelExplanation> e = explainAt(*demo, 2.0, kNarrowPixel);
  ASSERT_TRUE(e) << e.error();
  EXPECT_EQ(e.value().lobe.source, LobeExplanation::Source::Traced);
  EXPECT_TRUE(e.value().lobe.narrow);
  EXPECT_EQ(e.value().lobe.lobeRays, 8);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("roughness 0.25"), std::string::npos) << text;
  EXPECT_NE(text.find("traced with 8 lobe rays (narrowLobeRays;"), std::string::npos) << text;
  EXPECT_NE(text.find("roughness under 0.375"), std::string::npos) << text;
}

// frosted-glass at 400 x 400, t = 2 s, hierarchical search: a pixel left of the middle of the
// roughness-0.5 glass sphere (object 6 in reflect explain's count from 1). The light through it
// is a lobe of its own, of transmission roughness 0.5 x 0.75 x sqrt(0.5 / 2): lobe taps of alpha
// 0.1875^2, or, with lobe taps off, its level 0.1875 x 5 (the reflection reads levels 2 and 3).
TEST(PixelExplain, FrostedGlassNamesTheLobeOfTheLightThrough) {
  Result<Scene> scene = loadNamedScene("frosted-glass");
  ASSERT_TRUE(scene) << scene.error();
  auto demo = testing::makeCapturingDemo(scene.take());
  Result<PixelExplanation> tapped = explainAt(*demo, 2.0, {185, 230});
  ASSERT_TRUE(tapped) << tapped.error();
  ASSERT_EQ(tapped.value().message, "");
  EXPECT_EQ(tapped.value().lobe.source, LobeExplanation::Source::LobeTaps);
  const std::string tapText = joinedLines(tapped.value());
  EXPECT_NE(tapText.find("light through: 16 lobe taps of its own, the view ray refracted "
                         "through the lobe's microfacet normals, each read at the level of its "
                         "share of a lobe of alpha 0.0352 (transmission roughness 0.19 squared"),
            std::string::npos)
      << tapText;

  AccuracySettings prefiltered = demo->accuracySettings();
  prefiltered.lobeTaps = 0;
  ASSERT_EQ(demo->setAccuracySettings(prefiltered), "");
  Result<PixelExplanation> e = explainAt(*demo, 2.0, {185, 230});
  ASSERT_TRUE(e) << e.error();
  ASSERT_EQ(e.value().message, "");
  EXPECT_EQ(e.value().object, 5);
  const LobeExplanation& lobe = e.value().lobe;
  EXPECT_TRUE(lobe.glass);
  EXPECT_EQ(lobe.source, LobeExplanation::Source::Prefiltered);
  EXPECT_FLOAT_EQ(lobe.throughRoughness, 0.1875f);
  EXPECT_FLOAT_EQ(lobe.throughLevel, 0.9375f);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("frosted glass: roughness 0.50, GGX alpha 0.2500"), std::string::npos)
      << text;
  EXPECT_NE(text.find("light through: read around the refracted ray at level 0.94"),
            std::string::npos)
      << text;
}

// The default on frosted-glass (search: planned), 400 x 400, t = 2 s: the roughness-0.25 glass
// sphere's lobes are too narrow for taps, so both are traced, half of narrowLobeRays each.
TEST(PixelExplain, NarrowFrostedGlassNamesItsTracedRays) {
  Result<Scene> scene = loadNamedScene("frosted-glass");
  ASSERT_TRUE(scene) << scene.error();
  auto demo = testing::makeDemo(scene.take());
  Result<PixelExplanation> e = explainAt(*demo, 2.0, {117, 232});
  ASSERT_TRUE(e) << e.error();
  EXPECT_NE(e.value().message.find("traces a lobe too narrow for lobe taps"), std::string::npos)
      << e.value().message;
  EXPECT_EQ(e.value().lobe.source, LobeExplanation::Source::Traced);
  EXPECT_TRUE(e.value().lobe.glass);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("frosted glass: roughness 0.25"), std::string::npos) << text;
  EXPECT_NE(text.find("traced with 4 lobe rays (narrowLobeRays;"), std::string::npos) << text;
  EXPECT_NE(text.find("light through: traced with 4 rays"), std::string::npos) << text;
}

// The skybox scene at 400 x 400, t = 2 s, its skybox mirror (object 2, the left sphere) given
// roughness 0.5: it reads the static sky's prefiltered levels, 0.5 x 5 = 2.5 of the 256-texel
// sky, between level 2 (64 texels) and 3 (32).
TEST(PixelExplain, ARoughSkyboxMirrorNamesTheSkysLevels) {
  Result<Scene> scene = loadNamedScene("skybox");
  ASSERT_TRUE(scene) << scene.error();
  Scene s = scene.take();
  ASSERT_GT(s.objects.size(), 2u);
  s.objects[2].roughness = 0.5f;
  auto demo = testing::makeCapturingDemo(std::move(s));
  Result<PixelExplanation> e = explainAt(*demo, 2.0, {55, 240});
  ASSERT_TRUE(e) << e.error();
  // No probe to explain: the lobe's lines follow the message.
  EXPECT_NE(e.value().message.find("reflects the static skybox"), std::string::npos)
      << e.value().message;
  EXPECT_EQ(e.value().object, 2);
  const LobeExplanation& lobe = e.value().lobe;
  EXPECT_EQ(lobe.source, LobeExplanation::Source::PrefilteredSky);
  EXPECT_EQ(lobe.levels.lower, 2);
  EXPECT_EQ(lobe.levels.upper, 3);
  const std::string text = joinedLines(e.value());
  EXPECT_NE(text.find("read from the static skybox's prefiltered levels (filtered once): "
                      "roughness 0.50 x 5 levels = level 2.50, blended trilinearly between "
                      "level 2 (64x64 faces) and level 3 (32x32 faces)"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("sharp"), std::string::npos) << text;
}

// probe-lit at 320 x 240, t = 1 s: a pixel of sonic and one of mario (objects 2 and 3), each lit
// by a probe of its own. The pick names that probe and the irradiance at the pixel's normal; put
// through the course's Phong with that ambient, it gives the frame's own pixel: the irradiance
// the CPU projects from the faces read back is the one the GPU projected and lit the pixel with.
constexpr glm::ivec2 kSonicPixel{122, 140};
constexpr glm::ivec2 kMarioPixel{219, 175};
// The frame is RGBA8, the projections differ in filtering (the GPU's reads the box chain's 8 x 8
// level, the CPU's the 32-texel faces) and the GPU takes the parallax at the vertices, the CPU at
// the pixel: at most 1 level apart measured, held at 2. The constant
// ambient would be 20 or more levels off at both pixels (mario's faces away from the light: its
// colour there is the irradiance alone).
constexpr int kLitLevels = 2;

Scene probeLitScene() {
  Result<Scene> scene = loadNamedScene("probe-lit");
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

TEST(PixelExplain, AProbeLitFigureNamesTheIrradianceItsPixelWasLitWith) {
  constexpr int kWidth = 320, kHeight = 240;
  auto demo = testing::makeDemo(probeLitScene());
  const Result<RgbaImage> frame = renderFrameAt(*demo, 1.0, kWidth, kHeight);
  ASSERT_TRUE(frame) << frame.error();
  for (const auto& [pixel, object] : {std::pair{kSonicPixel, 1}, std::pair{kMarioPixel, 2}}) {
    Result<PixelExplanation> e = explainPixel(*demo, pixel.x, pixel.y, kWidth, kHeight);
    ASSERT_TRUE(e) << e.error();
    const PixelExplanation& x = e.value();
    ASSERT_EQ(x.object, object);
    EXPECT_EQ(x.irradianceProbe, object);  // its own probe ("own-probe")
    EXPECT_NE(x.message.find("is phong, lit by probe"), std::string::npos) << x.message;
    EXPECT_NE(x.message.find(formatLine("E / pi = %.3f, %.3f, %.3f", x.irradiance.r, x.irradiance.g,
                                        x.irradiance.b)),
              std::string::npos)
        << x.message;
    const SceneObject& figure = demo->scene().objects[static_cast<size_t>(object)];
    const PhongLight& light = demo->scene().light;
    const glm::vec3 lit =
        phongLit(figure.colour, x.surfacePoint, x.normal, light.position, x.eye, x.irradiance,
                 glm::vec4(light.ambient, light.diffuse, light.specular, light.shininess));
    const glm::ivec3 expected = colourBytes(lit);
    const uint8_t* drawn = frame.value().at(pixel.x, pixel.y);
    std::printf("probe-lit pixel %d,%d: E/pi %.3f %.3f %.3f, drawn %d %d %d, explained %d %d %d\n",
                pixel.x, pixel.y, x.irradiance.r, x.irradiance.g, x.irradiance.b, drawn[0],
                drawn[1], drawn[2], expected.r, expected.g, expected.b);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(drawn[k] - expected[k]), kLitLevels) << k;
  }
}

}  // namespace
}  // namespace reflect
