// The CPU cube sampler (core/cube_sampling.h) by hand: the face and (s, t) of GL's table at each
// axis and at ties, exact texels at face and texel centres, the bilinear weights, the image's row
// order, clamping to the edge and the seamless edges and corners. (tests/gl/cube_sampling_gl_test
// checks it against the GL itself.)
#include <gtest/gtest.h>

#include "core/cube_sampling.h"

namespace reflect {
namespace {

// Six N x N faces; texel (i, j) of face f is (f * 40 + i, j * 10, 7, 255), so every texel differs.
CubeFaces numberedFaces(int n) {
  CubeFaces faces;
  for (int f = 0; f < 6; ++f) {
    RgbaImage& face = faces[static_cast<size_t>(f)];
    face.width = face.height = n;
    face.pixels.resize(static_cast<size_t>(n) * static_cast<size_t>(n) * 4);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        uint8_t* p = &face.pixels[(static_cast<size_t>(j) * static_cast<size_t>(n) +
                                   static_cast<size_t>(i)) *
                                  4];
        p[0] = static_cast<uint8_t>(f * 40 + i);
        p[1] = static_cast<uint8_t>(j * 10);
        p[2] = 7;
        p[3] = 255;
      }
    }
  }
  return faces;
}

glm::vec4 texelOf(const CubeFaces& faces, const CubeTexel& t) {
  const uint8_t* p = faces[static_cast<size_t>(t.face)].at(t.i, t.j);
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

void expectColour(const glm::vec4& got, const glm::vec4& want, const std::string& what) {
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-6f) << what << " channel " << c;
}

TEST(CubeSampling, EachAxisPicksItsFaceAtTheCentre) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    const CubeFaceCoord c = cubeFaceCoord(axes[f] * 3.0f);
    EXPECT_EQ(c.face, f);
    EXPECT_EQ(c.s, 0.5f);
    EXPECT_EQ(c.t, 0.5f);
  }
}

TEST(CubeSampling, TheSpecsTableOfScTcAndMa) {
  // d = (rx, ry, rz) with the major axis of magnitude 2: s = (sc / 2 + 1) / 2, t = (tc / 2 + 1)
  // / 2.
  struct Case {
    glm::vec3 d;
    int face;
    float sc, tc;
  };
  const Case cases[] = {
      {{2, 0.5f, -1}, 0, 1, -0.5f},    // +X: sc = -rz, tc = -ry
      {{-2, 0.5f, -1}, 1, -1, -0.5f},  // -X: sc = +rz, tc = -ry
      {{0.5f, 2, -1}, 2, 0.5f, -1},    // +Y: sc = +rx, tc = +rz
      {{0.5f, -2, -1}, 3, 0.5f, 1},    // -Y: sc = +rx, tc = -rz
      {{0.5f, -1, 2}, 4, 0.5f, 1},     // +Z: sc = +rx, tc = -ry
      {{0.5f, -1, -2}, 5, -0.5f, 1},   // -Z: sc = -rx, tc = -ry
  };
  for (const Case& k : cases) {
    const CubeFaceCoord c = cubeFaceCoord(k.d);
    EXPECT_EQ(c.face, k.face);
    EXPECT_FLOAT_EQ(c.s, (k.sc / 2.0f + 1.0f) / 2.0f) << k.face;
    EXPECT_FLOAT_EQ(c.t, (k.tc / 2.0f + 1.0f) / 2.0f) << k.face;
  }
}

TEST(CubeSampling, TiesGoToZThenY) {
  EXPECT_EQ(cubeFaceCoord({1, 1, 0}).face, 2);       // X = Y: Y
  EXPECT_EQ(cubeFaceCoord({-1, -1, 0}).face, 3);     // -Y
  EXPECT_EQ(cubeFaceCoord({1, 0, 1}).face, 4);       // X = Z: Z
  EXPECT_EQ(cubeFaceCoord({0, 1, -1}).face, 5);      // Y = Z: Z
  EXPECT_EQ(cubeFaceCoord({1, 1, 1}).face, 4);       // all three: Z
  EXPECT_EQ(cubeFaceCoord({-1, 1, -1}).face, 5);     // -Z
  EXPECT_EQ(cubeFaceCoord({1, 0.999f, 0}).face, 0);  // no tie: the larger wins
  EXPECT_EQ(cubeFaceCoord({0, 0, 0}).face, 4);       // undefined in GL; +Z's centre, as llvmpipe
}

