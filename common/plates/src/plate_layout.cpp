#include "slicereuse/plates/plate_layout.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>

#include "slicereuse/plates/footprint.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

constexpr uint8_t kPaper = 255, kFill = 215, kInk = 0;

// 3 x 5 glyphs, rows from the top, '1' = ink. Drawn for this picture.
const char* glyph(char c) {
  struct G {
    char c;
    const char* rows;
  };
  static const G kGlyphs[] = {
      {'0', "111101101101111"}, {'1', "010110010010111"}, {'2', "111001111100111"}, {'3', "111001111001111"},
      {'4', "101101111001001"}, {'5', "111100111001111"}, {'6', "111100111101111"}, {'7', "111001001001001"},
      {'8', "111101111101111"}, {'9', "111101111001111"}, {'A', "010101111101101"}, {'B', "110101110101110"},
      {'C', "011100100100011"}, {'D', "110101101101110"}, {'E', "111100110100111"}, {'F', "111100110100100"},
      {'G', "011100101101011"}, {'H', "101101111101101"}, {'I', "111010010010111"}, {'J', "001001001101010"},
      {'K', "101101110101101"}, {'L', "100100100100111"}, {'M', "101111111101101"}, {'N', "110101101101101"},
      {'O', "010101101101010"}, {'P', "110101110100100"}, {'Q', "010101101110011"}, {'R', "110101110101101"},
      {'S', "011100010001110"}, {'T', "111010010010010"}, {'U', "101101101101111"}, {'V', "101101101101010"},
      {'W', "101101111111101"}, {'X', "101101010101101"}, {'Y', "101101010010010"}, {'Z', "111001010100111"},
      {'_', "000000000000111"}, {'-', "000000111000000"}, {'.', "000000000000010"}, {' ', "000000000000000"}};
  const char u = char(std::toupper(static_cast<unsigned char>(c)));
  for (const G& g : kGlyphs)
    if (g.c == u) return g.rows;
  return "111001010000010";  // '?'
}

struct Image {
  int width, height;
  std::vector<uint8_t> pixels;
  void set(int x, int y, uint8_t v) {
    if (x >= 0 && x < width && y >= 0 && y < height) pixels[size_t(y) * width + x] = v;
  }
};

void draw_text(Image& img, const std::string& text, int cx, int cy, int scale) {
  const int w = int(text.size()) * 4 * scale - scale, h = 5 * scale;
  const int x0 = cx - w / 2, y0 = cy - h / 2;
  for (size_t i = 0; i < text.size(); ++i) {
    const char* rows = glyph(text[i]);
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 3; ++c)
        if (rows[r * 3 + c] == '1')
          for (int dy = 0; dy < scale; ++dy)
            for (int dx = 0; dx < scale; ++dx) img.set(x0 + (int(i) * 4 + c) * scale + dx, y0 + r * scale + dy, kInk);
  }
}

}  // namespace

void write_plate_layout(const std::string& path, const std::vector<Mesh>& placed, const std::vector<std::string>& names,
                        const Platform& platform, double px) {
  if (names.size() != placed.size())
    throw Error(format("plate layout: %zu names for %zu members", names.size(), placed.size()));
  if (!(px > 0) || !std::isfinite(px)) throw Error(format("plate layout: pixel size %g mm is not positive", px));
  const double w = std::ceil((platform.x1 - platform.x0) / px), h = std::ceil((platform.y1 - platform.y0) / px);
  if (!(w >= 1 && h >= 1 && w <= 20000 && h <= 20000))
    throw Error(format("plate layout: %g x %g pixels is not within 1..20000 pixels a side", w, h));
  Image img{int(w), int(h), std::vector<uint8_t>(size_t(w) * size_t(h), kPaper)};
  const int scale = std::max(1, std::min(img.width, img.height) / 150);
  // Every member's footprint on the image's pixels (one member per core: each is a pass over
  // its faces) and its outline, then the names on top.
  std::vector<Footprint> footprints(placed.size());
  parallel_blocks(placed.size(), [&](size_t m) { footprints[m] = mesh_footprint(placed[m], 0, px); }, {},
                  "plate layout");
  std::vector<std::array<int, 2>> centre;
  for (size_t m = 0; m < placed.size(); ++m) {
    const Footprint& f = footprints[m];
    const int ox = int(std::lround((f.x0 - platform.x0) / px)), oy = int(std::lround((f.y0 - platform.y0) / px));
    auto cell = [&](int i, int j) { return i >= 0 && i < f.width && j >= 0 && j < f.height && f.cells[size_t(j) * f.width + i]; };
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        if (!cell(i, j)) continue;
        const bool edge = !cell(i - 1, j) || !cell(i + 1, j) || !cell(i, j - 1) || !cell(i, j + 1);
        img.set(ox + i, img.height - 1 - (oy + j), edge ? kInk : kFill);
      }
    centre.push_back({ox + f.width / 2, img.height - 1 - (oy + f.height / 2)});
  }
  for (size_t m = 0; m < placed.size(); ++m) draw_text(img, names[m], centre[m][0], centre[m][1], scale);
  for (int x = 0; x < img.width; ++x) {
    img.set(x, 0, kInk);
    img.set(x, img.height - 1, kInk);
  }
  for (int y = 0; y < img.height; ++y) {
    img.set(0, y, kInk);
    img.set(img.width - 1, y, kInk);
  }
  std::vector<uint8_t> png;
  encode_mask_png(img.pixels.data(), img.width, img.height, 8, png);
  AtomicFile out(path);
  out.write(png.data(), png.size());
  out.commit();
}

}  // namespace slicereuse
