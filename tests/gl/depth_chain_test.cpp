// The hierarchical search's depths, read back: every pyramid cell bounds the level-0 texels it
// covers (their near codes' min, their far codes' and backs' max), texels past a face's edge
// hold nothing, and the capture's clear code is the C++ side's depthCode of the far plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/depth_code.h"
#include "gfx/cube_capture_target.h"
#include "gfx/gl.h"
#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gfx/scene_renderer.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

// An integer texture image, read as (R, G) per texel, or (B, A) with `second`, rows from the
// bottom.
// A framebuffer, bound, with `level` of `texture` (its `layer` when an array) as its colour.
FramebufferHandle bindLevel(GLuint texture, bool array, int layer, int level) {
  FramebufferHandle fb(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
  if (array) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture, level, layer);
  } else {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, level);
  }
  return fb;
}

std::vector<glm::uvec2> readCodes(GLuint texture, bool array, int layer, int level, int width,
                                  int height, bool second = false) {
  const FramebufferHandle fb = bindLevel(texture, array, layer, level);
  std::vector<GLuint> rgba(static_cast<size_t>(width * height * 4));
  glReadPixels(0, 0, width, height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<glm::uvec2> out;
  const size_t c = second ? 2 : 0;
  for (size_t i = 0; i < rgba.size(); i += 4) out.push_back({rgba[i + c], rgba[i + c + 1]});
  return out;
}

// `faces`: bit f to check face f's tiles.
void checkPyramid(const CubeCaptureTarget& probe, int layer, unsigned faces = 0x3fu) {
  const int n = probe.faceSize(), top = probe.topLevel(), tile = 1 << top;
  const bool backs = layer == 0 && probe.format().layers == 2;
  for (int level = 0; level <= top; ++level) {
    const int t = tile >> level, span = 1 << level;
    const std::vector<glm::uvec2> pyramid =
        readCodes(probe.pyramid(), false, 0, level, 6 * t, t, layer == 1);
    for (int face = 0; face < 6; ++face) {
      if (!(faces & (1u << face))) continue;
      const std::vector<glm::uvec2> base = readCodes(probe.faceDepths(layer), true, face, 0, n, n);
      std::vector<glm::uvec2> back;
      if (backs) back = readCodes(probe.backs(), true, face, 0, n, n);
      for (int y = 0; y < t; ++y) {
        for (int x = 0; x < t; ++x) {
          glm::uvec2 expected(kInfiniteDepthCode, 0);
          for (int j = y * span; j < std::min((y + 1) * span, n); ++j) {
            for (int i = x * span; i < std::min((x + 1) * span, n); ++i) {
              const size_t k = static_cast<size_t>(j * n + i);
              glm::uvec2 c = base[k];
              ASSERT_LE(c.x, c.y) << "level 0 texel " << i << "," << j;
              if (backs) c.y = std::max(c.y, back[k].x);
              expected = {std::min(expected.x, c.x), std::max(expected.y, c.y)};
            }
          }
          ASSERT_EQ(pyramid[static_cast<size_t>(y * 6 * t + face * t + x)], expected)
              << "layer " << layer << " face " << face << " level " << level << " cell " << x << ","
              << y;
        }
      }
    }
  }
}

// One frame of `demo` at t = 0 into a size x size target; its first reflector's probe, or null.
const CubeCaptureTarget* probeAfterOneFrame(Demo& demo, int size) {
  auto target = OffscreenTarget::create(size, size);
  EXPECT_TRUE(target) << target.error();
  if (!target) return nullptr;
  demo.frame(0.0, target.value().framebuffer(), size, size, true);
  return demo.renderer()->probeTarget(demo.scene().reflectorIndex());
}

void checkScene(Scene scene, int layersExpected) {
  auto demo = testing::makeCapturingDemo(scene);
  const CubeCaptureTarget* probe = probeAfterOneFrame(*demo, 64);
  ASSERT_NE(probe, nullptr);
  ASSERT_TRUE(probe->format().depthChain);
  ASSERT_EQ(probe->format().layers, layersExpected);
  for (int layer = 0; layer < probe->format().layers; ++layer) checkPyramid(*probe, layer);
  EXPECT_TRUE(checkGlError("depth pyramid test"));
}

TEST(DepthPyramid, EveryCellBoundsTheTexelsItCoversInBothLayers) {
  checkScene(makeDynamicReflectionScene(), 2);
}

TEST(DepthPyramid, AFaceSizeThatIsNoPowerOfTwoLeavesThePaddingEmpty) {
  Scene scene = makeDynamicReflectionScene();
  scene.capture.faceSize = 100;  // tiles of 128 at level 0: 28 texels a row are padding
  checkScene(scene, 2);
}

TEST(DepthPyramid, WhereNothingWasDrawnTheCodeIsTheFarPlanesAsTheCSideComputesIt) {
  Scene scene = makeDynamicReflectionScene();
  scene.capture.faceSize = 16;
  auto demo = testing::makeCapturingDemo(scene);
  const CubeCaptureTarget* probe = probeAfterOneFrame(*demo, 16);
  ASSERT_NE(probe, nullptr);
  // Straight up (+Y) from the sphere's centre there is nothing: the clear value.
  const std::vector<glm::uvec2> up = readCodes(probe->faceDepths(0), true, 2, 0, 16, 16);
  const uint32_t far = depthCode(scene.capture.far / scene.capture.near);
  EXPECT_EQ(up[8 * 16 + 8], glm::uvec2(far, far));
}

// The second layer is the nearest surface behind the first object, not anything past some
// margin: a wall 0.2 deep at x = 2.9..3.1 in front of the probe (+X), and a small one at
// x = 4.3..4.5 behind it (small: a back face counts as the front object's back when it lies
// within the drawn object's size of the front). Near plane 0.1, so the second wall's front lies
// 530 codes behind the first wall's far end (its front plus the thickness the capture assumes).
// The centre texel of face +X stores the first wall's front in layer one and the second wall's
// in layer two, each to a code or two of the C++ side's depthCode. (The peel counts codes
// within two of the first layer's far end as the same surface; a slack of 530 codes or more
// loses the second wall, as tools/mutate.sh's peel-slack does.)
TEST(DepthPyramid, TheSecondLayerIsTheNearestSurfaceBehindTheFirst) {
  Scene scene;
  scene.name = "two walls";
  SceneObject sphere;
  sphere.mesh = "sphere.obj";
  sphere.placement = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));  // radius 1.27, at the origin
  sphere.material = Material::Mirror;
  const auto wall = [](float x, float depth, float side) {
    SceneObject o;
    o.mesh = "cube.obj";  // [-1, 1]^3
    o.placement = glm::scale(glm::translate(glm::mat4(1.0f), {x, 0.0f, 0.0f}),
                             {0.5f * depth, 0.5f * side, 0.5f * side});
    return o;
  };
  scene.objects = {sphere, wall(3.0f, 0.2f, 2.0f), wall(4.4f, 0.2f, 1.0f)};
  scene.capture.faceSize = 16;
  scene.capture.near = 0.1f;
  auto demo = testing::makeCapturingDemo(scene);
  const CubeCaptureTarget* probe = probeAfterOneFrame(*demo, 16);
  ASSERT_NE(probe, nullptr);
  ASSERT_EQ(probe->format().layers, 2);
  const float near = scene.capture.near;
  const size_t centre = 8 * 16 + 8;
  const auto codeAt = [&](int layer) {
    return static_cast<int>(readCodes(probe->faceDepths(layer), true, 0, 0, 16, 16)[centre].x);
  };
  EXPECT_NEAR(codeAt(0), static_cast<int>(depthCode(2.9 / near)), 2);
  EXPECT_NEAR(codeAt(1), static_cast<int>(depthCode(4.3 / near)), 2);
  EXPECT_TRUE(checkGlError("second layer test"));
}

