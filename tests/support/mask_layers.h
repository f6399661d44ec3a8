#pragma once
// Layers of hand-made loops for the mask tests (test_masks.cpp, test_antialiasing.cpp): Loop and
// Layer, their Slices, a few shapes, the small display the tests draw on, and a layer's image.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse::test {

// A contour's points (x, y in mm); closed unless open.
struct Loop {
  std::vector<std::array<double, 2>> pts;
  bool open = false;
};
using Layer = std::vector<Loop>;

// One layer per element, thickness h, validated.
Slices make_slices(const std::vector<Layer>& layers, double h = 0.1);

// Axis-aligned rectangle, counter-clockwise (or clockwise for a hole).
Loop rect(double x0, double y0, double x1, double y1, bool clockwise = false);

// A non-convex star with coordinates that fall nowhere special on the pixel grid: 2 * spikes
// points alternately at radius r1 and r0, counter-clockwise.
Loop star(double cx, double cy, double r0, double r1, int spikes);

// 200 x 200 pixels of 100 um: 20 x 20 mm around the origin.
PrinterProfile small_display();

// rasterize_layer's image of layer k (the buffer filled with 7 first, so unwritten pixels show);
// the number of open contours in *open when given.
std::vector<uint8_t> raster(const Slices& s, size_t k, const PrinterProfile& p, size_t* open = nullptr);

}  // namespace slicereuse::test