TEST(CubeSampling, FaceCentresOfAnOddSizeAreOneTexel) {
  const CubeFaces faces = numberedFaces(3);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    expectColour(sampleCubeLinear(faces, axes[f]), texelOf(faces, {f, 1, 1}),
                 "face " + std::to_string(f));
  }
}

TEST(CubeSampling, EveryTexelCentreIsThatTexel) {
  const int n = 4;
  const CubeFaces faces = numberedFaces(n);
  // +Z: sc = rx, tc = -ry; texel (i, j)'s centre is sc = 2 (i + 0.5) / n - 1.
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float sc = 2.0f * (static_cast<float>(i) + 0.5f) / n - 1.0f;
      const float tc = 2.0f * (static_cast<float>(j) + 0.5f) / n - 1.0f;
      expectColour(sampleCubeLinear(faces, {sc, -tc, 1.0f}), texelOf(faces, {4, i, j}),
                   "texel " + std::to_string(i) + "," + std::to_string(j));
    }
  }
}

TEST(CubeSampling, TopRowsOfTheImageAreUp) {
  // On the side faces t grows downwards (tc = -ry): +Y directions read the image's first rows.
  const CubeFaces faces = numberedFaces(4);
  // (0, 0.5, 1) on +Z: t = 0.25, v = 0.5: rows 0 and 1 equally (green 0 and 10).
  EXPECT_NEAR(sampleCubeLinear(faces, {0, 0.5f, 1}).g * 255.0f, 5.0f, 1e-4f);
  // (0, -0.5, 1): t = 0.75, v = 2.5: rows 2 and 3 (20 and 30).
  EXPECT_NEAR(sampleCubeLinear(faces, {0, -0.5f, 1}).g * 255.0f, 25.0f, 1e-4f);
}

TEST(CubeSampling, BilinearWeights) {
  const int n = 4;
  const CubeFaces faces = numberedFaces(n);
  // On +Z at u = 1.25, v = 2.75: columns 1, 2 weighted 0.75, 0.25; rows 2, 3 weighted 0.25, 0.75.
  const float s = (1.25f + 0.5f) / n;
  const float t = (2.75f + 0.5f) / n;
  const glm::vec4 got = sampleCubeLinear(faces, {2 * s - 1, -(2 * t - 1), 1});
  const glm::vec4 want =
      0.75f * 0.25f * texelOf(faces, {4, 1, 2}) + 0.25f * 0.25f * texelOf(faces, {4, 2, 2}) +
      0.75f * 0.75f * texelOf(faces, {4, 1, 3}) + 0.25f * 0.75f * texelOf(faces, {4, 2, 3});
  expectColour(got, want, "bilinear");
  EXPECT_NEAR(got.r * 255.0f, 4 * 40 + 1.25f, 1e-4f);
  EXPECT_NEAR(got.g * 255.0f, 27.5f, 1e-4f);
}

TEST(CubeSampling, ClampToEdgeStaysOnTheFace) {
  const int n = 4;
  const CubeFaces faces = numberedFaces(n);
  // The last quarter texel of +Z's right column (s = 1 - 0.1 / n, u = n - 0.6 + ...): clamped,
  // the edge texel alone.
  const float s = 1.0f - 0.1f / n;
  const float tc = 2.0f * 1.5f / n - 1.0f;  // row 1's centre
  const glm::vec3 d(2 * s - 1, -tc, 1);
  expectColour(sampleCubeLinear(faces, d, CubeEdges::ClampToEdge), texelOf(faces, {4, n - 1, 1}),
               "clamped");
  // Seamless: 0.4 of the way to the next face's texel (+X's column 0, the same row).
  const glm::vec4 seamless = sampleCubeLinear(faces, d, CubeEdges::Seamless);
  const glm::vec4 want = 0.6f * texelOf(faces, {4, n - 1, 1}) + 0.4f * texelOf(faces, {0, 0, 1});
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(seamless[c], want[c], 1e-5f) << c;
}

