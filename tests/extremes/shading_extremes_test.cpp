// Shading at its edges: grazing incidence on the mirror's silhouette, degenerate and zero normals
// and zero-area triangles from OBJ text, and colour sums above 1 clamped by RGBA8.
#include <gtest/gtest.h>

#include <cmath>

#include "app/headless_frames.h"
#include "core/obj_loader.h"
#include "extremes_util.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

using extremes::rgbAt;
using extremes::toBytes;
using extremes::translateScale;

const glm::vec3 kGold(0.95f, 0.85f, 0.4f);  // the sphere in makeDynamicReflectionScene
const glm::vec3 kMaskColour(1.0f, 0.0f, 1.0f);

// The mirror's smallest possible colour: the environment contributes >= 0, so every channel is
// at least base x colour (one level of rounding below).
glm::u8vec3 mirrorFloor(const glm::vec3& colour, float base) {
  return glm::u8vec3(glm::max(glm::vec3(toBytes(base * colour)) - 1.0f, glm::vec3(0.0f)));
}

// Where `scene`'s reflective object covers the frame: the same scene with the mirror drawn as a
// flat magenta Phong object (identical geometry, so identical coverage).
std::vector<uint8_t> mirrorMask(Scene scene, double seconds, int size, int* count) {
  extremes::useFlatLighting(scene);
  for (SceneObject& o : scene.objects) {
    if (o.usesEnvironment()) {
      o.material = Material::Phong;
      o.colour = kMaskColour;
    }
  }
  auto demo = testing::makeDemo(scene);
  auto image = renderFrameAt(*demo, seconds, size, size);
  EXPECT_TRUE(image) << image.error();
  return extremes::maskOf(image.value(), toBytes(kMaskColour), count);
}

TEST(ShadingExtremes, GrazingIncidenceOnTheSphereSilhouetteIsNeverAHole) {
  constexpr int kSize = 256;
  const Scene scene = makeDynamicReflectionScene();
  int discPixels = 0;
  const auto disc = mirrorMask(scene, 0.0, kSize, &discPixels);
  const auto rim = extremes::borderOf(disc, kSize, kSize);
  ASSERT_GT(discPixels, 1000);

  auto demo = testing::makeDemo(scene);
  auto image = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(image) << image.error();
  const glm::u8vec3 floor = mirrorFloor(kGold, 0.3f);
  int rimPixels = 0, black = 0, belowFloor = 0;
  glm::ivec3 rimMin(255);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const size_t i = static_cast<size_t>(y) * kSize + static_cast<size_t>(x);
      if (!disc[i]) continue;
      const glm::u8vec3 c = rgbAt(image.value(), x, y);
      black += c == glm::u8vec3(0);
      belowFloor += glm::any(glm::lessThan(c, floor));
      if (rim[i]) {
        ++rimPixels;
        rimMin = glm::min(rimMin, glm::ivec3(c));
      }
    }
  }
  std::printf(
      "sphere: %d pixels, %d on the silhouette (N.V ~ 0); darkest rim channels (%d,%d,%d), "
      "floor %s\n",
      discPixels, rimPixels, rimMin.r, rimMin.g, rimMin.b, extremes::describe(floor).c_str());
  EXPECT_EQ(black, 0);
  EXPECT_EQ(belowFloor, 0);
  EXPECT_GT(rimPixels, 100);
}

// Five positions: triangle 1-2-3 faces +Z; 2-4-5 lies on a line (zero area). Every corner has
// the all-zero normal 1, so the loader computes area-weighted normals and falls back to +Y.
constexpr const char* kDegenerateObj =
    "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nv 3 -1 0\nv 5 -1 0\n"
    "vn 0 0 0\n"
    "f 1//1 2//1 3//1\nf 2//1 4//1 5//1\n";
// Only zero-area triangles (three collinear points, and a point repeated).
constexpr const char* kZeroAreaObj = "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n";

TEST(ShadingExtremes, DegenerateNormalsFromObjAreFiniteUnitVectors) {
  auto mesh = parseObj(kDegenerateObj, "degenerate.obj");
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_EQ(mesh.value().mesh.vertices.size(), 5u);
  for (const Vertex& v : mesh.value().mesh.vertices) {
    ASSERT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) &&
                std::isfinite(v.normal.z));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    // Positions of the real triangle get its normal; the rest (only in the flat one) get +Y.
    const bool inRealTriangle = v.position.x <= 1.0f;
    EXPECT_EQ(v.normal, inRealTriangle ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0))
        << "at x = " << v.position.x;
  }
  auto flat = parseObj(kZeroAreaObj, "zero_area.obj");
  ASSERT_TRUE(flat) << flat.error();
  for (const Vertex& v : flat.value().mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
}

