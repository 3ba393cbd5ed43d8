// The raster frame against the Embree reference of the same moment and camera: where the two
// shade the same way (everything but the mirror) they must agree to rounding; on the mirror the
// difference is what the cube-map approximation costs, which these tests print and bound loosely.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "gl_fixture.h"
#include "reference/reference_renderer.h"

namespace reflect {
namespace {

constexpr int kSize = 512;
constexpr double kOffReflectorMinPsnr = 40.0;

MeshLookup meshesOf(const Demo& demo) {
  return [&demo](const std::string& name) { return demo.meshLevel(name, 0); };
}

// |a - b| per channel, scaled by `gain` so small differences show.
RgbaImage differenceImage(const RgbaImage& a, const RgbaImage& b, int gain) {
  RgbaImage d = a;
  for (size_t i = 0; i < d.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      const int diff =
          std::abs(static_cast<int>(a.pixels[i + c]) - static_cast<int>(b.pixels[i + c]));
      d.pixels[i + c] = static_cast<uint8_t>(std::min(255, diff * gain));
    }
    d.pixels[i + 3] = 255;
  }
  return d;
}

// Pixels whose centre ray (the GL camera's) meets the exact sphere of `radius` at `centre`.
size_t analyticDiscPixels(const LookCamera& camera, int w, int h, const glm::vec3& centre,
                          double radius) {
  const glm::dmat4 inv = glm::inverse(
      glm::dmat4(camera.projection(static_cast<float>(w) / static_cast<float>(h)) * camera.view()));
  const glm::dvec3 c(centre);
  size_t count = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double nx = (x + 0.5) / w * 2.0 - 1.0;
      const double ny = 1.0 - (y + 0.5) / h * 2.0;
      const glm::dvec4 n = inv * glm::dvec4(nx, ny, -1.0, 1.0);
      const glm::dvec4 f = inv * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 o = glm::dvec3(n) / n.w;
      const glm::dvec3 d = glm::normalize(glm::dvec3(f) / f.w - o);
      // |o + t d - c|^2 = r^2 has a real root.
      const glm::dvec3 oc = o - c;
      const double b = glm::dot(oc, d);
      const double disc = b * b - (glm::dot(oc, oc) - radius * radius);
      if (disc >= 0.0) ++count;
    }
  }
  return count;
}

void printReport(const char* label, const AccuracyReport& r) {
  std::printf(
      "%s: off-reflector PSNR %.2f dB (RMSE %.3f, p95 %d, max %d, %zu px); without silhouettes "
      "%.2f dB (max %d, %zu px)\n",
      label, r.offReflector.psnrDb, r.offReflector.rmse, r.offReflector.p95PixelError,
      r.offReflector.maxPixelError, r.offReflector.pixelCount, r.offReflectorInterior.psnrDb,
      r.offReflectorInterior.maxPixelError, r.offReflectorInterior.pixelCount);
  std::printf(
      "%s: reflector RMSE %.3f, PSNR %.2f dB, p95 %d, max %d over %zu px; mean angular error of "
      "the plain lookup %.3f deg; reference %.0f ms\n",
      label, r.reflector.rmse, r.reflector.psnrDb, r.reflector.p95PixelError,
      r.reflector.maxPixelError, r.reflector.pixelCount, r.meanAngularErrorDeg, r.referenceMs);
}

struct Compared {
  RgbaImage raster;
  ReferenceFrame reference;
  AccuracyReport report;
};

Compared renderBoth(Demo& demo, double t, int width = kSize, int height = kSize,
                    const std::string& tag = "") {
  Compared c;
  auto raster = renderFrameAt(demo, t, width, height);
  EXPECT_TRUE(raster) << raster.error();
  if (!raster) return c;
  c.raster = raster.take();
  auto reference = renderReference(demo.scene(), meshesOf(demo), demo.skyboxFaces(), demo.camera(),
                                   demo.clock().seconds(), width, height);
  EXPECT_TRUE(reference) << reference.error();
  if (!reference) return c;
  c.reference = reference.take();
  auto report = compareWithReference(c.raster, c.reference);
  EXPECT_TRUE(report) << report.error();
  if (report) c.report = report.value();
  c.report.timeSeconds = t;
  const std::string suffix = tag + "_t" + std::to_string(static_cast<int>(t)) + ".png";
  testing::saveOutput(c.raster, "raster" + suffix);
  testing::saveOutput(c.reference.image, "reference" + suffix);
  testing::saveOutput(differenceImage(c.raster, c.reference.image, 4), "difference_x4" + suffix);
  return c;
}

