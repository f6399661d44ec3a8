#include "support_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "mask_stack.h"

namespace slicereuse::test {
namespace {

constexpr uint8_t kLit = 128;
constexpr double kFar = std::numeric_limits<double>::infinity();

struct Box {
  int x0 = INT32_MAX, y0 = INT32_MAX, x1 = -1, y1 = -1;  // inclusive
  bool empty() const { return x1 < x0; }
  void add(int x, int y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
};

Box lit_box(const MaskImage& m, size_t* lit) {
  Box b;
  *lit = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.pixels[size_t(y) * m.width + x] >= kLit) {
        b.add(x, y);
        ++*lit;
      }
  return b;
}

// Squared distance transform along one line (Felzenszwalb and Huttenlocher): f in, d out, the
// samples step apart.
void line_transform(const std::vector<double>& f, double step, std::vector<double>& d) {
  const int n = int(f.size());
  std::vector<int> v(n);
  std::vector<double> z(n + 1);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kFar) continue;
    double s = -kFar;
    while (k >= 0) {
      const double p = v[k];
      s = ((f[q] + q * q * step * step) - (f[v[k]] + p * p * step * step)) / (2 * step * step * (q - p));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -kFar : s;
    z[k + 1] = kFar;
  }
  d.assign(n, kFar);
  if (k < 0) return;
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    const double dq = (q - v[j]) * step;
    d[q] = dq * dq + f[v[j]];
  }
}

// The largest distance in mm from a lit pixel of above to a lit pixel of below, within box (which
// holds every lit pixel of both).
double farthest(const MaskImage& below, const MaskImage& above, const Box& b, double column_mm, double row_mm) {
  const int w = b.x1 - b.x0 + 1, h = b.y1 - b.y0 + 1;
  std::vector<double> g(size_t(w) * h), f, d;
  for (int x = 0; x < w; ++x) {
    f.assign(h, kFar);
    for (int y = 0; y < h; ++y)
      if (below.pixels[size_t(b.y0 + y) * below.width + b.x0 + x] >= kLit) f[y] = 0;
    line_transform(f, row_mm, d);
    for (int y = 0; y < h; ++y) g[size_t(y) * w + x] = d[y];
  }
  double worst = 0;
  for (int y = 0; y < h; ++y) {
    f.assign(g.begin() + long(y) * w, g.begin() + long(y + 1) * w);
    line_transform(f, column_mm, d);
    for (int x = 0; x < w; ++x)
      if (above.pixels[size_t(b.y0 + y) * above.width + b.x0 + x] >= kLit) worst = std::max(worst, d[x]);
  }
  return std::sqrt(worst);
}

// The 8-connected lit regions of above with no lit pixel of below.
size_t islands(const MaskImage& below, const MaskImage& above, const Box& b) {
  const int W = above.width;
  std::vector<uint8_t> seen(above.pixels.size(), 0);
  std::vector<size_t> stack;
  size_t count = 0;
  for (int y = b.y0; y <= b.y1; ++y)
    for (int x = b.x0; x <= b.x1; ++x) {
      const size_t start = size_t(y) * W + x;
      if (seen[start] || above.pixels[start] < kLit) continue;
      bool rests = false;
      seen[start] = 1;
      stack.assign(1, start);
      while (!stack.empty()) {
        const size_t i = stack.back();
        stack.pop_back();
        rests |= below.pixels[i] >= kLit;
        const int px = int(i % W), py = int(i / W);
        for (int ny = std::max(py - 1, 0); ny <= std::min(py + 1, above.height - 1); ++ny)
          for (int nx = std::max(px - 1, 0); nx <= std::min(px + 1, W - 1); ++nx) {
            const size_t j = size_t(ny) * W + nx;
            if (!seen[j] && above.pixels[j] >= kLit) {
              seen[j] = 1;
              stack.push_back(j);
            }
          }
      }
      count += !rests;
    }
  return count;
}

// Layer k after layer k-1 (below, with its box): its lit pixels, islands and distance into s.
void add_layer(StackSupport& s, const MaskImage& below, const Box& below_box, const MaskImage& layer, Box* box,
               size_t k, const MaskImageLayout& image) {
  s.lit.push_back(0);
  *box = lit_box(layer, &s.lit.back());
  if (k == 0 || box->empty()) return;
  const size_t n = islands(below, layer, *box);
  if (n > 0 && s.islands == 0) s.first_island_layer = k;
  s.islands += n;
  double d = kFar;
  if (!below_box.empty()) {
    Box both = *box;
    both.add(below_box.x0, below_box.y0);
    both.add(below_box.x1, below_box.y1);
    d = farthest(below, layer, both, 1e-3 * image.column_um, 1e-3 * image.row_um);
  }
  if (d > s.max_distance_mm) {
    s.max_distance_mm = d;
    s.max_distance_layer = k;
  }
}

}  // namespace

StackSupport check_stack_support(const std::vector<MaskImage>& layers, const PrinterProfile& profile) {
  const MaskImageLayout image = mask_image_layout(profile);
  StackSupport s;
  Box below, box;
  for (size_t k = 0; k < layers.size(); ++k) {
    add_layer(s, k > 0 ? layers[k - 1] : layers[0], below, layers[k], &box, k, image);
    below = box;
  }
  return s;
}

StackSupport check_stack_support(const std::string& path, const PrinterProfile& profile) {
  const MaskImageLayout image = mask_image_layout(profile);
  MaskStack stack(path);
  StackSupport s;
  MaskImage below, layer;
  Box below_box, box;
  std::vector<uint8_t> bytes;
  for (size_t k = 0; k < stack.layers(); ++k) {
    stack.read(k, bytes);
    stack.decode(k, bytes, layer);
    add_layer(s, below, below_box, layer, &box, k, image);
    std::swap(below, layer);
    below_box = box;
  }
  return s;
}

}  // namespace slicereuse::test
