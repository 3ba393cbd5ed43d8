#include "golden_compare.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "gl_fixture.h"

namespace reflect::testing {

void expectMatchesGolden(const RgbaImage& image, const std::string& name) {
  const std::string output = saveOutput(image, name);
  const std::string golden = std::string(GOLDEN_DIR) + "/" + name;
  if (std::getenv("REFLECT_UPDATE_GOLDEN")) {
    std::filesystem::copy_file(output, golden, std::filesystem::copy_options::overwrite_existing);
  }
  auto expected = readPng(golden);
  ASSERT_TRUE(expected) << expected.error() << " (REFLECT_UPDATE_GOLDEN=1 writes it)";
  auto d = compareImages(image, expected.value(), kPixelTolerance);
  ASSERT_TRUE(d) << d.error();
  EXPECT_LE(d.value().fractionOver, kMaxFractionOver) << "see " << output;
  EXPECT_LE(d.value().meanChannel, kMaxMeanDifference) << "see " << output;
  std::printf("%s: max %d, mean %.4f, over %.5f\n", name.c_str(), d.value().maxChannel,
              d.value().meanChannel, d.value().fractionOver);
}

}  // namespace reflect::testing
