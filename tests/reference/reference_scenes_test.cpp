// The reference on every shipped scene (assets/scenes/*.json): it renders each one, equals the
// raster off the reflectors, and draws the same sky as GL. The reflectors' own error is printed
// and bounded only loosely: that difference is what the accuracy figures measure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"
#include "reference/reference_renderer.h"

namespace reflect {
namespace {

constexpr int kSize = 256;
constexpr double kOffReflectorMinPsnr = 40.0;
// The raster's reflectors differ from the truth by design; this only catches a broken reference.
constexpr double kReflectorLooseMinPsnr = 15.0;

MeshLookup meshesOf(const Demo& demo) {
  return [&demo](const std::string& name) { return demo.meshLevel(name, 0); };
}

std::unique_ptr<Demo> shippedDemo(const std::string& name) {
  Result<Scene> scene = loadNamedScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return testing::makeDemo(scene ? scene.take() : Scene{});
}

class ShippedSceneReference : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedSceneReference, EqualsTheRasterOffTheReflectorsAtTwoSeconds) {
  auto demo = shippedDemo(GetParam());
  auto report = measureAccuracy(*demo, 2.0, kSize, kSize);
  ASSERT_TRUE(report) << report.error();
  const AccuracyReport& r = report.value();
  std::printf(
      "%s: off-reflector PSNR %.2f dB (max %d, %zu px); reflectors PSNR %.2f dB (RMSE %.2f, "
      "%zu px), mean angular error of the lookup %.3f deg; reference %.0f ms\n",
      GetParam().c_str(), r.offReflector.psnrDb, r.offReflector.maxPixelError,
      r.offReflector.pixelCount, r.reflector.psnrDb, r.reflector.rmse, r.reflector.pixelCount,
      r.meanAngularErrorDeg, r.referenceMs);
  testing::saveOutput(r.referenceImage, "reference_" + GetParam() + "_t2.png");
  EXPECT_GE(r.offReflector.psnrDb, kOffReflectorMinPsnr);
  EXPECT_GT(r.reflectorPixels, 0u);  // every shipped scene has a mirror, glass or cube-textured
  EXPECT_GT(r.reflector.psnrDb, kReflectorLooseMinPsnr);
  EXPECT_TRUE(std::isfinite(r.meanAngularErrorDeg));
}

INSTANTIATE_TEST_SUITE_P(AllScenes, ShippedSceneReference, ::testing::ValuesIn(shippedSceneNames()),
                         [](const auto& param) {
                           std::string name = param.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The sky alone (no objects): every pixel is the background, drawn by GL's skybox pass and by the
// reference's cube sampler along the view ray, looking along each axis and between them.
TEST(ReferenceSky, TheBackgroundIsTheRastersSkyToOneLevel) {
  for (const char* name : {"skybox-grid", "skybox"}) {
    Result<Scene> loaded = loadNamedScene(name);
    ASSERT_TRUE(loaded) << loaded.error();
    Scene scene = loaded.take();
    scene.objects.clear();
    auto demo = testing::makeDemo(scene);
    ASSERT_NE(demo->skyboxFaces(), nullptr);
    size_t pixels = 0;
    size_t exact = 0;
    size_t withinOne = 0;
    int worst = 0;
    const float views[][2] = {{0, 0},  {90, 0},   {180, 0}, {270, 0},
                              {0, 85}, {30, -85}, {45, 35}, {-135, -35}};
    for (const auto& view : views) {
      demo->camera().setAngles(view[0], view[1]);
      auto raster = renderFrameAt(*demo, 0.0, kSize, kSize);
      ASSERT_TRUE(raster) << raster.error();
      auto reference = renderReference(demo->scene(), meshesOf(*demo), demo->skyboxFaces(),
                                       demo->camera(), 0.0, kSize, kSize);
      ASSERT_TRUE(reference) << reference.error();
      const RgbaImage& a = raster.value();
      const RgbaImage& b = reference.value().image;
      for (size_t p = 0; p < a.pixels.size(); p += 4) {
        int d = 0;
        for (size_t c = 0; c < 3; ++c) {
          d = std::max(d, std::abs(static_cast<int>(a.pixels[p + c]) - b.pixels[p + c]));
        }
        ++pixels;
        exact += d == 0;
        withinOne += d <= 1;
        worst = std::max(worst, d);
      }
      if (view[0] == 45.0f) {
        testing::saveOutput(a, std::string("sky_raster_") + name + ".png");
        testing::saveOutput(b, std::string("sky_reference_") + name + ".png");
      }
    }
    const double fraction = static_cast<double>(withinOne) / static_cast<double>(pixels);
    std::printf("%s: %zu sky pixels, %.4f%% equal, %.4f%% within one level, worst %d\n", name,
                pixels, 100.0 * static_cast<double>(exact) / static_cast<double>(pixels),
                100.0 * fraction, worst);
    EXPECT_GE(fraction, 0.999) << name;
  }
}

// The mask and the directions cover every pixel of every kind of reflector.
TEST(ReferenceScenes, EveryMirrorGlassAndCubeTexturedPixelIsAReflectorPixel) {
  for (const char* name : {"skybox", "ex12-1"}) {
    auto demo = shippedDemo(name);
    auto frame = renderReference(demo->scene(), meshesOf(*demo), demo->skyboxFaces(),
                                 demo->camera(), 2.0, 128, 96);
    ASSERT_TRUE(frame) << frame.error();
    const ReferenceFrame& f = frame.value();
    size_t reflectors = 0;
    std::vector<size_t> perMaterial(4, 0);
    for (size_t p = 0; p < f.objectIds.size(); ++p) {
      const int id = f.objectIds[p];
      const bool reflector =
          id >= 0 && demo->scene().objects[static_cast<size_t>(id)].material != Material::Phong;
      EXPECT_EQ(f.reflectorMask[p] != 0, reflector) << name << " pixel " << p;
      reflectors += reflector;
      if (id >= 0) {
        ++perMaterial[static_cast<size_t>(demo->scene().objects[static_cast<size_t>(id)].material)];
      }
    }
    EXPECT_GT(reflectors, 0u) << name;
    ASSERT_EQ(f.lookupDirs.size(), reflectors);
    ASSERT_EQ(f.trueDirs.size(), reflectors);
    for (size_t k = 0; k < reflectors; ++k) {
      EXPECT_NEAR(glm::length(f.lookupDirs[k]), 1.0f, 1e-4f) << name << " " << k;
      EXPECT_NEAR(glm::length(f.trueDirs[k]), 1.0f, 1e-4f) << name << " " << k;
    }
    if (std::string(name) == "skybox") {
      EXPECT_GT(perMaterial[static_cast<size_t>(Material::Mirror)], 0u);
      EXPECT_GT(perMaterial[static_cast<size_t>(Material::Glass)], 0u);
    } else {
      EXPECT_GT(perMaterial[static_cast<size_t>(Material::CubeTextured)], 0u);
    }
  }
}

// Glass, sky, mirrors and the cube-textured cube: threads do not change a bit.
TEST(ReferenceScenes, ThreadCountDoesNotChangeThePixelsOfGlassAndSky) {
  for (const char* name : {"skybox", "ex12-1", "shared-probe"}) {
    auto demo = shippedDemo(name);
    auto one = renderReference(demo->scene(), meshesOf(*demo), demo->skyboxFaces(), demo->camera(),
                               3.0, 96, 64, 1);
    auto three = renderReference(demo->scene(), meshesOf(*demo), demo->skyboxFaces(),
                                 demo->camera(), 3.0, 96, 64, 3);
    ASSERT_TRUE(one) << one.error();
    ASSERT_TRUE(three) << three.error();
    EXPECT_EQ(one.value().image.pixels, three.value().image.pixels) << name;
    EXPECT_EQ(one.value().objectIds, three.value().objectIds) << name;
    EXPECT_EQ(one.value().lookupDirs, three.value().lookupDirs) << name;
    EXPECT_EQ(one.value().trueDirs, three.value().trueDirs) << name;
  }
}

}  // namespace
}  // namespace reflect
