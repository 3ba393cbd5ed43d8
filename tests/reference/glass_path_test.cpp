// The reference's path through glass (traceGlass, the code renderReference uses) against what
// is known exactly: a sphere's exit point and direction (a ball lens, in closed form) and the
// total internal reflection of a right-angle prism. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/obj_loader.h"
#include "reference/reference_renderer.h"

namespace reflect {
namespace {

constexpr float kPi = 3.14159265358979f;

// A UV sphere of radius 1 at the origin, `slices` around and `stacks` from pole to pole, with
// exact normals (the vertex positions).
MeshData uvSphere(int slices, int stacks) {
  MeshData mesh;
  mesh.name = "uv sphere";
  for (int j = 0; j <= stacks; ++j) {
    const float polar = kPi * static_cast<float>(j) / static_cast<float>(stacks);
    for (int i = 0; i <= slices; ++i) {
      const float azimuth = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
      const glm::vec3 p(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                        std::sin(polar) * std::sin(azimuth));
      mesh.vertices.push_back({p, p});
    }
  }
  const auto at = [slices](int i, int j) { return static_cast<uint32_t>(j * (slices + 1) + i); };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

// The exact path through a sphere (centre c, radius r, index n) of the ray o + t d.
struct AnalyticPath {
  glm::dvec3 entry, exit, out;
};
AnalyticPath ballLens(const glm::dvec3& c, double r, double n, const glm::dvec3& o,
                      const glm::dvec3& dIn) {
  const glm::dvec3 d = glm::normalize(dIn);
  const glm::dvec3 oc = o - c;
  const double b = glm::dot(oc, d);
  const double t = -b - std::sqrt(b * b - (glm::dot(oc, oc) - r * r));
  AnalyticPath p;
  p.entry = o + t * d;
  const glm::dvec3 inside = glm::refract(d, (p.entry - c) / r, 1.0 / n);
  // The chord from the entry along `inside`: |entry - c + s inside| = r again at s = -2 (e - c).T.
  p.exit = p.entry - 2.0 * glm::dot(p.entry - c, inside) * inside;
  p.out = glm::refract(inside, -(p.exit - c) / r, n);  // never total: the path is symmetric
  return p;
}

// How far the mesh's facets sink below the sphere they approximate (centre c, radius r).
double facetDepth(const MeshData& mesh, const glm::mat4& model, const glm::dvec3& c, double r) {
  double deepest = 0.0;
  for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    glm::dvec3 v[3];
    for (int e = 0; e < 3; ++e) {
      v[e] = glm::dvec3(model * glm::vec4(mesh.vertices[mesh.indices[k + e]].position, 1.0f));
    }
    const glm::dvec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
    deepest = std::max(deepest, r - glm::length(centroid - c));
  }
  return deepest;
}

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

// Rays from the eye towards the sphere at impact parameters 0 .. 0.95 r, above, beside and below.
std::vector<glm::dvec3> targets(const glm::dvec3& c, double r) {
  std::vector<glm::dvec3> points;
  for (double f : {0.0, 0.2, 0.5, 0.8, 0.95}) {
    for (const glm::dvec3& side :
         {glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(-0.6, -0.8, 0)}) {
      points.push_back(c + f * r * side);
    }
  }
  return points;
}

// One ray through `mesh` (traceGlass with a single ray).
Result<GlassPath> traceOne(const MeshData& mesh, const glm::mat4& model, float ior,
                           const glm::vec3& origin, const glm::vec3& direction) {
  auto paths = traceGlass(mesh, model, ior, {GlassRay{origin, direction}});
  if (!paths) return Result<GlassPath>::failure(paths.error());
  return paths.value().at(0);
}

// The largest distance between traced exits and the ball lens's (in units of r), and the largest
// angle between the directions out (degrees).
struct Agreement {
  double point = 0.0;
  double angle = 0.0;
};
Agreement againstBallLens(const MeshData& sphere, const glm::mat4& model, const glm::dvec3& c,
                          double r, double n) {
  const glm::dvec3 eye(0.0, 1.0, 7.0);
  std::vector<GlassRay> rays;
  for (const glm::dvec3& target : targets(c, r)) {
    rays.push_back({glm::vec3(eye), glm::vec3(target - eye)});
  }
  auto paths = traceGlass(sphere, model, static_cast<float>(n), rays);
  EXPECT_TRUE(paths) << paths.error();
  Agreement worst;
  if (!paths) return worst;
  for (size_t k = 0; k < rays.size(); ++k) {
    const GlassPath& path = paths.value()[k];
    const AnalyticPath exact =
        ballLens(c, r, n, glm::dvec3(rays[k].origin), glm::dvec3(rays[k].direction));
    EXPECT_TRUE(path.entered) << k;
    EXPECT_TRUE(path.exited) << k;
    EXPECT_EQ(path.internalReflections, 0) << k;
    worst.point = std::max(worst.point, glm::length(glm::dvec3(path.exit) - exact.exit) / r);
    worst.angle = std::max(worst.angle, angleDegrees(glm::dvec3(path.direction), exact.out));
  }
  return worst;
}

TEST(GlassPath, AFineSphereLeavesWhereTheBallLensDoes) {
  const MeshData sphere = uvSphere(512, 256);
  const glm::vec3 centre(0.3f, 0.25f, -0.5f);
  const float radius = 0.7f;
  const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(radius));
  const double depth = facetDepth(sphere, model, centre, radius) / radius;
  for (double n : {1.0, 1.309, 1.52, 2.42}) {
    const Agreement a = againstBallLens(sphere, model, centre, radius, n);
    std::printf(
        "index %.3f, fine sphere (facets %.1e r deep): exit point within %.1e r, direction "
        "within %.4f deg\n",
        n, depth, a.point, a.angle);
    EXPECT_LT(a.point, 5e-4) << n;  // a few times the facets' depth, 3.4e-5 r
    EXPECT_LT(a.angle, 0.05) << n;
  }
  EXPECT_LT(depth, 5e-5);
}

TEST(GlassPath, TheGlassSphereSceneLeavesWhereTheBallLensDoesToItsTessellation) {
  auto loaded = loadObjFile(std::string(MODEL_DIR) + "/sphere.obj");
  ASSERT_TRUE(loaded) << loaded.error();
  const MeshData& sphere = loaded.value().mesh;
  // glass-sphere.json: sphere.obj at scale 0.5; its vertices lie on a sphere around the bounds'
  // centre.
  const glm::mat4 model = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  const glm::dvec3 centre(glm::vec3(model * glm::vec4(sphere.bounds.centre(), 1.0f)));
  double radius = 0.0;
  for (const Vertex& v : sphere.vertices) {
    radius += glm::length(glm::dvec3(model * glm::vec4(v.position, 1.0f)) - centre);
  }
  radius /= static_cast<double>(sphere.vertices.size());
  const double depth = facetDepth(sphere, model, centre, radius) / radius;
  const Agreement a = againstBallLens(sphere, model, centre, radius, 1.52);
  std::printf(
      "sphere.obj (radius %.4f, facets up to %.4f r deep): exit within %.4f r, direction within "
      "%.2f deg\n",
      radius, depth, a.point, a.angle);
  // A coarse mesh (320 faces): the exit differs from the ideal sphere's by its tessellation.
  EXPECT_LT(a.point, 4.0 * depth);
}

// A right-angle glass prism, 45-45-90: legs on the planes x = 0 and y = 0, the hypotenuse from
// (1, 0) to (0, 1), from z = 0 to 1. Flat faces (a vertex per face corner).
MeshData prism() {
  MeshData mesh;
  mesh.name = "prism";
  const auto quad = [&mesh](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const glm::vec3& p : {a, b, c, d}) mesh.vertices.push_back({p, n});
    mesh.indices.insert(mesh.indices.end(),
                        {first, first + 1, first + 2, first, first + 2, first + 3});
  };
  const auto triangle = [&mesh](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 n) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const glm::vec3& p : {a, b, c}) mesh.vertices.push_back({p, n});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
  };
  quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, -1, 0});  // the leg y = 0
  quad({0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {-1, 0, 0});  // the leg x = 0
  const glm::vec3 hypotenuse = glm::normalize(glm::vec3(1, 1, 0));
  quad({1, 0, 0}, {0, 1, 0}, {0, 1, 1}, {1, 0, 1}, hypotenuse);
  triangle({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1});
  triangle({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {0, 0, 1});
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

TEST(GlassPath, ARightAnglePrismReflectsTotallyAtItsHypotenuse) {
  const MeshData mesh = prism();
  // Straight up into the leg y = 0 at x = 0.3: the hypotenuse at 45 degrees, past glass's
  // critical angle (41.1 degrees for 1.52): reflected to -x, out through the leg x = 0 at
  // (0, 0.7), square to it.
  auto path = traceOne(mesh, glm::mat4(1.0f), 1.52f, {0.3f, -1.0f, 0.5f}, {0, 1, 0});
  ASSERT_TRUE(path) << path.error();
  const GlassPath& p = path.value();
  ASSERT_TRUE(p.entered);
  EXPECT_NEAR(glm::length(p.entry - glm::vec3(0.3f, 0.0f, 0.5f)), 0.0f, 1e-5f);
  EXPECT_EQ(p.internalReflections, 1);
  EXPECT_TRUE(p.exited);
  EXPECT_NEAR(glm::length(p.exit - glm::vec3(0.0f, 0.7f, 0.5f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(p.direction - glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);

  // Below the critical angle (index 1.3: 50.3 degrees) the same ray leaves through the
  // hypotenuse, bent away from its normal: sin(out) = 1.3 sin(45 degrees).
  auto weak = traceOne(mesh, glm::mat4(1.0f), 1.3f, {0.3f, -1.0f, 0.5f}, {0, 1, 0});
  ASSERT_TRUE(weak) << weak.error();
  EXPECT_EQ(weak.value().internalReflections, 0);
  EXPECT_TRUE(weak.value().exited);
  EXPECT_NEAR(glm::length(weak.value().exit - glm::vec3(0.3f, 0.7f, 0.5f)), 0.0f, 1e-5f);
  const float out = std::asin(1.3f * std::sin(kPi / 4.0f));
  EXPECT_NEAR(std::acos(glm::dot(weak.value().direction, glm::normalize(glm::vec3(1, 1, 0)))), out,
              1e-4f);
}

// An axis-aligned glass box from `lo` to `hi`, flat faces.
MeshData box(const glm::vec3& lo, const glm::vec3& hi) {
  MeshData mesh;
  mesh.name = "box";
  const glm::vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 centre = (lo + hi) * 0.5f;
  const glm::vec3 half = (hi - lo) * 0.5f;
  for (const glm::vec3& n : normals) {
    // The face's corners: centre + (n +- u +- v) * half, with u x v = n (counter-clockwise out).
    const glm::vec3 u = std::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(n, u);
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const glm::vec2& s :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      mesh.vertices.push_back({centre + (n + s.x * u + s.y * v) * half, n});
    }
    mesh.indices.insert(mesh.indices.end(),
                        {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  mesh.bounds = computeBounds(mesh.vertices);
  return mesh;
}

TEST(GlassPath, ALightPipeTrapsTheRayUntilTheLimit) {
  // A glass rod 100 long and 1 wide, entered through the centre of its end at 60 degrees from its
  // axis: inside, asin(sin 60 / 1.52) = 34.7 degrees from the axis, so 55.3 degrees on each side
  // wall, past the critical angle (41.1): an optical fibre. It bounces between y = +-0.5 every
  // 1 / tan(34.7) = 1.44 units; the reference follows kMaxInternalReflections of them, then lets
  // the ray go on from the last wall along its last direction.
  const MeshData rod = box({0.0f, -0.5f, -0.5f}, {100.0f, 0.5f, 0.5f});
  const float entryAngle = kPi / 3.0f;
  const glm::vec3 direction(std::cos(entryAngle), std::sin(entryAngle), 0.0f);
  auto path = traceOne(rod, glm::mat4(1.0f), 1.52f, -direction, direction);
  ASSERT_TRUE(path) << path.error();
  const GlassPath& p = path.value();
  ASSERT_TRUE(p.entered);
  EXPECT_NEAR(glm::length(p.entry), 0.0f, 1e-5f);
  EXPECT_FALSE(p.exited);
  EXPECT_EQ(p.internalReflections, kMaxInternalReflections);
  const float inside = std::asin(std::sin(entryAngle) / 1.52f);
  const float walls = static_cast<float>(kMaxInternalReflections);
  // The k-th reflection is at x = (0.5 + (k - 1)) / tan(inside), on y = +0.5 for odd k.
  const glm::vec3 last((0.5f + (walls - 1.0f)) / std::tan(inside),
                       kMaxInternalReflections % 2 == 1 ? 0.5f : -0.5f, 0.0f);
  EXPECT_NEAR(glm::length(p.exit - last), 0.0f, 1e-4f);
  // After an even number of reflections the ray runs as it entered.
  const glm::vec3 along(std::cos(inside),
                        kMaxInternalReflections % 2 == 1 ? -std::sin(inside) : std::sin(inside),
                        0.0f);
  EXPECT_NEAR(glm::length(p.direction - along), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace reflect
