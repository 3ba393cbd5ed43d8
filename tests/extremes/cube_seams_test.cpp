// Reflected directions exactly on cube-map edges and corners. Six walls of different colours
// fill the six faces of the live cube map; a lookup on an edge must return one of the two
// faces' colours or a blend of them (three at a corner), never black or anything else. And a
// uniform environment must come back exactly, seams and corners included.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "app/headless_frames.h"
#include "core/obj_loader.h"
#include "extremes_util.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

// Face k's wall colour (GL order +X, -X, +Y, -Y, +Z, -Z): 0/1 channels, exact in bytes.
const glm::vec3 kWallColours[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                   {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};

int faceOf(int axis, float sign) {
  return axis * 2 + (sign > 0 ? 0 : 1);
}

// The mirror sphere placed so that its probe (its bounds' centre) is exactly the origin.
SceneObject mirrorAtOrigin() {
  auto sphere = loadObjFile(builtInModelDirectory() + "/sphere.obj");
  EXPECT_TRUE(sphere) << sphere.error();
  const glm::vec3 centre = sphere ? sphere.value().mesh.bounds.centre() : glm::vec3(0.0f);
  return extremes::mirrorObject("sphere.obj",
                                glm::translate(glm::mat4(1.0f), -0.5f * centre) *
                                    glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)),
                                {1, 1, 1});
}

// quad.obj is the 2 x 2 square y = 0. Each wall is that square scaled to 10.1 x 10.1 and turned
// to face the origin from 5 units along its axis: the walls overlap past the cube's edges, so
// the depth test decides each texel exactly on the diagonal planes between faces.
glm::mat4 wallPlacement(int face) {
  const int axis = face / 2;
  const float sign = face % 2 == 0 ? 1.0f : -1.0f;
  glm::mat4 turn(1.0f);
  if (axis == 0) turn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1));
  if (axis == 2) turn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
  glm::vec3 offset(0.0f);
  offset[axis] = 5.0f * sign;
  return glm::translate(glm::mat4(1.0f), offset) * turn *
         glm::scale(glm::mat4(1.0f), glm::vec3(5.05f, 1.0f, 5.05f));
}

// Smallest distance (in byte levels) from `c` to a convex combination of two or three colours,
// by a search over the weights in steps of 1/120.
float distanceToBlend(const glm::u8vec3& c, const std::vector<glm::vec3>& candidates) {
  constexpr int kSteps = 120;
  const glm::vec3 got(c);
  const glm::vec3 third = candidates.size() == 3 ? candidates[2] : candidates[1];
  float best = 1e9f;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; i + j <= kSteps; ++j) {
      const float a = float(i) / kSteps, b = float(j) / kSteps;
      const glm::vec3 blend = a * candidates[0] + b * candidates[1] + (1.0f - a - b) * third;
      best = std::min(best, glm::length(got - 255.0f * blend));
    }
  }
  return best;
}

struct Lookup {
  glm::vec3 direction;
  std::vector<int> faces;  // the faces whose colours may blend there
  std::string name;
};

std::vector<Lookup> edgeAndCornerLookups() {
  std::vector<Lookup> lookups;
  const char* axisName = "xyz";
  // The 12 edges, exactly on them and a hair to either side.
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      for (float sa : {1.0f, -1.0f}) {
        for (float sb : {1.0f, -1.0f}) {
          for (float lean : {0.0f, 1e-4f, -1e-4f}) {
            glm::vec3 d(0.0f);
            d[a] = sa * (1.0f + lean);
            d[b] = sb;
            d[3 - a - b] = 0.3f * lean * 1e3f;  // off the edge's midpoint too
            lookups.push_back({d,
                               {faceOf(a, sa), faceOf(b, sb)},
                               std::string(sa > 0 ? "+" : "-") + axisName[a] +
                                   (sb > 0 ? "+" : "-") + axisName[b] + " lean " +
                                   std::to_string(lean)});
          }
        }
      }
    }
  }
  // The 8 corners.
  for (float sx : {1.0f, -1.0f}) {
    for (float sy : {1.0f, -1.0f}) {
      for (float sz : {1.0f, -1.0f}) {
        lookups.push_back({{sx, sy, sz},
                           {faceOf(0, sx), faceOf(1, sy), faceOf(2, sz)},
                           "corner " + std::to_string(int(sx)) + "," + std::to_string(int(sy)) +
                               "," + std::to_string(int(sz))});
      }
    }
  }
  return lookups;
}

