// A 5x7 pixel font for the labels the views write into images natively (the faces view's PNG):
// digits, capital letters and the few signs the labels use. The page draws the same label strings
// as text; only the native images need glyphs.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "core/image.h"

namespace reflect {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // one blank column between glyphs
// The light grey the inside views write their labels in.
inline constexpr std::array<uint8_t, 4> kLabelText{235, 235, 235, 255};

// The glyph's rows, top first; bit 4 is the leftmost pixel. Lower case is drawn as upper case;
// a character the font lacks is drawn as a filled box, so a missing glyph is seen, not skipped.
std::array<uint8_t, kGlyphHeight> glyphRows(char c);

// Pixels `text` covers at `scale` (each font pixel a scale x scale square).
int textWidth(const std::string& text, int scale);

// Writes `text` into `image` with its top-left corner at (x, y), in `rgba`; pixels outside the
// image are left out.
void drawText(RgbaImage& image, int x, int y, const std::string& text,
              const std::array<uint8_t, 4>& rgba, int scale = 1);

// Writes `text` word-wrapped to the image's width less `margin` each side, its first line's
// top-left corner at (margin, margin), lines kGlyphHeight + 5 apart; returns the row below the
// last line.
int drawWrappedText(RgbaImage& image, int margin, const std::string& text,
                    const std::array<uint8_t, 4>& rgba);

}  // namespace reflect
