// Diffuse light from the live probes in the frame planner (docs/rough.md, "Diffuse light from
// the probe"): each probe-lit object reads the nearest probe; a probe whose reflector is traced
// is still captured for its readers (colours only), and its irradiance is projected again only
// in frames that redraw one of its faces.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/cube_sampling.h"
#include "core/frame_planner.h"
#include "core/irradiance.h"
#include "core/irradiance_parallax.h"
#include "core/scene_file.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

using testing::boxAt;
using testing::mirrorAt;

PlannedObject litBoxAt(const glm::vec3& p) {
  PlannedObject o = boxAt(p);
  o.probeLit = true;
  return o;
}

CaptureContext searching(Search search) {
  CaptureContext c;
  c.accuracy.search = search;
  return c;
}

TEST(ProbeLightPlanning, EachReaderTakesTheNearestProbe) {
  FramePlanner planner;
  const FramePlan plan = planner.plan({mirrorAt({0, 0, 0}, 0.0f), mirrorAt({10, 0, 0}, 0.0f),
                                       litBoxAt({2, 0, 0}), litBoxAt({7, 0, 0}), boxAt({3, 0, 0})},
                                      searching(Search::Hierarchical), {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(plan.probes[0].diffuseReaders, std::vector<int>{2});
  EXPECT_EQ(plan.probes[1].diffuseReaders, std::vector<int>{3});
  EXPECT_EQ(plan.irradianceOf(2), &plan.probes[0]);
  EXPECT_EQ(plan.irradianceOf(3), &plan.probes[1]);
  EXPECT_EQ(plan.irradianceOf(4), nullptr);  // a Phong object with the constant ambient
  EXPECT_EQ(plan.irradianceOf(0), nullptr);
}

TEST(ProbeLightPlanning, ATracedReflectorsProbeStaysCapturedForItsReaders) {
  FramePlanner planner;
  const std::vector<PlannedObject> lit{mirrorAt({0, 0, 0}, 0.0f), litBoxAt({3, 0, 0})};
  const FramePlan plan = planner.plan(lit, searching(Search::Exact), {});
  ASSERT_EQ(plan.traced.size(), 1u);
  EXPECT_TRUE(plan.traces(0));
  ASSERT_EQ(plan.probes.size(), 1u);
  const ProbePlan& probe = plan.probes[0];
  EXPECT_TRUE(probe.lightOnly);
  EXPECT_EQ(probe.faces.size(), 6u);
  EXPECT_EQ(probe.layers, 1);
  EXPECT_TRUE(probe.plainLookupSuffices);  // no depths: nothing searches it
  EXPECT_TRUE(probe.projectIrradiance);
  EXPECT_EQ(plan.probeOf(0), nullptr);  // the mirror reads its rays, not this cube
  EXPECT_EQ(plan.layoutOf(0)->reflector, 0);
  EXPECT_EQ(plan.irradianceOf(1), &probe);

  // Without a reader the traced reflector has no probe at all.
  FramePlanner alone;
  const FramePlan plain =
      alone.plan({mirrorAt({0, 0, 0}, 0.0f), boxAt({3, 0, 0})}, searching(Search::Exact), {});
  EXPECT_TRUE(plain.probes.empty());
}

TEST(ProbeLightPlanning, IrradianceIsProjectedOnlyWhenAFaceWasRedrawn) {
  FramePlanner planner;
  std::vector<PlannedObject> lit{mirrorAt({0, 0, 0}, 0.0f), litBoxAt({3, 0, 0}), boxAt({0, 0, 3})};
  EXPECT_TRUE(planner.plan(lit, searching(Search::Exact), {}).probes[0].projectIrradiance);
  const FramePlan still = planner.plan(lit, searching(Search::Exact), {});
  ASSERT_EQ(still.probes.size(), 1u);
  EXPECT_TRUE(still.probes[0].faces.empty());
  EXPECT_FALSE(still.probes[0].projectIrradiance);
  // The reader is not in the probe it reads: moving it redraws nothing.
  lit[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(3, 1, 0));
  EXPECT_FALSE(planner.plan(lit, searching(Search::Exact), {}).probes[0].projectIrradiance);
  lit[2].model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 3));  // what it sees moves
  const FramePlan moved = planner.plan(lit, searching(Search::Exact), {});
  EXPECT_FALSE(moved.probes[0].faces.empty());
  EXPECT_TRUE(moved.probes[0].projectIrradiance);
}

