#pragma once
// GooFootprint: the two preview images of a .goo header (goo_writer.h), made from the masks:
// the union of every layer's lit pixels, a top view of the build plate (x to the right, y up:
// the image's mirrors undone), fitted into a square at the plate's true proportions, centred.
//   add(runs)     ORs one layer's mask (MaskRuns, as the layer is encoded) into a grid of
//                 kGrid x kGrid cells, in time proportional to its runs; any thread, any order
//   preview(n)    n x n RGB565 pixels, row-major from the top: each the share of lit cells in
//                 its n-th of the grid, as a grey level (round(255 * share)); n divides kGrid
//                 (the two previews, 116 and 290, do: 580 = 5 * 116 = 2 * 290)
// A cell is lit when a lit pixel overlaps it.
// Why a union of footprints: it shows where the part stands on the plate, cheaply; a rendering
// of the model would need the mesh, which a mask export does not have.
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "slicereuse/masks/mask_png.h"
#include "slicereuse/masks/printer_profile.h"

namespace slicereuse {

class GooFootprint {
 public:
  static constexpr int kGrid = 580;

  explicit GooFootprint(const PrinterProfile& profile);
  void add(const MaskRuns& runs);
  std::vector<uint16_t> preview(int n) const;

 private:
  static constexpr int kWords = (kGrid + 63) / 64;  // one row of cells as bits
  static std::pair<int, int> span(double a, double b);
  MaskImageLayout layout_;
  double cell_per_column_, cell_per_row_, left_, top_;  // pixel edges -> cell coordinates
  std::vector<std::atomic<uint64_t>> cells_;             // kGrid rows of kWords
};

}  // namespace slicereuse
