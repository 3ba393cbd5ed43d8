// Model transforms at their extremes: uniform scales of 1e-4 and 1e4, a strongly non-uniform
// scale, singular scales, and an object 1e5 units from the origin; on the CPU (normal matrices,
// planner, frustum) and rendered.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/headless_frames.h"
#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/frustum.h"
#include "core/normal_matrix.h"
#include "extremes_util.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

using extremes::makeDemoWith;
using extremes::translateScale;

bool allFinite(const glm::mat3& m) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// What the renderer uploads as u_normalMatrix (scene_renderer.cpp).
glm::mat3 normalMatrix(const glm::mat4& model) {
  return normalMatrixOf(glm::mat3(model));
}

TEST(TransformExtremes, UniformScaleKeepsNormalDirections) {
  const glm::vec3 normals[] = {
      {0, 1, 0}, glm::normalize(glm::vec3(1, 2, 3)), glm::normalize(glm::vec3(-5, 0.1f, 2))};
  for (float s : {1e-4f, 1e4f}) {
    const glm::mat4 model =
        glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(s)), 0.7f, glm::vec3(0, 1, 0));
    const glm::mat3 n = normalMatrix(model);
    ASSERT_TRUE(allFinite(n)) << s;
    for (const glm::vec3& local : normals) {
      const glm::vec3 expected =
          glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0, 1, 0))) * local;
      EXPECT_LT(glm::length(glm::normalize(n * local) - expected), 1e-6f) << "scale " << s;
    }
  }
}

TEST(TransformExtremes, NonUniformScaleKeepsTiltedNormalsPerpendicular) {
  // A plane tilted 30 degrees about Z, then stretched S(100, 1, 100) (as the ground is).
  const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 0, 1));
  const glm::mat4 model = glm::scale(glm::mat4(1.0f), glm::vec3(100, 1, 100)) * tilt;
  const glm::vec3 normal(0, 1, 0);
  const glm::vec3 tangents[] = {{1, 0, 0}, {0, 0, 1}, glm::normalize(glm::vec3(1, 0, 1))};
  const glm::vec3 worldNormal = glm::normalize(normalMatrix(model) * normal);
  const glm::vec3 naiveNormal = glm::normalize(glm::mat3(model) * normal);
  float worst = 0, naiveWorst = 0;
  for (const glm::vec3& t : tangents) {
    const glm::vec3 worldTangent = glm::normalize(glm::mat3(model) * t);
    worst = std::max(worst, std::fabs(glm::dot(worldNormal, worldTangent)));
    naiveWorst = std::max(naiveWorst, std::fabs(glm::dot(naiveNormal, worldTangent)));
  }
  std::printf("S(100,1,100) tilted plane: |N.T| = %.3g with the inverse-transpose, %.3g with M\n",
              static_cast<double>(worst), static_cast<double>(naiveWorst));
  EXPECT_LT(worst, 1e-6f);
  EXPECT_GT(naiveWorst, 0.5f);  // the test would notice the upper 3x3 used directly
}

TEST(TransformExtremes, SingularScaleNormalMatrixIsFiniteAndPointsTheRightWay) {
  // glm::inverseTranspose divides by the determinant: for scale 0 (uniform, or on one axis) it is
  // inf/NaN. The renderer uses normalMatrixOf (the cofactor matrix), which needs no division.
  const glm::mat3 flat = glm::mat3(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1)));
  EXPECT_FALSE(allFinite(glm::inverseTranspose(flat)));
  EXPECT_FALSE(allFinite(glm::inverseTranspose(glm::mat3(0.0f))));
  const glm::mat3 n = normalMatrixOf(flat);
  ASSERT_TRUE(allFinite(n));
  ASSERT_TRUE(allFinite(normalMatrixOf(glm::mat3(0.0f))));
  // The flattened plane's normal is still +Y.
  EXPECT_LT(glm::length(glm::normalize(n * glm::vec3(0, 1, 0)) - glm::vec3(0, 1, 0)), 1e-6f);
  // And for regular matrices it agrees in direction with the inverse-transpose.
  const glm::mat3 m = glm::mat3(glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(100, 1, 100)),
                                            0.5f, glm::normalize(glm::vec3(1, 2, 3))));
  const glm::vec3 v = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
  EXPECT_LT(glm::length(glm::normalize(normalMatrixOf(m) * v) -
                        glm::normalize(glm::inverseTranspose(m) * v)),
            1e-5f);
}