TEST(ProbeLightPlanning, AnObjectsOwnProbeIsSmallAndLeavesItOut) {
  FramePlanner planner;
  PlannedObject own = litBoxAt({3, 0, 0});
  own.ownsLightProbe = true;
  const FramePlan plan = planner.plan({mirrorAt({0, 0, 0}, 0.0f), own, boxAt({3, 0, 3})},
                                      searching(Search::Exact), {});
  ASSERT_EQ(plan.probes.size(), 1u);  // the mirror is traced and has no reader
  const ProbePlan& probe = plan.probes[0];
  EXPECT_EQ(probe.reflector, 1);
  EXPECT_EQ(probe.diffuseReaders, std::vector<int>{1});
  EXPECT_TRUE(probe.lightOnly);
  EXPECT_EQ(probe.faceSize, kIrradianceFaceSize);
  EXPECT_EQ(probe.centre, glm::vec3(3, 0, 0));
  for (const FacePlan& face : probe.faces) {
    for (const DrawItem& d : face.draws) EXPECT_NE(d.object, 1);  // never itself
  }
  EXPECT_EQ(plan.probeOf(1), nullptr);
  EXPECT_EQ(plan.irradianceOf(1), &probe);
}

TEST(ProbeLightPlanning, TheCostOfATraceCountsTheCaptureItsReadersKeep) {
  const std::vector<PlannedObject> plain{mirrorAt({0, 0, 0}, 0.0f), boxAt({3, 0, 0})};
  const std::vector<PlannedObject> lit{mirrorAt({0, 0, 0}, 0.0f), litBoxAt({3, 0, 0})};
  const PlannerView view{{0, 0, 8}, 400.0f, 800.0f * 800.0f};
  FramePlanner a, b;
  a.plan(plain, searching(Search::Planned), {}, view);
  b.plan(lit, searching(Search::Planned), {}, view);
  ASSERT_EQ(a.choices().size(), 1u);
  ASSERT_EQ(b.choices().size(), 1u);
  EXPECT_DOUBLE_EQ(a.choices()[0].captureMs, b.choices()[0].captureMs);
  EXPECT_GT(b.choices()[0].traceMs, a.choices()[0].traceMs);
}

TEST(ProbeLightScene, AmbientKeyAndItsErrors) {
  const auto parse = [](const std::string& objects) {
    return parseSceneJson(R"({"objects": [)" + objects + "]}", "lit.json");
  };
  Result<Scene> ok = parse(R"({"mesh": "s.obj", "material": {"type": "mirror"}},
      {"mesh": "a.obj", "ambient": "probe"}, {"mesh": "b.obj", "ambient": "constant"})");
  ASSERT_TRUE(ok) << ok.error();
  EXPECT_FALSE(ok.value().objects[0].probeLit());
  EXPECT_TRUE(ok.value().objects[1].probeLit());
  EXPECT_EQ(ok.value().objects[2].ambient, Ambient::Constant);
  Result<Scene> own = parse(R"({"mesh": "a.obj", "ambient": "own-probe"})");
  ASSERT_TRUE(own) << own.error();  // its own probe is the live probe it reads
  EXPECT_TRUE(own.value().objects[0].ownsLightProbe());
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambient": "sky"})").error(),
            "lit.json: objects[0].ambient: expected \"constant\", \"probe\" or \"own-probe\"");
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambient": 1})").error(),
            "lit.json: objects[0].ambient: expected a string");
  EXPECT_EQ(
      parse(R"({"mesh": "a.obj", "material": {"type": "mirror"}, "ambient": "probe"})").error(),
      "lit.json: objects[0].ambient: \"probe\" lights a Phong object only");
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambient": "probe"})").error(),
            "lit.json: objects: an object with \"ambient\": \"probe\" needs a live probe to read "
            "(a mirror, glass or cube-textured object with a live environment)");
  // ambientRadius: the distance its surroundings are taken at; unset (the default, or
  // "measured"): measured from the probe's distances.
  EXPECT_FALSE(own.value().objects[0].ambientRadius.has_value());
  Result<Scene> near = parse(R"({"mesh": "a.obj", "ambient": "own-probe", "ambientRadius": 6},
      {"mesh": "b.obj", "ambient": "own-probe", "ambientRadius": "measured"})");
  ASSERT_TRUE(near) << near.error();
  EXPECT_EQ(near.value().objects[0].ambientRadius, 6.0f);
  EXPECT_FALSE(near.value().objects[1].ambientRadius.has_value());
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambient": "own-probe", "ambientRadius": -1})").error(),
            "lit.json: objects[0].ambientRadius: expected a number from 0 to 1000");
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambient": "own-probe", "ambientRadius": "far"})").error(),
            "lit.json: objects[0].ambientRadius: expected a number from 0 to 1000 or \"measured\"");
  EXPECT_EQ(parse(R"({"mesh": "a.obj", "ambientRadius": 6})").error(),
            "lit.json: objects[0].ambientRadius: needs \"ambient\": \"probe\" or \"own-probe\"");
}

