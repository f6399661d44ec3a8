#include "wall_measure.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/util/squared_distances.h"

namespace slicereuse::test {
namespace {

struct MaskLayer {
  std::vector<uint8_t> cavity;  // unlit and enclosed
  std::vector<float> outside2;  // squared distance in pixels to the nearest outside pixel
};

// Layer k's cavity and its distances to the outside, the outside flooded from the image's border.
MaskLayer mask_layer(MaskStack& stack, size_t k, int& w, int& h) {
  std::vector<uint8_t> bytes;
  stack.read(k, bytes);
  MaskImage img;
  decode_mask_png(bytes.data(), bytes.size(), stack.layer_name(k), img);
  w = img.width, h = img.height;
  std::vector<uint8_t> out(img.pixels.size(), 0);
  std::vector<size_t> todo;
  const auto flood = [&](int x, int y) {
    const size_t i = size_t(y) * size_t(w) + size_t(x);
    if (!out[i] && img.pixels[i] < 128) out[i] = 1, todo.push_back(i);
  };
  for (int x = 0; x < w; ++x) flood(x, 0), flood(x, h - 1);
  for (int y = 0; y < h; ++y) flood(0, y), flood(w - 1, y);
  while (!todo.empty()) {
    const size_t i = todo.back();
    todo.pop_back();
    const int x = int(i % size_t(w)), y = int(i / size_t(w));
    if (x > 0) flood(x - 1, y);
    if (x + 1 < w) flood(x + 1, y);
    if (y > 0) flood(x, y - 1);
    if (y + 1 < h) flood(x, y + 1);
  }
  MaskLayer layer;
  layer.cavity.resize(out.size());
  for (size_t i = 0; i < out.size(); ++i) layer.cavity[i] = img.pixels[i] < 128 && !out[i];
  const std::vector<double> d2 = squared_distances(out, w, h);
  layer.outside2.assign(d2.begin(), d2.end());
  return layer;
}

}  // namespace

WallMeasure measure_walls(MaskStack& stack, double pixel_mm, double layer_mm, double limit_mm) {
  WallMeasure m;
  m.thinnest_mm = limit_mm;
  const long n = long(stack.layers()), reach = long(std::ceil(limit_mm / layer_mm));
  std::vector<MaskLayer> layers(static_cast<size_t>(n));
  int w = 0, h = 0;
  long read = 0;
  for (long k = 0; k < n; ++k) {
    for (; read < std::min(n, k + reach + 1); ++read) layers[size_t(read)] = mask_layer(stack, size_t(read), w, h);
    if (k - reach - 2 >= 0) layers[size_t(k - reach - 2)] = {};  // no longer within reach
    const std::vector<uint8_t>& cavity = layers[size_t(k)].cavity;
    const auto is_cavity = [&](long j, size_t i) { return j >= 0 && j < n && layers[size_t(j)].cavity[i]; };
    for (size_t i = 0; i < cavity.size(); ++i) {
      if (!cavity[i]) continue;
      m.cavity_mm3 += pixel_mm * pixel_mm * layer_mm;
      const size_t x = i % size_t(w), y = i / size_t(w);
      const bool boundary = x == 0 || y == 0 || x + 1 == size_t(w) || y + 1 == size_t(h) || !cavity[i - 1] ||
                            !cavity[i + 1] || !cavity[i - size_t(w)] || !cavity[i + size_t(w)] ||
                            !is_cavity(k - 1, i) || !is_cavity(k + 1, i);
      if (!boundary) continue;
      for (long j = k - reach; j <= k + reach; ++j) {
        const double dz = double(j - k) * layer_mm;
        const double planar2 = j < 0 || j >= n ? 0 : double(layers[size_t(j)].outside2[i]) * pixel_mm * pixel_mm;
        m.thinnest_mm = std::min(m.thinnest_mm, std::sqrt(planar2 + dz * dz));
      }
    }
  }
  return m;
}

}  // namespace slicereuse::test