TEST(CubeSeams, EdgeAndCornerLookupsBlendOnlyTheFacesThatMeetThere) {
  Scene scene;
  extremes::useFlatLighting(scene);
  scene.clearColour = glm::vec3(0.0f);  // a gap between walls would read black
  scene.objects.push_back(mirrorAtOrigin());
  for (int face = 0; face < 6; ++face) {
    scene.objects.push_back(
        extremes::phongObject("quad.obj", wallPlacement(face), kWallColours[face]));
  }
  auto demo = testing::makeCapturingDemo(scene);
  ASSERT_TRUE(renderFrameAt(*demo, 0.0, 32, 32));  // runs the capture

  // Face centres first: each is exactly its wall.
  std::vector<glm::vec3> centres;
  for (int face = 0; face < 6; ++face) {
    glm::vec3 d(0.0f);
    d[face / 2] = face % 2 == 0 ? 1.0f : -1.0f;
    centres.push_back(d);
  }
  const auto atCentres = extremes::sampleCube(demo->environmentTexture(), centres);
  ASSERT_EQ(atCentres.size(), 6u);
  for (int face = 0; face < 6; ++face) {
    EXPECT_EQ(atCentres[static_cast<size_t>(face)], extremes::toBytes(kWallColours[face]))
        << "face " << face;
  }

  const std::vector<Lookup> lookups = edgeAndCornerLookups();
  std::vector<glm::vec3> directions;
  for (const Lookup& l : lookups) directions.push_back(l.direction);
  const auto sampled = extremes::sampleCube(demo->environmentTexture(), directions);
  ASSERT_EQ(sampled.size(), lookups.size());
  float worst = 0.0f;
  for (size_t i = 0; i < lookups.size(); ++i) {
    std::vector<glm::vec3> candidates;
    for (int face : lookups[i].faces) candidates.push_back(kWallColours[face]);
    const float d = distanceToBlend(sampled[i], candidates);
    worst = std::max(worst, d);
    EXPECT_LE(d, 3.0f) << lookups[i].name << ": got " << extremes::describe(sampled[i]);
    EXPECT_NE(sampled[i], glm::u8vec3(0)) << lookups[i].name;
  }
  std::printf(
      "%zu edge and corner lookups: worst distance from a blend of the meeting faces %.2f levels\n",
      lookups.size(), static_cast<double>(worst));
}

TEST(CubeSeams, UniformEnvironmentHasNoSeams) {
  Scene scene;
  scene.clearColour = glm::vec3(0.2f, 0.4f, 0.6f);  // exactly (51, 102, 153)
  scene.objects.push_back(mirrorAtOrigin());
  auto demo = testing::makeCapturingDemo(scene);
  ASSERT_TRUE(renderFrameAt(*demo, 0.0, 32, 32));
  std::vector<glm::vec3> directions;
  for (const Lookup& l : edgeAndCornerLookups()) directions.push_back(l.direction);
  for (int k = 0; k < 64; ++k) {  // and a spiral over the whole sphere
    const float z = 1.0f - (2.0f * float(k) + 1.0f) / 64.0f;
    const float a = 2.39996f * float(k);
    directions.push_back(
        {std::sqrt(1 - z * z) * std::cos(a), z, std::sqrt(1 - z * z) * std::sin(a)});
  }
  const glm::u8vec3 expected(51, 102, 153);
  ASSERT_EQ(extremes::toBytes(scene.clearColour), expected);
  const auto sampled = extremes::sampleCube(demo->environmentTexture(), directions);
  ASSERT_EQ(sampled.size(), directions.size());
  int wrong = 0;
  for (size_t i = 0; i < sampled.size(); ++i) {
    if (sampled[i] != expected) {
      ++wrong;
      ADD_FAILURE() << "direction (" << directions[i].x << "," << directions[i].y << ","
                    << directions[i].z << "): " << extremes::describe(sampled[i]);
    }
  }
  std::printf("uniform environment: %zu lookups, %d differ from (51,102,153)\n", sampled.size(),
              wrong);
}

}  // namespace
}  // namespace reflect
