#pragma once
// AirRegions: the air of a stack of layers (pixels <= UVtools' resin-trap BinaryThreshold),
// labelled in 3D as it streams in, bottom to top, as UVtools' resin trap and suction cup
// detection sees it.
//
// air_layer_of(solid): a layer's solid runs (level_runs.h: its pixels above the threshold) -> its
//   air: the runs of the other pixels, and their regions in the layer, joined by 4-connectivity,
//   each with its pixels, box and whether it touches the image border; a region under 4 pixels
//   (RequiredAreaToProcessCheck) that does not touch the border is taken as solid. Regions are
//   numbered in order of their first run, as label_runs numbers them. Depends on the layer alone
//   (a job computes it in parallel).
// add_layer(air, layer, piece_of): the next layer's air regions. A region joins the air of the
//   layer below that it overlaps by at least 10 pixels (RequiredBlackPixelsToDrain), or by all of
//   the smaller one's pixels when either has fewer (a narrow vent still connects).
// finish(): the air of the last layer opens to the air above the part; every region closes.
// closed(): the regions that closed (no air in the next layer continues them), each with its
//   pixels, box, layers, the most pixels it has in one layer, and whether it reached the image
//   border (drains), the top (open upwards) or layer 0 (sealed by the plate).
// With pieces tracked (AirRegions(true); support_traps.cpp), each region of a layer added is a
//   piece, numbered across the stack in order (add_layer puts each region's into piece_of, or
//   kNoPiece for a region taken as solid), and piece_set(p) names the 3D region a piece ended in: a closed
//   region's piece_set(piece) is that of each of its pieces.
// Memory: the runs of one layer and the regions still open, whatever the number of layers (and,
// tracking pieces, 4 bytes a piece).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "level_runs.h"
#include "slicereuse/util/union_find.h"

namespace slicereuse {

struct AirRegion {
  uint64_t pixels = 0;
  uint64_t layer_pixels = 0;      // in the layer being added
  uint64_t max_layer_pixels = 0;  // most in one layer
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  size_t first_layer = 0, last_layer = 0;
  bool border = false, top = false, plate = false;
  bool marked = false;  // set on a layer's region by the caller, kept by the 3D region it joins
  uint32_t piece = 0;   // tracking pieces: one of its pieces
};

constexpr uint32_t kNoPiece = UINT32_MAX;

// A layer's air: its runs, the region of each run, and the regions (pixels, box, border; their
// layers are set as the layer is added); a region too small to count is solid.
struct AirLayer {
  LevelRuns runs;
  RunLabels labels;
  std::vector<AirRegion> regions;
  std::vector<bool> solid;  // per region: too small to count
};

AirLayer air_layer_of(const LevelRuns& solid);

class AirRegions {
 public:
  explicit AirRegions(bool track_pieces = false) : track_pieces_(track_pieces) {}
  void add_layer(AirLayer air, size_t layer, std::vector<uint32_t>* piece_of = nullptr);
  uint32_t piece_set(uint32_t piece) { return pieces_.find(piece); }
  void finish();
  // The regions closed since the last call (moved out).
  std::vector<AirRegion> take_closed();

 private:
  void merge(uint32_t a, uint32_t b);
  void close_regions_not_in(const std::vector<uint32_t>& alive_roots);

  UnionFind sets_;
  std::vector<AirRegion> regions_;      // by node of sets_; valid at roots
  LevelRuns previous_air_;
  std::vector<uint32_t> previous_labels_;  // per run of previous_air_: its region in its layer
  std::vector<uint32_t> previous_node_;    // per region of the layer below, UINT32_MAX: solid
  std::vector<uint64_t> previous_area_;    // per region of the layer below: its pixels
  std::vector<uint8_t> previous_inner_rows_;  // per row: holds air not reaching the image border
  std::vector<AirRegion> closed_;
  bool track_pieces_ = false;
  UnionFind pieces_;  // tracking pieces: every piece of the stack
};

}  // namespace slicereuse
