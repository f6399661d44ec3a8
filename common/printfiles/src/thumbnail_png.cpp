#include "thumbnail_png.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {
namespace {

constexpr int kSamples = 4;          // per pixel along each axis
constexpr double kMargin = 0.05;     // of the picture's side, around the part
constexpr double kDarkest = 0.4;     // brightness of the first layer; the top layers are at 1
constexpr uint8_t kResin[3] = {0xFF, 0x80, 0x40};

// The cells of [lo, hi] each of a picture axis's sample positions falls in (-1 outside them):
// picture pixel p's samples are at p + (i + 1/2) / kSamples, the picture's centre on `centre`.
std::vector<int> sample_cells(int pixels, double cells_per_pixel, double centre, int lo, int hi) {
  std::vector<int> cell(size_t(pixels) * kSamples);
  for (int p = 0; p < pixels; ++p)
    for (int i = 0; i < kSamples; ++i) {
      const double f = std::floor(centre + (p + (i + 0.5) / kSamples - 0.5 * pixels) * cells_per_pixel);
      cell[size_t(p) * kSamples + size_t(i)] = f >= lo && f <= hi ? int(f) : -1;
    }
  return cell;
}

// The pixels [begin, end) of an axis with a sample on the part's bounding box (the others are
// transparent): samples increase along the axis, so they are contiguous.
std::pair<int, int> pixels_on_part(const std::vector<int>& cell) {
  const int pixels = int(cell.size() / kSamples);
  int begin = 0, end = pixels;
  while (begin < end && cell[size_t(begin) * kSamples + kSamples - 1] < 0) ++begin;
  while (end > begin && cell[size_t(end - 1) * kSamples] < 0) --end;
  return {begin, end};
}

}  // namespace

void thumbnail_png(const HeightMap& view, int width, int height, std::vector<uint8_t>& out) {
  int c0 = view.cols, c1 = -1, r0 = view.rows, r1 = -1;
  for (int r = 0; r < view.rows; ++r)
    for (int c = 0; c < view.cols; ++c)
      if (view.level[size_t(r) * size_t(view.cols) + size_t(c)]) {
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
        r0 = std::min(r0, r);
        r1 = std::max(r1, r);
      }
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4, 0);
  if (c1 >= 0) {
    const double cols = c1 - c0 + 1, rows = r1 - r0 + 1;
    const double cells_per_pixel =
        std::max(cols / (width * (1 - 2 * kMargin)), rows / (height * (1 - 2 * kMargin)));
    const std::vector<int> x = sample_cells(width, cells_per_pixel, c0 + 0.5 * cols, c0, c1);
    const std::vector<int> y = sample_cells(height, cells_per_pixel, r0 + 0.5 * rows, r0, r1);
    const std::pair<int, int> xs = pixels_on_part(x), ys = pixels_on_part(y);
    const int x_begin = xs.first, x_end = xs.second;
    // Rows on all cores: the thumbnails are made after the last layer, while nothing else runs.
#pragma omp parallel for schedule(dynamic, 16)
    for (int py = ys.first; py < ys.second; ++py)
      for (int px = x_begin; px < x_end; ++px) {
        int covered = 0, levels = 0;
        for (int j = 0; j < kSamples; ++j) {
          const int r = y[size_t(py) * kSamples + size_t(j)];
          if (r < 0) continue;
          const uint8_t* row = view.level.data() + size_t(r) * size_t(view.cols);
          for (int i = 0; i < kSamples; ++i) {
            const int c = x[size_t(px) * kSamples + size_t(i)];
            const int level = c < 0 ? 0 : row[c];
            covered += level > 0;
            levels += level;
          }
        }
        if (!covered) continue;
        const double brightness = kDarkest + (1 - kDarkest) * (double(levels) / covered - 1) / 254;
        uint8_t* p = rgba.data() + (size_t(py) * size_t(width) + size_t(px)) * 4;
        for (int ch = 0; ch < 3; ++ch) p[ch] = uint8_t(kResin[ch] * brightness + 0.5);  // rounded (positive)
        p[3] = uint8_t((255 * covered + kSamples * kSamples / 2) / (kSamples * kSamples));
      }
  }
  encode_rgba_png(rgba.data(), width, height, out);
}

std::vector<uint16_t> rgb565_preview(const HeightMap& view, int width, int height) {
  std::vector<uint16_t> out(size_t(width) * size_t(height), 0);
  if (view.cols == 0 || view.rows == 0) return out;
  // The display's cells per preview pixel, the same along both sides: the whole display fits.
  const double cells_per_pixel = std::max(double(view.cols) / width, double(view.rows) / height);
  const std::vector<int> x = sample_cells(width, cells_per_pixel, 0.5 * view.cols, 0, view.cols - 1);
  const std::vector<int> y = sample_cells(height, cells_per_pixel, 0.5 * view.rows, 0, view.rows - 1);
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      int covered = 0;
      for (int j = 0; j < kSamples; ++j) {
        const int r = y[size_t(py) * kSamples + size_t(j)];
        if (r < 0) continue;
        for (int i = 0; i < kSamples; ++i) {
          const int c = x[size_t(px) * kSamples + size_t(i)];
          covered += c >= 0 && view.level[size_t(r) * size_t(view.cols) + size_t(c)] != 0;
        }
      }
      const unsigned v = unsigned((255 * covered + kSamples * kSamples / 2) / (kSamples * kSamples));
      out[size_t(py) * size_t(width) + size_t(px)] = uint16_t((v >> 3) << 11 | (v >> 2) << 5 | (v >> 3));
    }
  return out;
}

}  // namespace slicereuse