// A small scene for rendered comparisons: ground, a lit cube, the mirror sphere.
Scene smallScene() {
  Scene scene;
  scene.objects.push_back(extremes::phongObject(
      "quad.obj", translateScale({-1, -2, 4}, {100, 1, 100}), {0.4f, 0.4f, 1.0f}));
  scene.objects.push_back(extremes::phongObject(
      "cube.obj", translateScale({1.8f, -1.0f, 0.5f}, glm::vec3(0.5f)), {1.0f, 0.4f, 0.4f}));
  SceneObject sphere = extremes::mirrorObject(
      "sphere.obj", translateScale({0, 0, 0}, glm::vec3(0.5f)), {0.95f, 0.85f, 0.4f});
  scene.objects.push_back(sphere);
  return scene;
}

// The whole scene scaled by s about the origin (objects, camera, light, capture planes): a
// perspective image of it is the same picture, so it must match the unscaled frame.
Scene scaledScene(float s) {
  Scene scene = smallScene();
  for (SceneObject& o : scene.objects)
    o.placement = glm::scale(glm::mat4(1.0f), glm::vec3(s)) * o.placement;
  scene.camera.eye *= s;
  scene.camera.near *= s;
  scene.camera.far *= s;
  scene.capture.near *= s;
  scene.capture.far *= s;
  scene.light.position *= s;
  return scene;
}

// Renders scaledScene(s) for s = 1e-4, 1, 1e4 with `accuracy`; returns the worst fraction of
// pixels (over 2 levels) and the worst max difference against s = 1.
std::pair<double, int> scaleInvarianceError(const AccuracySettings& accuracy,
                                            const std::string& label) {
  constexpr int kSize = 192;
  auto render = [&](float s) -> Result<RgbaImage> {
    auto demo = makeDemoWith(scaledScene(s));
    if (!demo) return Result<RgbaImage>::failure("no demo");
    const std::string error = demo->setAccuracySettings(accuracy);
    if (!error.empty()) return Result<RgbaImage>::failure(error);
    return renderFrameAt(*demo, 0.0, kSize, kSize);
  };
  auto expected = render(1.0f);
  EXPECT_TRUE(expected) << expected.error();
  if (!expected) return {1.0, 255};
  std::pair<double, int> worst{0.0, 0};
  for (float s : {1e-4f, 1e4f}) {
    auto image = render(s);
    EXPECT_TRUE(image) << image.error();
    if (!image) return {1.0, 255};
    testing::saveOutput(
        image.value(),
        "scaled_" + label + "_" + std::to_string(static_cast<int>(std::log10(s))) + ".png");
    auto d = compareImages(image.value(), expected.value(), 2);
    std::printf(
        "%s lookup, scene scaled by %g: max channel difference %d, mean %.4f, %.4f%% of "
        "pixels over 2\n",
        label.c_str(), static_cast<double>(s), d.value().maxChannel, d.value().meanChannel,
        100.0 * d.value().fractionOver);
    worst.first = std::max(worst.first, d.value().fractionOver);
    worst.second = std::max(worst.second, d.value().maxChannel);
  }
  return worst;
}

TEST(TransformExtremes, ScenesScaledBy1eMinus4And1e4RenderTheSamePicture) {
  // The course's plain lookup along R: a perspective picture of a uniformly scaled world is the
  // same picture. (Float rounding could move a silhouette pixel; measured: no difference at all.)
  AccuracySettings plain;
  plain.search = Search::Plain;
  const auto [fraction, maxDifference] = scaleInvarianceError(plain, "plain");
  EXPECT_LE(fraction, 0.003) << "max difference " << maxDifference;
}

