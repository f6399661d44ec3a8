#include "slicereuse/regions/label_region.h"

#include <cmath>

#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "stroke_font.h"

namespace slicereuse {
namespace {

constexpr double kStrokeShare = 0.12;  // of the height
constexpr double kArcToleranceMm = 0.002;  // the round ends' chords, a fortieth of a 50 um pixel

void check_label(const std::string& text, double height_mm) {
  if (!(std::isfinite(height_mm) && height_mm > 0))
    throw Error(format("a label's height is %g mm; it must be a positive number", height_mm));
  if (text.find_first_not_of(' ') == std::string::npos) throw Error("a label needs a text, but it is empty");
  for (const char c : text)
    if (!glyph_strokes(c))
      throw Error(format("the label '%s' holds '%c', which labels cannot print: letters, digits, '-', '_', '.', '/', "
                         "'+', '#' and spaces only",
                         text.c_str(), c));
}

// Grid units to mm, and the text's width in grid units.
double unit_mm(double height_mm) { return (height_mm - label_stroke_mm(height_mm)) / kGlyphHeight; }
double text_units(const std::string& text) { return double(text.size() - 1) * kGlyphAdvance + kGlyphWidth; }

}  // namespace

double label_stroke_mm(double height_mm) { return kStrokeShare * height_mm; }

std::array<double, 2> label_box_mm(const std::string& text, double height_mm) {
  check_label(text, height_mm);
  return {text_units(text) * unit_mm(height_mm) + label_stroke_mm(height_mm), height_mm};
}

ClipperLib::Paths label_region(const std::string& text, double height_mm, bool mirrored) {
  check_label(text, height_mm);
  const double unit = unit_mm(height_mm);
  const double x0 = -0.5 * text_units(text), y0 = -0.5 * kGlyphHeight;  // the grid's centre at (0, 0)
  ClipperLib::Paths strokes;
  for (size_t i = 0; i < text.size(); ++i)
    for (const std::vector<double>& stroke : *glyph_strokes(text[i])) {
      ClipperLib::Path path;
      for (size_t p = 0; p + 1 < stroke.size(); p += 2) {
        const double x = (x0 + double(i) * kGlyphAdvance + stroke[p]) * unit;
        path.push_back({region_units(mirrored ? -x : x), region_units((y0 + stroke[p + 1]) * unit)});
      }
      strokes.push_back(std::move(path));
    }
  ClipperLib::ClipperOffset offset(2, double(region_units(kArcToleranceMm)));
  offset.AddPaths(strokes, ClipperLib::jtRound, ClipperLib::etOpenRound);
  ClipperLib::Paths region;
  offset.Execute(region, 0.5 * double(region_units(label_stroke_mm(height_mm))));
  return region;
}

}  // namespace slicereuse
