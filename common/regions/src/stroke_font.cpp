#include "stroke_font.h"

#include <array>
#include <cctype>
#include <cstdlib>
#include <string>

namespace slicereuse {
namespace {

// Each glyph: strokes separated by ';', a stroke's points "x,y" separated by spaces.
struct GlyphText {
  char c;
  const char* strokes;
};

constexpr GlyphText kGlyphs[] = {
    {'0', "1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1 1,0; 4,5 0,1"},
    {'1', "1,5 2,6 2,0; 1,0 3,0"},
    {'2', "0,5 1,6 3,6 4,5 4,4 0,0 4,0"},
    {'3', "0,5 1,6 3,6 4,5 4,4 3,3 1,3; 3,3 4,2 4,1 3,0 1,0 0,1"},
    {'4', "3,0 3,6 0,2 4,2"},
    {'5', "4,6 0,6 0,3 3,3 4,2 4,1 3,0 0,0"},
    {'6', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,2 3,3 0,3"},
    {'7', "0,6 4,6 1,0"},
    {'8', "1,3 0,4 0,5 1,6 3,6 4,5 4,4 3,3 1,3 0,2 0,1 1,0 3,0 4,1 4,2 3,3"},
    {'9', "4,3 1,3 0,4 0,5 1,6 3,6 4,5 4,1 3,0 1,0 0,1"},
    {'A', "0,0 0,4 2,6 4,4 4,0; 0,3 4,3"},
    {'B', "0,0 0,6 3,6 4,5 4,4 3,3 0,3; 3,3 4,2 4,1 3,0 0,0"},
    {'C', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1"},
    {'D', "0,0 0,6 2,6 4,4 4,2 2,0 0,0"},
    {'E', "4,6 0,6 0,0 4,0; 0,3 3,3"},
    {'F', "4,6 0,6 0,0; 0,3 3,3"},
    {'G', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,3 2,3"},
    {'H', "0,0 0,6; 4,0 4,6; 0,3 4,3"},
    {'I', "1,6 3,6; 2,6 2,0; 1,0 3,0"},
    {'J', "4,6 4,1 3,0 1,0 0,1"},
    {'K', "0,0 0,6; 4,6 0,2; 1,3 4,0"},
    {'L', "0,6 0,0 4,0"},
    {'M', "0,0 0,6 2,3 4,6 4,0"},
    {'N', "0,0 0,6 4,0 4,6"},
    {'O', "1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1 1,0"},
    {'P', "0,0 0,6 3,6 4,5 4,4 3,3 0,3"},
    {'Q', "1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,1 1,0; 2,2 4,0"},
    {'R', "0,0 0,6 3,6 4,5 4,4 3,3 0,3; 2,3 4,0"},
    {'S', "4,5 3,6 1,6 0,5 0,4 1,3 3,3 4,2 4,1 3,0 1,0 0,1"},
    {'T', "0,6 4,6; 2,6 2,0"},
    {'U', "0,6 0,1 1,0 3,0 4,1 4,6"},
    {'V', "0,6 2,0 4,6"},
    {'W', "0,6 1,0 2,3 3,0 4,6"},
    {'X', "0,6 4,0; 0,0 4,6"},
    {'Y', "0,6 2,3 4,6; 2,3 2,0"},
    {'Z', "0,6 4,6 0,0 4,0"},
    {'-', "1,3 3,3"},
    {'_', "0,0 4,0"},
    {'.', "2,0 2,0.5"},
    {'/', "0,0 4,6"},
    {'+', "2,1 2,5; 0,3 4,3"},
    {'#', "1,0 1,6; 3,0 3,6; 0,2 4,2; 0,4 4,4"},
    {' ', ""},
};

std::vector<std::vector<double>> parse(const char* text) {
  std::vector<std::vector<double>> strokes;
  std::vector<double> stroke;
  const char* p = text;
  while (true) {
    while (*p == ' ') ++p;
    if (*p == ';' || *p == '\0') {
      if (!stroke.empty()) strokes.push_back(std::move(stroke));
      stroke.clear();
      if (*p == '\0') break;
      ++p;
      continue;
    }
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    const double y = std::strtod(end + 1, &end);  // past the ','
    stroke.insert(stroke.end(), {x, y});
    p = end;
  }
  return strokes;
}

}  // namespace

const std::vector<std::vector<double>>* glyph_strokes(char c) {
  static const std::array<std::vector<std::vector<double>>, sizeof(kGlyphs) / sizeof(kGlyphs[0])> parsed = [] {
    std::array<std::vector<std::vector<double>>, sizeof(kGlyphs) / sizeof(kGlyphs[0])> a;
    for (size_t i = 0; i < a.size(); ++i) a[i] = parse(kGlyphs[i].strokes);
    return a;
  }();
  const char u = char(std::toupper(static_cast<unsigned char>(c)));
  for (size_t i = 0; i < parsed.size(); ++i)
    if (kGlyphs[i].c == u) return &parsed[i];
  return nullptr;
}

}  // namespace slicereuse
