#pragma once
// LayerChecker: UVtools' printability checks on a stack of masks fed bottom to top.
//
// In: the stack's layers in order (layer 0 on the plate), each a grey MaskImage or MaskRuns of the
// same size (0 unlit .. 255 fully lit), the pixel size in mm (x, y) and the layer height in mm.
// Out (finish(), called once after the last layer): a PrintabilityReport (printability_report.h) with, under UVtools' default
// settings (IssueManager, LayerIssueConfiguration):
//   - islands: a 4-connected region of pixels > 1 of a layer above layer 0 whose pixels >= 10
//     rest on fewer than max(1, 0.25 x their count) pixels >= 150 of the layer below; one that
//     rests on at least 10 (and a quarter of that) is an island only if it holds an overhang
//     pixel (UVtools' enhanced detection);
//   - overhangs: the pixels brighter than the layer below's by more than 127, eroded 40 times by
//     a 3x3 cross (an L1 disc of radius 40; the border of the two layers' bounding box does not
//     erode), as 8-connected regions;
//   - resin traps: 3D regions of air (pixels <= 100) connected to neither the image border at any
//     layer nor the air of the top layer, and not reaching layer 0 (a cavity on the plate is
//     not a trap); regions of a layer smaller than 4 pixels are taken as solid, and air joins
//     the air of the layer below only through at least 10 shared pixels;
//   - suction cups: such regions of air closed towards the plate but open at the top layer
//     (they drain only upwards: the floor, the walls and the vat's film make a cup at each
//     peel), at least 100 pixels in one layer and 0.5 mm high;
//   - touching bounds: pixels >= 127 within 5 pixels of the image's edges, consecutive layers
//     as one finding.
// Memory: the previous layer's image and runs, and the open air regions; a 10,000-layer stack
// costs no more than a 10-layer one. Time per layer: proportional to the runs and lit pixels,
// plus the pixels of the bounding box of each layer's new overhanging pixels.
// add_layer throws Error when a layer's size differs from the first layer's.
//
// prepare_layer: a layer's mask -> what the checks need of it alone (its runs at the checks'
// levels, its lit and air regions), for add_layer. Thread-safe: a job prepares each layer on
// the thread that made it, so that the checker's work in order is only joining the layers.
#include <cstddef>
#include <memory>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printability/printability_report.h"

namespace slicereuse {

struct LayerFacts;

struct PreparedLayer {
  PreparedLayer();
  ~PreparedLayer();
  PreparedLayer(PreparedLayer&&) noexcept;
  PreparedLayer& operator=(PreparedLayer&&) noexcept;
  std::unique_ptr<LayerFacts> facts;
};

PreparedLayer prepare_layer(MaskRuns layer);

class LayerChecker {
 public:
  LayerChecker(double pixel_x_mm, double pixel_y_mm, double layer_height_mm);
  ~LayerChecker();
  LayerChecker(const LayerChecker&) = delete;
  LayerChecker& operator=(const LayerChecker&) = delete;

  // A layer as an image, or as runs of levels (mask_png.h's MaskRuns, what the rasterizer and
  // print files' decoders give: checked in time proportional to its runs, not its pixels).
  void add_layer(const MaskImage& layer);
  void add_layer(MaskRuns layer);
  void add_layer(PreparedLayer layer);
  PrintabilityReport finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace slicereuse