TEST(Reference, AgreesWithTheRasterOffTheMirror) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  for (double t : {0.0, 5.0}) {
    const Compared c = renderBoth(*demo, t);
    ASSERT_EQ(c.reference.image.width, kSize);
    const std::string label = "t=" + std::to_string(static_cast<int>(t));
    printReport(label.c_str(), c.report);
    EXPECT_GE(c.report.offReflector.psnrDb, kOffReflectorMinPsnr) << label;
    EXPECT_GT(c.report.offReflectorPixels, static_cast<size_t>(kSize * kSize / 2));
  }
}

TEST(Reference, MirrorRegionMetricsAndCoverage) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  // The sphere: sphere.obj's bounds (2.5456 across, centred at y = 0.5) at scale 0.5.
  const glm::vec3 centre(0.0f, 0.25f, 0.0f);
  const double radius = 1.2728;
  const size_t expected = analyticDiscPixels(demo->camera(), kSize, kSize, centre, radius);
  for (double t : {0.0, 5.0}) {
    const Compared c = renderBoth(*demo, t);
    const AccuracyReport& r = c.report;
    EXPECT_TRUE(std::isfinite(r.reflector.rmse));
    EXPECT_TRUE(std::isfinite(r.reflector.psnrDb));
    EXPECT_TRUE(std::isfinite(r.meanAngularErrorDeg));
    EXPECT_GT(r.meanAngularErrorDeg, 0.0);
    EXPECT_LT(r.meanAngularErrorDeg, 90.0);
    EXPECT_EQ(c.reference.lookupDirs.size(), r.reflectorPixels);
    const double ratio = static_cast<double>(r.reflectorPixels) / static_cast<double>(expected);
    std::printf("t=%d: mirror mask %zu px, exact sphere's disc %zu px (ratio %.4f)\n",
                static_cast<int>(t), r.reflectorPixels, expected, ratio);
    EXPECT_NEAR(ratio, 1.0, 0.05);
  }
}

// A phone's shape (390x844, halved): the camera keeps its field of view across, and the
// reference follows camera.projection as the raster does, so the two still agree off the mirror
// and the mirror covers the exact sphere's disc, as wide as on a square target of that width.
TEST(Reference, AgreesWithTheRasterOnAPortraitTarget) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  constexpr int kWidth = 195, kHeight = 422;
  const Compared c = renderBoth(*demo, 0.0, kWidth, kHeight, "_portrait");
  ASSERT_EQ(c.reference.image.width, kWidth);
  ASSERT_EQ(c.reference.image.height, kHeight);
  printReport("portrait", c.report);
  EXPECT_GE(c.report.offReflector.psnrDb, kOffReflectorMinPsnr);
  const glm::vec3 centre(0.0f, 0.25f, 0.0f);
  const double radius = 1.2728;
  const size_t disc = analyticDiscPixels(demo->camera(), kWidth, kHeight, centre, radius);
  const size_t squareDisc = analyticDiscPixels(demo->camera(), kWidth, kWidth, centre, radius);
  std::printf("portrait: mirror mask %zu px, exact disc %zu px, on a %dx%d target %zu px\n",
              c.report.reflectorPixels, disc, kWidth, kWidth, squareDisc);
  EXPECT_NEAR(static_cast<double>(c.report.reflectorPixels) / static_cast<double>(disc), 1.0, 0.05);
  EXPECT_NEAR(static_cast<double>(disc) / static_cast<double>(squareDisc), 1.0, 0.03);
}

TEST(Reference, ProbeCentreIsTheMirrorsBoundsCentre) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  const int mirror = demo->scene().reflectorIndex();
  ASSERT_GE(mirror, 0);
  const glm::vec3 c = probeCentre(demo->scene(), meshesOf(*demo), 0.0, mirror);
  EXPECT_NEAR(c.x, 0.0f, 1e-3f);
  EXPECT_NEAR(c.y, 0.25f, 1e-3f);
  EXPECT_NEAR(c.z, 0.0f, 1e-3f);
}

TEST(Reference, MeasureAccuracyMatchesTheParts) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto report = measureAccuracy(*demo, 5.0, 128, 128);
  ASSERT_TRUE(report) << report.error();
  EXPECT_EQ(report.value().width, 128);
  EXPECT_EQ(report.value().timeSeconds, 5.0);
  EXPECT_GT(report.value().reflectorPixels, 0u);
  EXPECT_EQ(report.value().reflectorPixels + report.value().offReflectorPixels, 128u * 128u);
  EXPECT_GT(report.value().rasterMs, 0.0);
  EXPECT_GT(report.value().referenceMs, 0.0);
  printReport("measureAccuracy 128x128 t=5", report.value());
}

