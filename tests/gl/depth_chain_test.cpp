// The hierarchical search's depth chains, read back: level 0 holds the depth code of what each
// face saw (the same code the C++ side computes), and every level above bounds the one below.
#include <gtest/gtest.h>

#include <vector>

#include "core/cube_faces.h"
#include "core/depth_code.h"
#include "gfx/cube_capture_target.h"
#include "gfx/gl.h"
#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

// min and max codes of one level of one face, row-major from the bottom row.
std::vector<glm::uvec2> readChain(GLuint chain, int face, int level, int size) {
  FramebufferHandle fb(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, chain, level, face);
  std::vector<GLuint> rgba(static_cast<size_t>(size * size * 4));
  glReadPixels(0, 0, size, size, GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<glm::uvec2> out;
  for (size_t i = 0; i < rgba.size(); i += 4) out.push_back({rgba[i], rgba[i + 1]});
  return out;
}

TEST(DepthChain, LevelsBoundTheLevelBelowAndLevelZeroHoldsTheDepthCodes) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto target = OffscreenTarget::create(64, 64);
  ASSERT_TRUE(target);
  demo->frame(0.0, target.value().framebuffer(), 64, 64, true);
  const CubeCaptureTarget* probe = demo->renderer()->probeTarget(demo->scene().reflectorIndex());
  ASSERT_NE(probe, nullptr);
  ASSERT_TRUE(probe->format().depthChain);
  const int n = probe->faceSize();
  for (int face = 0; face < 6; ++face) {
    std::vector<glm::uvec2> below = readChain(probe->depthChain(0), face, 0, n);
    for (const glm::uvec2& c : below) ASSERT_LE(c.x, c.y);
    for (int level = 1; level <= probe->topLevel(); ++level) {
      const int size = std::max(n >> level, 1), belowSize = std::max(n >> (level - 1), 1);
      const std::vector<glm::uvec2> here = readChain(probe->depthChain(0), face, level, size);
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          glm::uvec2 expected(kInfiniteDepthCode, 0);
          for (int j = 2 * y; j < std::min(2 * y + 2, belowSize); ++j) {
            for (int i = 2 * x; i < std::min(2 * x + 2, belowSize); ++i) {
              const glm::uvec2 c = below[static_cast<size_t>(j * belowSize + i)];
              expected = {std::min(expected.x, c.x), std::max(expected.y, c.y)};
            }
          }
          ASSERT_EQ(here[static_cast<size_t>(y * size + x)], expected)
              << "face " << face << " level " << level << " texel " << x << "," << y;
        }
      }
      below = here;
    }
  }
  EXPECT_TRUE(checkGlError("depth chain test"));
}

}  // namespace
}  // namespace reflect
