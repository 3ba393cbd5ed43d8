// The face-use view of a real frame: at known pixels of the sphere its colour is the face that
// GL's face rule (core/cube_sampling.h cubeFaceCoord) gives the reflected ray, computed here in
// closed form from the camera and the sphere; and with the view on, the screen is that view.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>

#include <glm/gtc/matrix_inverse.hpp>

#include "app/face_use_view.h"
#include "core/cube_sampling.h"
#include "core/face_use.h"
#include "core/scene.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

// Large enough that the sphere lies between the view's title and its legend (7 lines of text
// over the bottom-left corner).
constexpr int kSize = 400;
constexpr int kLegendTop = kSize - 100;

// The reflected direction of the view ray through pixel (x, y)'s centre off the sphere (centre c,
// radius r), or nothing where the ray misses its inner 70% (the silhouette's facets are left out:
// the mesh is a tessellated sphere).
std::optional<glm::vec3> reflectedAt(const Demo& demo, int x, int y, const glm::vec3& c, float r) {
  const glm::mat4 inverse = glm::inverse(demo.camera().projection(1.0f) * demo.camera().view());
  const glm::vec2 ndc((x + 0.5f) / kSize * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize * 2.0f);
  const glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f);
  const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 o = glm::vec3(near) / near.w;
  const glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - o);
  const float b = glm::dot(o - c, d);
  const float h = b * b - (glm::dot(o - c, o - c) - r * r);
  if (h < (1.0f - 0.7f * 0.7f) * r * r) return std::nullopt;
  const glm::vec3 p = o + d * (-b - std::sqrt(h));
  return glm::reflect(d, glm::normalize(p - c));
}

// True when `d` is within ~5 degrees of a face boundary, where a facet's normal could tip it.
bool nearAFaceEdge(const glm::vec3& d) {
  std::array<float, 3> a{std::abs(d.x), std::abs(d.y), std::abs(d.z)};
  std::sort(a.begin(), a.end());
  return a[1] > 0.85f * a[2];
}

TEST(FaceUseView, EachSpherePixelHasTheColourOfTheFaceItsReflectionReads) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  AccuracySettings plain = demo->accuracySettings();
  plain.search = Search::Plain;  // the course's lookup: along the reflected ray itself
  ASSERT_EQ(demo->setAccuracySettings(plain), "");
  auto screen = OffscreenTarget::create(kSize, kSize);
  ASSERT_TRUE(screen);
  demo->frame(0.0, screen.value().framebuffer(), kSize, kSize, true);
  ASSERT_EQ(demo->lastPlan().probes.size(), 1u);
  const auto lookups = [&demo](unsigned target, int w, int h) {
    demo->renderLookupDirections(target, w, h);
  };
  const Result<RgbaImage> view =
      composeFaceUseView(demo->scene(), demo->lastPlan(), demo->insideViews().ages(), lookups,
                         screen.value().readPixels());
  ASSERT_TRUE(view) << view.error();
  testing::saveOutput(view.value(), "face_use_view.png");

  const SceneObject& sphere =
      demo->scene().objects[static_cast<size_t>(demo->scene().reflectorIndex())];
  const MeshData* mesh = demo->meshLevel(sphere.mesh, 0);
  ASSERT_NE(mesh, nullptr);
  const glm::mat4 model = demo->scene().modelMatrix(sphere, 0.0);
  const glm::vec3 centre(model * glm::vec4(mesh->bounds.centre(), 1.0f));
  const float radius = glm::length(glm::vec3(model * glm::vec4(1, 0, 0, 0))) * 0.5f *
                       (mesh->bounds.max.x - mesh->bounds.min.x);
  int checked = 0;
  std::set<int> facesSeen;
  for (int y = 20; y < kLegendTop; y += 3) {
    for (int x = 0; x < kSize; x += 3) {
      const std::optional<glm::vec3> r = reflectedAt(*demo, x, y, centre, radius);
      if (!r || nearAFaceEdge(*r)) continue;
      const int face = cubeFaceCoord(*r).face;
      const std::array<uint8_t, 4>& colour = kFaceUseColours[static_cast<size_t>(face)];
      ASSERT_TRUE(std::equal(colour.begin(), colour.end(), view.value().at(x, y)))
          << "pixel (" << x << ", " << y << ") should read face " << face;
      ++checked;
      facesSeen.insert(face);
    }
  }
  // Every third pixel of the sphere's inner 70%, away from the edges: hundreds of pixels, on every
  // face but the one behind it (-Z, seen only at the rim, which is left out).
  EXPECT_GT(checked, 300);  // 382 at this size
  EXPECT_EQ(facesSeen, (std::set<int>{0, 1, 2, 3, 4}));

  // With the view on, the screen shows it: the same pixels between the title and the legend
  // (the legend differs: a frame later, with no time passed, every face is a frame old).
  demo->setInsideView(InsideView::FaceUse, FacesChannel::Colour);
  demo->frame(0.0, screen.value().framebuffer(), kSize, kSize, true);
  const RgbaImage shown = screen.value().readPixels();
  for (int y = 20; y < kLegendTop; ++y) {
    ASSERT_TRUE(std::equal(shown.at(0, y), shown.at(0, y) + kSize * 4, view.value().at(0, y)))
        << "row " << y;
  }
}

}  // namespace
}  // namespace reflect
