// The faces view's image (core/cube_cross): the squares hold the faces' own pixels where the
// cross reads them, stale faces at half brightness, and the labels are the course's table.
#include <gtest/gtest.h>

#include <cstring>

#include "core/bitmap_font.h"
#include "core/cube_cross.h"

namespace reflect {
namespace {

// Six faces of `size`, each pixel a function of face, column and row, so that any misplaced or
// flipped texel shows.
CubeFaces patternedFaces(int size) {
  CubeFaces faces;
  for (size_t f = 0; f < 6; ++f) {
    faces[f].width = faces[f].height = size;
    faces[f].pixels.resize(static_cast<size_t>(size * size) * 4);
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        uint8_t* p = &faces[f].pixels[static_cast<size_t>((y * size + x) * 4)];
        p[0] = static_cast<uint8_t>(40 * f + 1);
        p[1] = static_cast<uint8_t>(x * 7);
        p[2] = static_cast<uint8_t>(y * 11);
        p[3] = 255;
      }
    }
  }
  return faces;
}

std::array<FaceMark, 6> allCaptured() {
  std::array<FaceMark, 6> marks;
  for (FaceMark& mark : marks) mark.captured = true;
  return marks;
}

TEST(CubeCross, EachSquareHoldsItsFaceTexelForTexel) {
  const CubeFaces faces = patternedFaces(16);
  for (bool labels : {false, true}) {
    const RgbaImage view = unfoldCross(faces, allCaptured(), labels, "CHANNEL COLOUR");
    const CrossGeometry g = crossGeometry(16);
    ASSERT_EQ(view.width,
              labels ? labelledCrossWidth(g, allCaptured(), "CHANNEL COLOUR") : g.width);
    ASSERT_EQ(view.height, g.height);
    for (size_t f = 0; f < 6; ++f) {
      for (int y = 0; y < 16; ++y) {
        ASSERT_EQ(std::memcmp(view.at(g.squareOrigin[f][0], g.squareOrigin[f][1] + y),
                              faces[f].at(0, y), 16 * 4),
                  0)
            << "face " << f << " row " << y << " labels " << labels;
      }
    }
  }
}

TEST(CubeCross, SquaresSitWhereTheCrossLoaderReadsThem) {
  // Squares at pitch (size + 2 margin): the view with its margins cut away is the horizontal
  // cross facesFromCross reads, so each face comes back where it went in.
  const int size = 8;
  const CubeFaces faces = patternedFaces(size);
  const RgbaImage view = unfoldCross(faces, allCaptured(), false, "");
  const CrossGeometry g = crossGeometry(size);
  RgbaImage cross;
  cross.width = 4 * size;
  cross.height = 3 * size;
  cross.pixels.assign(static_cast<size_t>(cross.width * cross.height) * 4, 0);
  const int pitch = size + 2 * g.margin;
  for (int cy = 0; cy < 3; ++cy) {
    for (int cx = 0; cx < 4; ++cx) {
      for (int y = 0; y < size; ++y) {
        std::memcpy(
            &cross.pixels[static_cast<size_t>(((cy * size + y) * cross.width + cx * size) * 4)],
            view.at(cx * pitch + g.margin, cy * pitch + g.margin + y), size * 4);
      }
    }
  }
  const Result<CubeFaces> back = facesFromCross(cross, "view");
  ASSERT_TRUE(back.ok()) << back.error();
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(back.value()[f].pixels, faces[f].pixels) << "face " << f;
}

TEST(CubeCross, AStaleFaceIsDimmedToHalfAndTheOthersAreNot) {
  const CubeFaces faces = patternedFaces(8);
  std::array<FaceMark, 6> marks = allCaptured();
  marks[3] = FaceMark{false, 4, true};
  const RgbaImage view = unfoldCross(faces, marks, false, "");
  const CrossGeometry g = crossGeometry(8);
  const uint8_t* stale = view.at(g.squareOrigin[3][0] + 5, g.squareOrigin[3][1] + 6);
  const uint8_t* original = faces[3].at(5, 6);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(stale[c], original[c] / 2) << "channel " << c;
  EXPECT_EQ(stale[3], original[3]);
  EXPECT_EQ(std::memcmp(view.at(g.squareOrigin[2][0] + 5, g.squareOrigin[2][1] + 6),
                        faces[2].at(5, 6), 4),
            0);
}

