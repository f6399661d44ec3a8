#pragma once
// stroke_font: the project's own single-stroke font for labels (label_region.h), drawn for it on
// a grid 4 units wide and 6 high (capitals and digits from the baseline y = 0 to y = 6), so that
// a label comes out the same on every machine with no font looked up.
//
// glyph_strokes(c): c's strokes, each a polyline as x y pairs in grid units (one stroke per
// vector), or null when the font has no such character. Letters are capitals (a lower-case
// letter is its capital); digits, '-', '_', '.', '/', '+', '#' and ' ' (no strokes).
#include <vector>

namespace slicereuse {

constexpr double kGlyphWidth = 4, kGlyphHeight = 6, kGlyphAdvance = 6;  // grid units

const std::vector<std::vector<double>>* glyph_strokes(char c);

}  // namespace slicereuse
