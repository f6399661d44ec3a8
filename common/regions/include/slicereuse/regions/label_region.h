#pragma once
// label_region: a text -> the region its letters fill, to engrave into a part as its contours
// are: the strokes of the project's own single-stroke font (stroke_font.h, drawn on a grid, the
// same on every machine), each widened into a band of stroke_mm with round ends and joins
// (Clipper), united. The letters stand height_mm from the lowest to the highest ink, the strokes
// included, spaced a glyph's width and a half apart; the text's box is centred on (0, 0), and
// `mirrored` reverses x (a label on a part's base reads from below).
// label_stroke_mm: the stroke of a label height_mm high: 0.12 of it, as engraved case labels
// are (bold enough to print at a tenth of the height).
// label_box_mm: the width and height of label_region(text, height_mm)'s box, without making it.
// Characters: letters (lower-case as capitals), digits, '-', '_', '.', '/', '+', '#' and ' ';
// throws Error naming any other character, for an empty text, or for a height that is not a
// positive number.
#include <array>
#include <clipper.hpp>
#include <string>

namespace slicereuse {

double label_stroke_mm(double height_mm);
std::array<double, 2> label_box_mm(const std::string& text, double height_mm);
ClipperLib::Paths label_region(const std::string& text, double height_mm, bool mirrored);

}  // namespace slicereuse
