// Depth precision against the near/far planes, measured. The shipped scene has nothing coplanar
// with the ground (the figures' lowest points are 0.19 and 1.5 units above it), so a "contact
// shadow" decal 0.01 units above the ground under the figures stands for the closest surfaces a
// scene is likely to have. With flat colours each pixel names the surface that won its depth
// test; we count
//   lost:    decal pixels (from a decal-only frame at the defaults) where the ground won;
//   flicker: pixels whose winner changes when the camera moves forward by 0.001 units
//            (silhouette pixels excluded: they move legitimately),
// for near 1e-3..10 x far 1e2..1e6, with 16- and 24-bit depth buffers (the main pass's depth is
// the framebuffer's, so the test provides both; the app itself always uses 24 bits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "extremes_util.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

using extremes::translateScale;

constexpr int kSize = 192;
constexpr float kDecalHeight = 0.01f;
const glm::vec3 kGround(0.4f, 0.4f, 1.0f);
const glm::vec3 kDecal(0.1f, 0.1f, 0.1f);

Scene zFightScene(float nearPlane, float farPlane, bool withGround) {
  Scene scene;
  extremes::useFlatLighting(scene);
  if (withGround)
    scene.objects.push_back(
        extremes::phongObject("quad.obj", translateScale({-1, -2, 4}, {100, 1, 100}), kGround));
  // Under both figures: x from -3.25 to 3.75, z from 0.25 to 3.25.
  scene.objects.push_back(extremes::phongObject(
      "decal.obj", translateScale({0.25f, -2.0f + kDecalHeight, 1.75f}, {3.5f, 1, 1.5f}), kDecal));
  scene.objects.push_back(extremes::phongObject(
      "sonic.obj", translateScale({-2, -0.5f, 2}, glm::vec3(0.05f)), {0.4f, 1.0f, 0.4f}));
  scene.objects.push_back(extremes::phongObject(
      "mario.obj", translateScale({2.5f, -0.5f, 1.5f}, glm::vec3(0.02f)), {1.0f, 0.4f, 0.4f}));
  scene.camera.near = nearPlane;
  scene.camera.far = farPlane;
  return scene;
}

std::string quadText() {
  return "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\nvn 0 1 0\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
}

// Pixels whose colour differs from a 4-neighbour's: silhouettes, where a tiny move may flip a
// pixel without any depth-precision problem.
std::vector<uint8_t> edgePixels(const RgbaImage& image) {
  std::vector<uint8_t> edges(static_cast<size_t>(image.width) * static_cast<size_t>(image.height),
                             0);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::u8vec3 c = extremes::rgbAt(image, x, y);
      bool edge = false;
      if (x > 0) edge |= extremes::rgbAt(image, x - 1, y) != c;
      if (x + 1 < image.width) edge |= extremes::rgbAt(image, x + 1, y) != c;
      if (y > 0) edge |= extremes::rgbAt(image, x, y - 1) != c;
      if (y + 1 < image.height) edge |= extremes::rgbAt(image, x, y + 1) != c;
      edges[static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)] =
          edge;
    }
  }
  return edges;
}

struct ZFight {
  int decalPixels = 0;  // decal pixels at the defaults (the reference)
  int lost = 0;
  int flicker = 0;
};

ZFight measure(Demo& demo, int depthBits, const std::vector<uint8_t>& decalInterior,
               int decalPixels) {
  ZFight z;
  z.decalPixels = decalPixels;
  demo.camera().reset();
  auto a = extremes::renderWithDepthBits(demo, 0.0, kSize, kSize, depthBits);
  demo.camera().move(0.01f);  // 0.001 units forward
  auto b = extremes::renderWithDepthBits(demo, 0.0, kSize, kSize, depthBits);
  demo.camera().reset();
  EXPECT_TRUE(a && b);
  if (!a || !b) return z;
  const glm::u8vec3 ground = extremes::toBytes(kGround);
  const std::vector<uint8_t> edges = edgePixels(a.value());
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const size_t i = static_cast<size_t>(y) * kSize + static_cast<size_t>(x);
      if (decalInterior[i] && extremes::rgbAt(a.value(), x, y) == ground) ++z.lost;
      if (!edges[i] && extremes::rgbAt(a.value(), x, y) != extremes::rgbAt(b.value(), x, y))
        ++z.flicker;
    }
  }
  return z;
}

// Depth-buffer resolution, in world units along the view axis, at distance z: one step of a
// 2^bits fixed-point window depth d = (f / (f - n)) (1 - n / z) is dz = z^2 (f - n) / (f n 2^bits).
double depthStep(double z, double n, double f, int bits) {
  return z * z * (f - n) / (f * n * std::ldexp(1.0, bits));
}

TEST(DepthPrecision, ZFightingAcrossNearFarAndDepthBits) {
  const std::map<std::string, std::string> meshes{{"decal.obj", quadText()}};
  // The decal as the defaults show it, without the ground: where it must win.
  auto decalOnly = extremes::makeDemoWith(zFightScene(1.0f, 100.0f, false), meshes);
  ASSERT_TRUE(decalOnly);
  auto reference = extremes::renderWithDepthBits(*decalOnly, 0.0, kSize, kSize, 24);
  ASSERT_TRUE(reference) << reference.error();
  testing::saveOutput(reference.value(), "zfight_decal_only.png");
  int decalPixels = 0;
  const auto decalMask =
      extremes::maskOf(reference.value(), extremes::toBytes(kDecal), &decalPixels);
  const auto decalInterior = extremes::interiorOf(decalMask, kSize, kSize);
  ASSERT_GT(decalPixels, 500);

  // The decal is seen about 6 units away, at ~30 degrees to the ground: the ray travels about
  // 0.02 units from decal to ground, which is what the depth buffer must resolve.
  std::printf(
      "decal %.2f above the ground, %d pixels at the defaults; camera moved 0.001 for flicker\n",
      static_cast<double>(kDecalHeight), decalPixels);
  std::printf("  near     far      bits  lost   flicker  depth step at 6 units\n");
  for (float nearPlane : {1e-3f, 1e-2f, 1e-1f, 1.0f, 10.0f}) {
    for (float farPlane : {1e2f, 1e4f, 1e6f}) {
      auto demo = extremes::makeDemoWith(zFightScene(nearPlane, farPlane, true), meshes);
      ASSERT_TRUE(demo);
      for (int bits : {16, 24}) {
        const ZFight z = measure(*demo, bits, decalInterior, decalPixels);
        std::printf("  %-8g %-8g %-5d %-6d %-8d %.2g%s\n", static_cast<double>(nearPlane),
                    static_cast<double>(farPlane), bits, z.lost, z.flicker,
                    depthStep(6.0, nearPlane, farPlane, bits),
                    nearPlane > 6.0f ? "  (decal closer than the near plane: clipped)" : "");
        if (nearPlane == 1.0f && farPlane == 100.0f && bits == 24) {
          // The shipped settings: no depth fighting anywhere on the ground.
          EXPECT_EQ(z.lost, 0);
          EXPECT_EQ(z.flicker, 0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace reflect