TEST(ShadingExtremes, DegenerateMeshesRenderWithoutBlackOrNaNPixels) {
  constexpr int kSize = 128;
  const glm::vec3 white(0.9f, 0.9f, 0.9f);
  Scene scene;
  scene.clearColour = glm::vec3(0.4f);
  scene.objects.push_back(
      extremes::phongObject("degenerate.obj", translateScale({-1.3f, 1, 2}, glm::vec3(1)), white));
  SceneObject mirror =
      extremes::mirrorObject("degenerate.obj", translateScale({1.3f, 1, 2}, glm::vec3(1)), white);
  scene.objects.push_back(mirror);
  scene.objects.push_back(
      extremes::phongObject("zero_area.obj", translateScale({0, 0, 2}, glm::vec3(1)), white));
  auto demo = extremes::makeDemoWith(
      scene, {{"degenerate.obj", kDegenerateObj}, {"zero_area.obj", kZeroAreaObj}});
  ASSERT_TRUE(demo);
  auto image = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(image) << image.error();
  testing::saveOutput(image.value(), "degenerate_meshes.png");

  // Left half: the Phong copy (>= ambient x colour); right half: the mirror (>= 0.3 x colour).
  const glm::u8vec3 clear = toBytes(scene.clearColour);
  const glm::u8vec3 phongFloor = glm::u8vec3(glm::vec3(toBytes(0.2f * white)) - 1.0f);
  const glm::u8vec3 mirrorMin = mirrorFloor(white, 0.3f);
  int phongPixels = 0, mirrorPixels = 0, bad = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const glm::u8vec3 c = rgbAt(image.value(), x, y);
      if (c == clear) continue;
      const bool left = x < kSize / 2;
      (left ? phongPixels : mirrorPixels)++;
      bad += glm::any(glm::lessThan(c, left ? phongFloor : mirrorMin));
    }
  }
  std::printf("degenerate mesh: %d Phong pixels, %d mirror pixels, %d black or below their floor\n",
              phongPixels, mirrorPixels, bad);
  EXPECT_GT(phongPixels, 100);
  EXPECT_GT(mirrorPixels, 100);
  EXPECT_EQ(bad, 0);

  // The zero-area mesh alone covers nothing: the frame is the clear colour everywhere.
  Scene zeroOnly;
  zeroOnly.clearColour = scene.clearColour;
  zeroOnly.objects.push_back(
      extremes::phongObject("zero_area.obj", translateScale({0, 1, 2}, glm::vec3(1)), white));
  auto zeroDemo = extremes::makeDemoWith(zeroOnly, {{"zero_area.obj", kZeroAreaObj}});
  ASSERT_TRUE(zeroDemo);
  auto empty = renderFrameAt(*zeroDemo, 0.0, kSize, kSize);
  ASSERT_TRUE(empty);
  int clearPixels = 0;
  extremes::maskOf(empty.value(), clear, &clearPixels);
  EXPECT_EQ(clearPixels, kSize * kSize);
}

TEST(ShadingExtremes, ColourSumsAboveOneClampTo255) {
  // A white environment (the clear colour on every face) on the gold mirror: every mirror pixel
  // is 0.78 x 1 + 0.3 x (0.95, 0.85, 0.4) = (1.065, 1.035, 0.90), stored in RGBA8 as
  // (255, 255, 0.90 x 255 = 229.5). 229.5 is a rounding tie: in float 0.78f + 0.3f x 0.4f is
  // 0.89999998, so 229 is the exact result and 230 is what a GPU adding 0.5 after a slightly
  // different rounding gives; both are the formula's answer.
  constexpr int kSize = 96;
  Scene scene;
  scene.clearColour = glm::vec3(1.0f);
  SceneObject sphere =
      extremes::mirrorObject("sphere.obj", translateScale({0, 0, 0}, glm::vec3(0.5f)), kGold);
  scene.objects.push_back(sphere);
  int discPixels = 0;
  const auto disc = mirrorMask(scene, 0.0, kSize, &discPixels);
  auto demo = testing::makeDemo(scene);
  auto image = renderFrameAt(*demo, 0.0, kSize, kSize);
  ASSERT_TRUE(image);
  const float blue = 0.78f * 1.0f + 0.3f * kGold.b;
  std::printf("white environment on gold: blue = %.8f -> %.4f levels\n", static_cast<double>(blue),
              static_cast<double>(blue * 255.0f));
  std::map<std::tuple<int, int, int>, int> seen;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (!disc[static_cast<size_t>(y) * kSize + static_cast<size_t>(x)]) continue;
      const glm::u8vec3 c = rgbAt(image.value(), x, y);
      ++seen[{c.r, c.g, c.b}];
    }
  }
  ASSERT_GT(discPixels, 300);
  for (const auto& [c, n] : seen) {
    std::printf("  (%d,%d,%d) x %d\n", std::get<0>(c), std::get<1>(c), std::get<2>(c), n);
  }
  ASSERT_EQ(seen.size(), 1u) << "a uniform environment must give one colour over the whole sphere";
  const auto [r, g, b] = seen.begin()->first;
  EXPECT_EQ(r, 255);
  EXPECT_EQ(g, 255);
  EXPECT_TRUE(b == 229 || b == 230) << b;
}

}  // namespace
}  // namespace reflect