TEST(CubeCross, TheViewShrinksByWholeFactorsToFitAndShrunkTexelsAreBlockMeans) {
  EXPECT_EQ(crossShrinkFactor(256, 0, 0), 1);        // natively: no limit
  EXPECT_EQ(crossShrinkFactor(256, 1200, 1000), 1);  // 1128 x 929 fits
  EXPECT_EQ(crossShrinkFactor(256, 640, 600), 2);    // 616 x 545 at 128
  const CrossGeometry half = crossGeometry(128);
  EXPECT_LE(half.width, 640);
  EXPECT_LE(half.height, 600);
  EXPECT_EQ(crossShrinkFactor(256, 100, 100), 32);  // never below 8 texels
  const CubeFaces faces = patternedFaces(8);
  const CubeFaces small = shrinkFaces(faces, 2);
  ASSERT_EQ(small[1].width, 4);
  // Texel (1, 2) of the half-size face: the mean of texels (2..3, 4..5); green is 7 x column.
  EXPECT_EQ(small[1].at(1, 2)[1], (7 * 2 + 7 * 3 + 7 * 2 + 7 * 3 + 2) / 4);
  EXPECT_EQ(small[1].at(1, 2)[2], (11 * 4 + 11 * 4 + 11 * 5 + 11 * 5 + 2) / 4);
  EXPECT_EQ(shrinkFaces(faces, 1)[3].pixels, faces[3].pixels);
}

TEST(CubeCross, LabelsAreTheCoursesFaceTable) {
  EXPECT_EQ(faceLabel(0), "+X  LOOK (1,0,0)  UP (0,-1,0)");
  EXPECT_EQ(faceLabel(2), "+Y  LOOK (0,1,0)  UP (0,0,1)");
  EXPECT_EQ(faceLabel(3), "-Y  LOOK (0,-1,0)  UP (0,0,-1)");
  EXPECT_EQ(faceLabel(5), "-Z  LOOK (0,0,-1)  UP (0,-1,0)");
  EXPECT_EQ(faceStatus(FaceMark{true, 0, true}), "CAPTURED");
  EXPECT_EQ(faceStatus(FaceMark{false, 1, true}), "STALE 1 FRAME");
  EXPECT_EQ(faceStatus(FaceMark{false, 7, true}), "STALE 7 FRAMES");
  EXPECT_EQ(faceStatus(FaceMark{false, 0, false}), "EMPTY");
}

// Small faces widen the labelled view to its legend; 256-texel faces' cross is wider than any
// legend line and keeps its width. The title's last glyph lies inside the view.
TEST(CubeCross, TheLegendIsNeverCutOff) {
  const std::string title = "PROBE OF OBJECT 3 (MARIO.OBJ)  2 OF 2 PROBES  CHANNEL IRRADIANCE";
  std::array<FaceMark, 6> marks = allCaptured();
  const CrossGeometry small = crossGeometry(32);
  const int wide = labelledCrossWidth(small, marks, title);
  EXPECT_EQ(wide, textWidth(title, 1) + 2 * small.margin);
  EXPECT_GT(wide, small.width);
  const RgbaImage view = unfoldCross(patternedFaces(32), marks, true, title);
  EXPECT_EQ(view.width, wide);
  EXPECT_EQ(view.height, small.height);
  marks[1] = FaceMark{false, 123, true};  // "STALE 123 FRAMES" is no wider than the title
  EXPECT_EQ(labelledCrossWidth(small, marks, title), wide);
  EXPECT_EQ(labelledCrossWidth(crossGeometry(256), marks, title), crossGeometry(256).width);
}

TEST(BitmapFont, GlyphsAreTheirArtAndAMissingOneIsABox) {
  EXPECT_EQ(glyphRows('1'), (std::array<uint8_t, 7>{0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}));
  EXPECT_EQ(glyphRows('x'), glyphRows('X'));
  EXPECT_EQ(glyphRows('#'), (std::array<uint8_t, 7>{0x1f, 0x1f, 0x1f, 0x1f, 0x1f, 0x1f, 0x1f}));
  EXPECT_EQ(glyphRows(' '), (std::array<uint8_t, 7>{}));
  EXPECT_EQ(textWidth("+X", 1), 11);
  EXPECT_EQ(textWidth("", 3), 0);
}

TEST(BitmapFont, TextLightsExactlyTheGlyphsPixelsAndClipsAtTheEdge) {
  RgbaImage image;
  image.width = 8;
  image.height = 9;
  image.pixels.assign(8 * 9 * 4, 0);
  drawText(image, 4, 1, "-", {255, 0, 0, 255});  // the bar is row 3; columns 4..8 (8 is outside)
  int lit = 0;
  for (int y = 0; y < 9; ++y) {
    for (int x = 0; x < 8; ++x) {
      const bool on = image.at(x, y)[0] == 255;
      lit += on;
      EXPECT_EQ(on, y == 4 && x >= 4) << x << "," << y;
    }
  }
  EXPECT_EQ(lit, 4);
}

}  // namespace
}  // namespace reflect