TEST(TransformExtremes, DistanceCorrectedLookupIsScaleInvariant) {
  // The shipped default (distance-corrected lookup) is geometric too. It once stored distance as
  // d / (d + 1), which assumed distances near 1 unit (1.5% of pixels off by up to 112 levels at
  // 1e-4 and 1e4); it now encodes in units of the capture's near plane.
  const auto [fraction, maxDifference] = scaleInvarianceError(AccuracySettings{}, "default");
  EXPECT_LE(fraction, 0.003) << "max difference " << maxDifference;
}

TEST(TransformExtremes, StretchedTiltedPlaneIsLitWithItsTrueNormal) {
  // Phong without specular and with a light so far away that L is one direction: the plane's
  // colour is colour * (ambient + diffuse * max(N.L, 0)) at every pixel.
  constexpr int kSize = 128;
  Scene scene;
  const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 0, 1));
  const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(0, -2, 0)) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(100, 1, 100)) * tilt;
  const glm::vec3 colour(1.0f, 0.5f, 0.25f);
  scene.objects.push_back(extremes::phongObject("quad.obj", model, colour));
  const glm::vec3 toLight = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  scene.light.position = 1e6f * toLight;
  scene.light.specular = 0.0f;
  scene.clearColour = glm::vec3(0.0f);
  auto demo = makeDemoWith(scene);
  ASSERT_TRUE(demo);
  auto image = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(image) << image.error();

  const glm::vec3 trueNormal =
      glm::normalize(glm::inverseTranspose(glm::mat3(model)) * glm::vec3(0, 1, 0));
  const glm::vec3 naiveNormal = glm::normalize(glm::mat3(model) * glm::vec3(0, 1, 0));
  auto lit = [&](const glm::vec3& n) {
    return extremes::toBytes(colour * (scene.light.ambient +
                                       scene.light.diffuse * std::max(glm::dot(n, toLight), 0.0f)));
  };
  const glm::u8vec3 expected = lit(trueNormal);
  int planePixels = 0, worst = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const glm::u8vec3 c = extremes::rgbAt(image.value(), x, y);
      if (c == glm::u8vec3(0)) continue;  // the clear colour: sky above the horizon
      ++planePixels;
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int(c[k]) - int(expected[k])));
    }
  }
  std::printf(
      "tilted S(100,1,100) plane: %d pixels, expected %s (with M instead: %s), worst "
      "channel error %d\n",
      planePixels, extremes::describe(expected).c_str(),
      extremes::describe(lit(naiveNormal)).c_str(), worst);
  EXPECT_GT(planePixels, kSize * kSize / 4);
  EXPECT_LE(worst, 2);
}

TEST(TransformExtremes, ObjectsScaledToZeroLeaveTheFrameUnchanged) {
  constexpr int kSize = 160;
  auto base = makeDemoWith(smallScene());
  ASSERT_TRUE(base);
  auto expected = renderFrameAt(*base, 0.0, kSize, kSize);
  ASSERT_TRUE(expected) << expected.error();

  Scene scene = smallScene();
  scene.objects.push_back(
      extremes::phongObject("cube.obj", translateScale({0.5f, 0, 2}, glm::vec3(0.0f)), {0, 1, 0}));
  SceneObject zeroMirror =
      extremes::mirrorObject("sphere.obj", translateScale({-1, 0, 2}, glm::vec3(0.0f)), {1, 1, 1});
  scene.objects.push_back(zeroMirror);
  auto demo = makeDemoWith(scene);
  ASSERT_TRUE(demo);
  auto image = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(image) << image.error();
  auto d = compareImages(image.value(), expected.value(), 0);
  ASSERT_TRUE(d);
  // Zero-area triangles cover no pixel, so their NaN normal matrix never reaches a fragment.
  EXPECT_EQ(d.value().maxChannel, 0)
      << "a zero-scale object changed " << d.value().fractionOver * 100 << "% of the frame";
  // Both mirrors are planned: captured or traced.
  EXPECT_EQ(demo->lastStats().probes + demo->lastStats().tracedReflectors, 2);
}

