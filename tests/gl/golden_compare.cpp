#include "golden_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/headless_frames.h"
#include "gl_fixture.h"

namespace reflect::testing {

std::vector<bool> reflectorMask(const Scene& scene, double seconds, int width, int height) {
  Scene flat = scene;
  flat.clearColour = glm::vec3(0.0f);
  flat.skybox = {};
  flat.light.ambient = 1.0f;
  flat.light.diffuse = 0.0f;
  flat.light.specular = 0.0f;
  bool any = false;
  for (SceneObject& o : flat.objects) {
    const bool reflects = o.material != Material::Phong;  // mirror, glass, Ex12-1's cube
    any |= reflects;
    o.colour = glm::vec3(reflects ? 1.0f : 0.0f);
    o.material = Material::Phong;
  }
  if (!any) return {};
  auto demo = makeDemo(std::move(flat));
  auto image = renderFrameAt(*demo, seconds, width, height);
  EXPECT_TRUE(image) << image.error();
  std::vector<bool> mask;
  if (!image) return mask;
  const RgbaImage& m = image.value();
  mask.resize(static_cast<size_t>(m.width) * static_cast<size_t>(m.height));
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = m.pixels[i * 4] > 128;
  return mask;
}

GoldenDifference goldenDifference(const RgbaImage& image, const RgbaImage& golden,
                                  const std::vector<bool>& mask) {
  GoldenDifference out;
  auto frame = compareImages(image, golden, kPixelTolerance);
  if (frame) out.frame = frame.value();
  if (mask.empty() || !frame) return out;
  ImageDifference r;
  size_t over = 0;
  double sum = 0.0;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    ++out.reflectorPixels;
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int(image.pixels[i * 4 + c]) - int(golden.pixels[i * 4 + c]));
      worst = std::max(worst, d);
      sum += d;
    }
    r.maxChannel = std::max(r.maxChannel, worst);
    over += worst > kPixelTolerance;
  }
  if (out.reflectorPixels == 0) return out;
  r.meanChannel = sum / (3.0 * static_cast<double>(out.reflectorPixels));
  r.fractionOver = static_cast<double>(over) / static_cast<double>(out.reflectorPixels);
  out.reflectors = r;
  return out;
}

namespace {

std::string describe(const std::string& name, const GoldenDifference& d) {
  char line[256];
  std::snprintf(line, sizeof line, "%s: frame max %d, mean %.4f, over %.5f", name.c_str(),
                d.frame.maxChannel, d.frame.meanChannel, d.frame.fractionOver);
  std::string out = line;
  if (d.reflectors) {
    std::snprintf(line, sizeof line, "; reflectors (%zu px) max %d, mean %.4f, over %.5f",
                  d.reflectorPixels, d.reflectors->maxChannel, d.reflectors->meanChannel,
                  d.reflectors->fractionOver);
    out += line;
  }
  return out;
}

}  // namespace

void expectMatchesGolden(const RgbaImage& image, const std::string& name,
                         const std::vector<bool>& mask) {
  const std::string output = saveOutput(image, name);
  const std::string golden = std::string(GOLDEN_DIR) + "/" + name;
  if (std::getenv("REFLECT_UPDATE_GOLDEN")) {
    // A retake says what it replaces: the difference from the golden it overwrites.
    auto old = readPng(golden);
    if (old && old.value().width == image.width && old.value().height == image.height) {
      std::printf("retake %s\n",
                  describe(name, goldenDifference(image, old.value(), mask)).c_str());
    } else {
      std::printf("retake %s: new\n", name.c_str());
    }
    std::filesystem::copy_file(output, golden, std::filesystem::copy_options::overwrite_existing);
  }
  auto expected = readPng(golden);
  ASSERT_TRUE(expected) << expected.error() << " (REFLECT_UPDATE_GOLDEN=1 writes it)";
  ASSERT_EQ(expected.value().width, image.width);
  ASSERT_EQ(expected.value().height, image.height);
  const GoldenDifference d = goldenDifference(image, expected.value(), mask);
  EXPECT_LE(d.frame.fractionOver, kMaxFractionOver) << "see " << output;
  EXPECT_LE(d.frame.meanChannel, kMaxMeanDifference) << "see " << output;
  if (!mask.empty()) {
    ASSERT_TRUE(d.reflectors) << name << ": the mask holds no reflector pixel";
    EXPECT_LE(d.reflectors->fractionOver, kMaxReflectorFractionOver) << "see " << output;
    EXPECT_LE(d.reflectors->meanChannel, kMaxReflectorMeanDifference) << "see " << output;
  }
  std::printf("%s\n", describe(name, d).c_str());
}

}  // namespace reflect::testing