// The direction a point reads the irradiance along: the normal with no radius or at the probe's
// centre; off the centre, towards where the normal's ray leaves the sphere of that radius. A
// point 1 above the centre, normal +X, radius 2: the ray leaves at (sqrt 3, 1, 0), so the
// direction is (sqrt 3, 1, 0) / 2; radius 1000: nearly the normal.
TEST(Irradiance, TheDirectionReadIsCorrectedForParallaxByTheRadius) {
  const glm::vec3 centre(2, -1, 0), x(1, 0, 0);
  const auto near = [](const glm::vec3& a, const glm::vec3& b) {
    return glm::length(a - b) < 1e-6f;
  };
  EXPECT_EQ(irradianceDirection(x, centre + glm::vec3(0, 1, 0), centre, 0.0f), x);
  EXPECT_TRUE(near(irradianceDirection(x, centre, centre, 2.0f), x));
  EXPECT_TRUE(near(irradianceDirection(x, centre + glm::vec3(0, 1, 0), centre, 2.0f),
                   glm::vec3(std::sqrt(3.0f) / 2.0f, 0.5f, 0.0f)));
  const glm::vec3 far = irradianceDirection(x, centre + glm::vec3(0, 1, 0), centre, 1000.0f);
  EXPECT_NEAR(far.x, 1.0f, 1e-6f);
  EXPECT_NEAR(far.y, 0.001f, 1e-6f);
  // A normal pointing back towards the centre reads the far side: (0, -1, 0) from 1 above, 2 out.
  EXPECT_TRUE(
      near(irradianceDirection(glm::vec3(0, -1, 0), centre + glm::vec3(0, 1, 0), centre, 2.0f),
           glm::vec3(0, -1, 0)));
  // Outside the sphere with the ray pointing away, the point itself: unit.
  const glm::vec3 outside = irradianceDirection(x, centre + glm::vec3(3, 0, 0), centre, 2.0f);
  EXPECT_TRUE(near(outside, x));
}

// The basis and its band factors: a uniform environment of radiance c gives E / pi = c in every
// direction; one lit from +Z alone (radiance 1 on the hemisphere z > 0) gives the clamped-cosine
// convolution, 1 at +Z, 1/2 sideways, 0 at -Z, within order 2's known error there.
RgbaImage filledFace(int size, uint8_t r, uint8_t g, uint8_t b) {
  RgbaImage face;
  face.width = face.height = size;
  for (int i = 0; i < size * size; ++i) face.pixels.insert(face.pixels.end(), {r, g, b, 255});
  return face;
}

TEST(Irradiance, UniformAndHalfLitEnvironments) {
  constexpr int kFace = 16;
  CubeFaces uniform, half;
  for (int f = 0; f < 6; ++f) {
    uniform[static_cast<size_t>(f)] = filledFace(kFace, 51, 102, 204);
    half[static_cast<size_t>(f)] = filledFace(kFace, 0, 0, 0);
    // The hemisphere z > 0 white: texel centres only, as the projection reads them.
    for (int y = 0; y < kFace; ++y) {
      for (int x = 0; x < kFace; ++x) {
        const glm::vec3 d = faceDirection(f, (x + 0.5f) / kFace, (y + 0.5f) / kFace);
        if (d.z <= 0.0f) continue;
        uint8_t* texel = &half[static_cast<size_t>(f)].pixels[4 * size_t(y * kFace + x)];
        texel[0] = texel[1] = texel[2] = 255;
      }
    }
  }
  const IrradianceCoefficients u = projectIrradiance(uniform);
  for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, -1, 0)}) {
    const glm::vec3 e = irradianceAt(u, n);
    EXPECT_NEAR(e.r, 0.2f, 1e-4f);
    EXPECT_NEAR(e.g, 0.4f, 1e-4f);
    EXPECT_NEAR(e.b, 0.8f, 1e-4f);
  }
  const IrradianceCoefficients h = projectIrradiance(half);
  EXPECT_NEAR(irradianceAt(h, {0, 0, 1}).r, 1.0f, 0.07f);
  EXPECT_NEAR(irradianceAt(h, {1, 0, 0}).r, 0.5f, 0.02f);
  EXPECT_NEAR(irradianceAt(h, {0, 0, -1}).r, 0.0f, 0.07f);
}