// Prints the cost of one 800 x 800 reference (no bound asserted: the machine may be busy).
TEST(Reference, AFullFrameIsTheSameOnOneThreadAndOnAll) {
  // The frame README's numbers are measured at: every row split among the threads or not, the
  // same pixels and ids (the times are printed, not held: a test does not time).
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  std::vector<ReferenceFrame> frames;
  for (int threads : {1, 0}) {
    auto frame = renderReference(demo->scene(), meshesOf(*demo), nullptr, demo->camera(), 5.0, 800,
                                 800, threads);
    ASSERT_TRUE(frame) << frame.error();
    std::printf("reference 800x800, %s: %.1f ms\n",
                threads == 1 ? "1 thread" : "all hardware threads", frame.value().renderMs);
    frames.push_back(frame.take());
  }
  EXPECT_EQ(frames[0].image.pixels, frames[1].image.pixels);
  EXPECT_EQ(frames[0].objectIds, frames[1].objectIds);
}

TEST(Reference, ThreadCountDoesNotChangeThePixels) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto one =
      renderReference(demo->scene(), meshesOf(*demo), nullptr, demo->camera(), 3.0, 96, 64, 1);
  auto three =
      renderReference(demo->scene(), meshesOf(*demo), nullptr, demo->camera(), 3.0, 96, 64, 3);
  ASSERT_TRUE(one) << one.error();
  ASSERT_TRUE(three) << three.error();
  EXPECT_EQ(one.value().image.pixels, three.value().image.pixels);
  EXPECT_EQ(one.value().objectIds, three.value().objectIds);
  EXPECT_EQ(one.value().lookupDirs.size(), three.value().lookupDirs.size());
}

TEST(Reference, TwoMirrorsAreBothTracedAsMirrors) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  Scene scene = demo->scene();
  const int first = scene.reflectorIndex();
  SceneObject second = scene.objects[static_cast<size_t>(first)];
  second.placement =
      glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f, 0.0f, -1.0f)) * second.placement;
  scene.objects.push_back(second);
  auto frame = renderReference(scene, meshesOf(*demo), nullptr, demo->camera(), 0.0, 256, 256);
  ASSERT_TRUE(frame) << frame.error();
  testing::saveOutput(frame.value().image, "reference_two_mirrors.png");
  const int secondIndex = static_cast<int>(scene.objects.size()) - 1;
  size_t firstPixels = 0;
  size_t secondPixels = 0;
  for (size_t i = 0; i < frame.value().objectIds.size(); ++i) {
    firstPixels += frame.value().objectIds[i] == first;
    secondPixels += frame.value().objectIds[i] == secondIndex;
    EXPECT_EQ(frame.value().reflectorMask[i] != 0,
              frame.value().objectIds[i] == first || frame.value().objectIds[i] == secondIndex);
  }
  EXPECT_GT(firstPixels, 0u);
  EXPECT_GT(secondPixels, 0u);
  EXPECT_EQ(frame.value().lookupDirs.size(), firstPixels + secondPixels);
}

TEST(Reference, RefusesWhatItCannotRenderExactly) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  // A scene that names a skybox, without its faces.
  Scene sky = demo->scene();
  sky.skybox.cross = "skybox/sky_cross.png";
  auto noFaces = renderReference(sky, meshesOf(*demo), nullptr, demo->camera(), 0.0, 8, 8);
  EXPECT_FALSE(noFaces);
  // Faces that are not six equal squares.
  CubeFaces faces;
  for (RgbaImage& face : faces) face = RgbaImage{2, 2, std::vector<uint8_t>(16, 0)};
  faces[3] = RgbaImage{2, 1, std::vector<uint8_t>(8, 0)};
  auto badFaces = renderReference(sky, meshesOf(*demo), &faces, demo->camera(), 0.0, 8, 8);
  EXPECT_FALSE(badFaces);
  auto missing = renderReference(
      demo->scene(), [](const std::string&) -> const MeshData* { return nullptr; }, nullptr,
      demo->camera(), 0.0, 8, 8);
  EXPECT_FALSE(missing);
  EXPECT_FALSE(renderReference(demo->scene(), meshesOf(*demo), nullptr, demo->camera(), 0.0, 0, 8));
}

}  // namespace
}  // namespace reflect
