#pragma once
// TopView: the part as seen from above, gathered while its layers are encoded, for the pictures
// a print file carries (thumbnail_png.h): which cells of the build plate the layers cover, and
// how high the highest layer covering each is.
//   TopView view(display, layers)   a grid over the display's area (printer_profile.h, offsets
//                                   included) of square cells, as small as the display's pixels
//                                   but at most kTopViewCells along the longer side
//   view.add(layer, k)              layer k of the stack, drawn
//                                   if it is one of the layers the view is made of (below): any
//                                   thread, any order; each layer once
//   view.finish()                   after the last add: the HeightMap (the same on every call)
// A layer is drawn as a binary mask at the grid's resolution (rasterize_layer_runs: a cell is
// covered when its centre is inside), in the same visit to its points as its image, so the
// picture costs no pass of its own over the contours. The view is made of at most
// kTopViewLayers layers: the stack cut into that many bands of equal height, the top layer of
// each (every layer of a stack of up to kTopViewLayers layers). Why: drawing every layer of a
// thin-layer stack would cost about as much CPU time as its masks (bench/RESULTS.md); a feature
// thinner than a band (1/128 of the part's height) may be missing from the picture, whose
// shading by height has 128 steps then. The map is in model axes, whatever the display's
// orientation and mirrors: the picture shows the part, not the printer's image of it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/layer_view.h"

namespace slicereuse {

// Longest side of the grid in cells: the thumbnails are at most 800 pixels wide, and a part on
// PrusaSlicer's thumbnails rarely fills the display.
constexpr int kTopViewCells = 512;
// Most layers a view is drawn from (above).
constexpr size_t kTopViewLayers = 128;

// Row 0 at the largest y, columns along +x. level: per cell, 0 where no drawn layer covers it,
// else 1 + 254 * k / (layers - 1) (rounded down) of the highest drawn layer k that does (255 for
// a single layer).
struct HeightMap {
  int cols = 0, rows = 0;
  std::vector<uint8_t> level;  // cols * rows
};

class TopView {
 public:
  TopView(const PrinterProfile& display, size_t layers);
  void add(const LayerView& layer, size_t k);
  const HeightMap& finish();
  // Whether layer k is one of those the view is drawn from.
  bool draws(size_t k) const;

 private:
  using Canvas = std::vector<uint8_t>;
  // A canvas per thread drawing at the same time, merged by finish(): no locking per cell.
  std::unique_ptr<Canvas> take();
  void give(std::unique_ptr<Canvas> canvas);

  PrinterProfile grid_;  // the grid as a binary landscape display without mirrors
  size_t layers_;
  HeightMap map_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Canvas>> idle_;
};

}  // namespace slicereuse