// Only the faces a frame recaptures get their tiles rebuilt (issue 11: the chain is built after
// a face is captured, only for the faces recaptured). Every cell is marked at the top level (one
// cell a face) before each frame: the faces recaptured must come out rebuilt, and the others keep
// the mark, which no rebuild could leave. Each frame the whole pyramid must still bound its
// level-0 texels.
TEST(DepthPyramid, OnlyTheFacesRecapturedAreRebuilt) {
  Scene scene = makeDynamicReflectionScene();
  scene.capture.faceSize = 32;
  auto demo = testing::makeCapturingDemo(scene);
  auto target = OffscreenTarget::create(32, 32);
  ASSERT_TRUE(target);
  const glm::uvec2 mark(12345u, 54321u);
  int partialFrames = 0;
  for (int frame = 0; frame < 8; ++frame) {
    const CubeCaptureTarget* probe = demo->renderer()->probeTarget(demo->scene().reflectorIndex());
    if (probe) {
      const FramebufferHandle fb = bindLevel(probe->pyramid(), false, 0, probe->topLevel());
      const GLuint values[4] = {mark.x, mark.y, mark.x, mark.y};
      glClearBufferuiv(GL_COLOR, 0, values);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    const FrameStats& stats =
        demo->frame(frame == 0 ? 0.0 : 0.25, target.value().framebuffer(), 32, 32, true);
    ASSERT_TRUE(stats.error.empty()) << stats.error;
    probe = demo->renderer()->probeTarget(demo->scene().reflectorIndex());
    ASSERT_NE(probe, nullptr);
    const std::vector<glm::uvec2> top =
        readCodes(probe->pyramid(), false, 0, probe->topLevel(), 6, 1);
    const int kept = static_cast<int>(std::count(top.begin(), top.end(), mark));
    std::printf("frame %d: %d faces captured, %d marks kept\n", frame, stats.facesCaptured, kept);
    // The faces the plan captured, as a mask.
    unsigned planned = 0;
    ASSERT_EQ(demo->lastPlan().probes.size(), 1u);
    for (const FacePlan& f : demo->lastPlan().probes[0].faces) planned |= 1u << f.face;
    if (frame == 0) {
      EXPECT_EQ(stats.facesCaptured, 6);  // the first frame: no mark yet, every face drawn
      EXPECT_EQ(kept, 0);
    } else {
      EXPECT_EQ(kept, 6 - stats.facesCaptured) << "frame " << frame;
      partialFrames += stats.facesCaptured > 0 && stats.facesCaptured < 6;
      // The faces rebuilt (no mark left) are exactly the faces captured, and they bound their
      // texels at every level.
      unsigned rebuilt = 0;
      for (size_t f = 0; f < 6; ++f) rebuilt |= top[f] == mark ? 0u : 1u << f;
      EXPECT_EQ(rebuilt, planned) << "frame " << frame;
      for (int layer = 0; layer < probe->format().layers; ++layer) {
        checkPyramid(*probe, layer, rebuilt);
      }
    }
  }
  EXPECT_GT(partialFrames, 0);  // not vacuous: some frames recaptured only some faces
  EXPECT_TRUE(checkGlError("partial pyramid test"));
}

}  // namespace
}  // namespace reflect
