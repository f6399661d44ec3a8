#include "mask_layers.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/raster/rasterize_layer.h"

namespace slicereuse::test {

Slices make_slices(const std::vector<Layer>& layers, double h) {
  Slices s;
  s.thickness = h;
  s.layer_begin.push_back(0);
  s.contour_begin.push_back(0);
  for (size_t k = 0; k < layers.size(); ++k) {
    s.layer_z.push_back((double(k) + 0.5) * h);
    for (const Loop& l : layers[k]) {
      for (const auto& p : l.pts) {
        s.xyz.push_back(p[0]);
        s.xyz.push_back(p[1]);
        s.xyz.push_back(s.layer_z.back());
      }
      s.contour_begin.push_back(s.xyz.size() / 3);
      s.contour_open.push_back(l.open);
    }
    s.layer_begin.push_back(s.contour_open.size());
  }
  validate_slices(s);
  return s;
}

Loop rect(double x0, double y0, double x1, double y1, bool clockwise) {
  Loop l{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
  if (clockwise) std::reverse(l.pts.begin(), l.pts.end());
  return l;
}

Loop star(double cx, double cy, double r0, double r1, int spikes) {
  Loop l;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double a = 3.141592653589793 * i / spikes + 0.1234, r = i % 2 ? r0 : r1;
    l.pts.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return l;
}

PrinterProfile small_display() {
  PrinterProfile p;
  p.width_px = 200;
  p.height_px = 200;
  p.pixel_size_x_um = 100;
  p.pixel_size_y_um = 100;
  return p;
}

std::vector<uint8_t> raster(const Slices& s, size_t k, const PrinterProfile& p, size_t* open) {
  std::vector<uint8_t> img(size_t(p.width_px) * p.height_px, 7);
  const size_t o = rasterize_layer(s, k, p, img.data());
  if (open) *open = o;
  return img;
}

}  // namespace slicereuse::test