// The irradiance cube the faces view shows: the uniform environment's is the environment itself,
// texel for texel; the half-lit one's face centres are E / pi along each axis (+Z white, the four
// sideways faces half grey, -Z black, within order 2's error), and every face is size x size.
TEST(Irradiance, TheIrradianceCubeIsTheLightEachNormalTakes) {
  constexpr int kFace = 16, kShown = 8;
  CubeFaces uniform, half;
  for (int f = 0; f < 6; ++f) {
    uniform[static_cast<size_t>(f)] = filledFace(kFace, 51, 102, 204);
    half[static_cast<size_t>(f)] = filledFace(kFace, f == 4 ? 255 : 0, 0, 0);
  }
  const CubeFaces same = irradianceCube(projectIrradiance(uniform), kShown);
  for (const RgbaImage& face : same) {
    ASSERT_EQ(face.width, kShown);
    ASSERT_EQ(face.height, kShown);
    EXPECT_EQ(face.pixels, filledFace(kShown, 51, 102, 204).pixels);
  }
  // +Z's face alone lit, radiance 1: E / pi along +Z is that face's projected solid angle over
  // pi, 0.5541 (141.3 of 255, integrated numerically); along +X its half on that side is one of
  // four equal shares of the rest of +X's hemisphere, (1 - 0.5541) / 4 = 0.1115 (28.4); along -Z
  // nothing. Order 2 keeps each within 8.
  const CubeFaces lit = irradianceCube(projectIrradiance(half), kShown);
  const auto centre = [&lit](int face) {
    const RgbaImage& image = lit[static_cast<size_t>(face)];
    // The four texels round the centre, averaged: the face's axis direction.
    int sum = 0;
    for (int y : {kShown / 2 - 1, kShown / 2}) {
      for (int x : {kShown / 2 - 1, kShown / 2}) sum += image.at(x, y)[0];
    }
    return sum / 4.0;
  };
  EXPECT_NEAR(centre(4), 141.3, 8.0);
  for (int side : {0, 1, 2, 3}) EXPECT_NEAR(centre(side), 28.4, 8.0);
  EXPECT_NEAR(centre(5), 0.0, 8.0);
}

// The parallax taps (core/irradiance_parallax.h): nothing to add at the probe's centre, where every
// tap's ray is the probe's own, nor in surroundings of one colour, whatever their distances; a
// point moved towards a lit wall sees more of it, one moved away less.
TEST(IrradianceParallax, MovesTheLightToWhereThePointSeesIt) {
  constexpr int kFace = 32;
  CubeFaces plain, wall;
  for (int f = 0; f < 6; ++f) {
    plain[static_cast<size_t>(f)] = filledFace(kFace, 90, 120, 30);
    // +X (face 0) a white wall at distance 3 near-plane units (alpha 3 / 4), the rest dark sky.
    wall[static_cast<size_t>(f)] =
        f == 0 ? filledFace(kFace, 255, 255, 255) : filledFace(kFace, 0, 0, 0);
    for (size_t k = 3; k < plain[static_cast<size_t>(f)].pixels.size(); k += 4) {
      plain[static_cast<size_t>(f)].pixels[k] = static_cast<uint8_t>(40 + 30 * f);
      if (f == 0) wall[0].pixels[k] = 191;
    }
  }
  const glm::vec3 centre(1, 2, 3);
  const glm::vec3 x(1, 0, 0);
  for (const glm::vec3& n : {x, glm::vec3(0, 0.6f, 0.8f), glm::vec3(0, -1, 0)}) {
    // (normalize's rounding only)
    EXPECT_LT(glm::length(irradianceParallax(wall, centre, centre, n, 0.5f)), 1e-6f);
    EXPECT_EQ(irradianceParallax(plain, centre + glm::vec3(0.4f, -0.3f, 0.2f), centre, n, 0.5f),
              glm::vec3(0.0f));
  }
  // The wall is 1.5 from the centre (near plane 0.5): 0.75 nearer, it fills more of +X's view.
  const glm::vec3 towards = irradianceParallax(wall, centre + 0.75f * x, centre, x, 0.5f);
  const glm::vec3 away = irradianceParallax(wall, centre - 0.75f * x, centre, x, 0.5f);
  EXPECT_GT(towards.r, 0.02f);  // measured 0.025 and -0.0069
  EXPECT_LT(away.r, -0.005f);
}

}  // namespace
}  // namespace reflect