TEST(TransformExtremes, QuadWithASingularScaleIsLitLikeTheSameQuadUnscaled) {
  // quad.obj lies in y = 0, so S(1, 0, 1) leaves its geometry exactly as S(1, 1, 1) does: same
  // pixels, same true normal (+Y). Only the normal matrix differs: inverse-transpose of a
  // singular 3x3 is inf/NaN. The frames must be equal.
  constexpr int kSize = 128;
  Scene scene;
  scene.clearColour = glm::vec3(0.0f);
  const glm::vec3 colour(0.2f, 0.9f, 0.2f);
  scene.objects.push_back(
      extremes::phongObject("quad.obj", translateScale({0, -1.2f, 3}, {1, 1, 1}), colour));
  auto unscaled = makeDemoWith(scene);
  ASSERT_TRUE(unscaled);
  auto expected = renderFrameAt(*unscaled, 0.0, kSize, kSize);
  ASSERT_TRUE(expected);
  scene.objects[0].placement = translateScale({0, -1.2f, 3}, {1, 0, 1});
  auto singular = makeDemoWith(scene);
  ASSERT_TRUE(singular);
  auto image = renderFrameAt(*singular, 0.0, kSize, kSize);
  ASSERT_TRUE(image);
  testing::saveOutput(image.value(), "singular_scale_quad.png");
  int quadPixels = 0, black = 0;
  glm::u8vec3 sampleWant(0), sampleGot(0);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const glm::u8vec3 want = extremes::rgbAt(expected.value(), x, y);
      if (want == glm::u8vec3(0)) continue;
      ++quadPixels;
      const glm::u8vec3 got = extremes::rgbAt(image.value(), x, y);
      black += got == glm::u8vec3(0);
      if (quadPixels == 1 || (x == kSize / 2 && sampleGot == glm::u8vec3(0))) {
        sampleWant = want;
        sampleGot = got;
      }
    }
  }
  auto d = compareImages(image.value(), expected.value(), 2);
  ASSERT_TRUE(d);
  std::printf(
      "quad S(1,0,1) vs S(1,1,1): %d quad pixels, %d black, max channel difference %d, "
      "e.g. %s instead of %s\n",
      quadPixels, black, d.value().maxChannel, extremes::describe(sampleGot).c_str(),
      extremes::describe(sampleWant).c_str());
  ASSERT_GT(quadPixels, 500);
  // Before the cofactor normal matrix this was (10,46,10), the ambient term only (NaN normal).
  EXPECT_LE(d.value().maxChannel, 2);
}