TEST(CubeSampling, SeamlessNeighboursAcrossEachKindOfEdge) {
  const int n = 4;
  // +X's right edge borders -Z's left, row for row; its left edge +Z's right.
  EXPECT_EQ(seamlessTexel(0, n, 2, n), (CubeTexel{5, 0, 2}));
  EXPECT_EQ(seamlessTexel(0, -1, 2, n), (CubeTexel{4, n - 1, 2}));
  // +X's top row borders +Y's right column, reversed: +X (i, 0) meets +Y (n - 1, n - 1 - i).
  EXPECT_EQ(seamlessTexel(0, 1, -1, n), (CubeTexel{2, n - 1, n - 2}));
  // +Y's top row (rz = -1) borders -Z's top row, reversed.
  EXPECT_EQ(seamlessTexel(2, 1, -1, n), (CubeTexel{5, n - 2, 0}));
  // -Y's bottom row (rz = -1) borders -Z's bottom row, reversed.
  EXPECT_EQ(seamlessTexel(3, 1, n, n), (CubeTexel{5, n - 2, n - 1}));
  // +Z's bottom row borders -Y's top row (rz = +1 is -Y's t = 0).
  EXPECT_EQ(seamlessTexel(4, 1, n, n), (CubeTexel{3, 1, 0}));
  // Inside, a texel is itself.
  EXPECT_EQ(seamlessTexel(3, 2, 1, n), (CubeTexel{3, 2, 1}));
  // Going across and back returns to the start, for every edge texel of every face.
  for (int f = 0; f < 6; ++f) {
    for (int k = 0; k < n; ++k) {
      for (const CubeTexel past :
           {CubeTexel{f, -1, k}, CubeTexel{f, n, k}, CubeTexel{f, k, -1}, CubeTexel{f, k, n}}) {
        const CubeTexel there = seamlessTexel(past.face, past.i, past.j, n);
        EXPECT_NE(there.face, f);
        // The texel just past `there`'s edge, towards f, is the edge texel we came from.
        const int di = there.i == 0 ? -1 : there.i == n - 1 ? 1 : 0;
        const int dj = there.j == 0 ? -1 : there.j == n - 1 ? 1 : 0;
        bool found = false;
        for (const auto& [si, sj] : {std::pair{di, 0}, std::pair{0, dj}}) {
          if (si == 0 && sj == 0) continue;
          const CubeTexel back = seamlessTexel(there.face, there.i + si, there.j + sj, n);
          const CubeTexel from{f, std::clamp(past.i, 0, n - 1), std::clamp(past.j, 0, n - 1)};
          found = found || back == from;
        }
        EXPECT_TRUE(found) << "face " << f << " texel " << past.i << "," << past.j;
      }
    }
  }
}

TEST(CubeSampling, ACubeCornerIsTheMeanOfItsThreeTexels) {
  const int n = 4;
  const CubeFaces faces = numberedFaces(n);
  // (1, 1, 1): a tie, so +Z, at s = 1, t = 0: the footprint's fourth texel would be off two edges.
  // The three faces meeting there: +Z's top-right texel, +X's top-left, +Y's bottom-right.
  const glm::vec4 want = (texelOf(faces, {4, n - 1, 0}) + texelOf(faces, {0, 0, 0}) +
                          texelOf(faces, {2, n - 1, n - 1})) /
                         3.0f;
  expectColour(sampleCubeLinear(faces, {1, 1, 1}), want, "corner");
  // Approached from +X's side the same.
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(sampleCubeLinear(faces, {1, 0.99999f, 0.99999f})[c], want[c], 1e-3f) << c;
  }
}

TEST(CubeSampling, FaceDirectionIsTheInverseOfFaceSelection) {
  // Texel centres of a 4x4 face on every face: back to the same face, s and t.
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const float s = (static_cast<float>(i) + 0.5f) / 4.0f;
        const float t = (static_cast<float>(j) + 0.5f) / 4.0f;
        const CubeFaceCoord back = cubeFaceCoord(faceDirection(face, s, t));
        EXPECT_EQ(back.face, face);
        EXPECT_FLOAT_EQ(back.s, s) << face << " " << i << "," << j;
        EXPECT_FLOAT_EQ(back.t, t) << face << " " << i << "," << j;
      }
    }
  }
  // The face's centre is its look direction from the course's table.
  EXPECT_EQ(faceDirection(2, 0.5f, 0.5f), glm::vec3(0, 1, 0));
  EXPECT_EQ(faceDirection(5, 0.5f, 0.5f), glm::vec3(0, 0, -1));
}

}  // namespace
}  // namespace reflect