TEST(TransformExtremes, ObjectFarFromTheOriginStaysFiniteInPlannerAndFrustum) {
  const Bounds cube{glm::vec3(-1), glm::vec3(1)};
  for (const glm::vec3& where : {glm::vec3(1e5f, 0, 0), glm::vec3(1e5f, 1e5f, -1e5f)}) {
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), where);
    const Bounds world = transformBounds(cube, model);
    EXPECT_EQ(world.min, where - glm::vec3(1));
    EXPECT_EQ(world.max, where + glm::vec3(1));
    int facesSeeing = 0;
    for (int face = 0; face < 6; ++face) {
      EXPECT_FALSE(faceMaySee(glm::vec3(0), face, 1.0f, 100.0f, cube, model))
          << "far 100, face " << face;
      facesSeeing += faceMaySee(glm::vec3(0), face, 1.0f, 1e6f, cube, model);
    }
    // Within a far plane of 1e6 the box is in front of exactly one face (+X), or on the
    // boundary of at most three when it sits on a cube diagonal.
    EXPECT_GE(facesSeeing, 1);
    EXPECT_LE(facesSeeing, where.y == 0 ? 1 : 3);
  }
  EXPECT_TRUE(faceMaySee(glm::vec3(0), 0, 1.0f, 1e6f, cube,
                         glm::translate(glm::mat4(1.0f), glm::vec3(1e5f, 0, 0))));

  // The planner: a mirror at the origin and a cube 1e5 away; beyond the capture's far plane of
  // 100 the cube is never drawn into a face, and every number in the plan is finite.
  FramePlanner planner;
  std::vector<PlannedObject> objects(2);
  objects[0].localBounds = cube;
  objects[0].probed = true;
  objects[1].localBounds = cube;
  objects[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(1e5f, 3.0f, -2.0f));
  CaptureContext context;
  for (float farPlane : {100.0f, 1e6f}) {
    context.far = farPlane;
    const FramePlan plan = planner.plan(objects, context, PlannerSettings{});
    ASSERT_EQ(plan.probes.size(), 1u);
    EXPECT_TRUE(std::isfinite(plan.probes[0].centre.x) && std::isfinite(plan.probes[0].centre.y) &&
                std::isfinite(plan.probes[0].centre.z));
    int drawsOfFarCube = 0;
    for (const FacePlan& face : plan.probes[0].faces) {
      for (const DrawItem& d : face.draws) drawsOfFarCube += d.object == 1;
    }
    EXPECT_EQ(drawsOfFarCube, farPlane < 1e5f ? 0 : 1) << "capture far " << farPlane;
  }
}

TEST(TransformExtremes, ObjectFarFromTheOriginRendersFinite) {
  constexpr int kSize = 128;
  Scene scene = smallScene();
  extremes::useFlatLighting(scene);
  auto base = makeDemoWith(scene);
  ASSERT_TRUE(base);
  auto without = renderFrameAt(*base, 0.0, kSize, kSize);
  ASSERT_TRUE(without);

  // A cube of half-size 5000 1e5 ahead of the camera and 3e4 up (above the mirror sphere, which
  // covers the view axis): beyond the far plane of 100 it is clipped away entirely; with a far
  // plane of 1e6 it shows, in its exact flat colour, where the camera projects its centre.
  const glm::vec3 colour(0.0f, 1.0f, 0.0f);
  const glm::vec3 centre(0.0f, 3e4f, -1e5f);
  scene.objects.push_back(
      extremes::phongObject("cube.obj", translateScale(centre, glm::vec3(5000.0f)), colour));
  auto clipped = makeDemoWith(scene);
  ASSERT_TRUE(clipped);
  auto image = renderFrameAt(*clipped, 0.0, kSize, kSize);
  ASSERT_TRUE(image);
  auto d = compareImages(image.value(), without.value(), 0);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().maxChannel, 0) << "an object beyond the far plane changed the frame";

  scene.camera.far = 1e6f;
  auto visible = makeDemoWith(scene);
  ASSERT_TRUE(visible);
  image = renderFrameAt(*visible, 0.0, kSize, kSize);
  ASSERT_TRUE(image);
  testing::saveOutput(image.value(), "far_cube.png");
  int cubePixels = 0;
  extremes::maskOf(image.value(), extremes::toBytes(colour), &cubePixels);
  LookCamera camera(scene.camera);
  const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(centre, 1.0f);
  const int px = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * kSize);
  const int py = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * kSize);
  // Half-size 5000 at ~1.04e5: about 5.5 degrees of a 70-degree view, ~10 pixels across.
  std::printf("cube 1e5 away, far 1e6: %d pixels of its exact colour around (%d,%d)\n", cubePixels,
              px, py);
  EXPECT_GE(cubePixels, 49);
  EXPECT_LE(cubePixels, 169);
  ASSERT_TRUE(px >= 0 && py >= 0 && px < kSize && py < kSize);
  EXPECT_EQ(extremes::rgbAt(image.value(), px, py), extremes::toBytes(colour));
}

}  // namespace
}  // namespace reflect
