#pragma once
// plate_job: one build plate's print file. Every layer's mask is the union of the placed
// members' layers at that height.
//
// Input: the members already placed (place_mesh, placement.h: turned and moved in x-y, z
// untouched), and how their contours are made:
//   reuse (options.encoding set): the source's encoding transferred onto each member's placed
//     vertices in exact mode (transfer_contours.h), so each member's layers equal direct slicing
//     of the placed member; the plate's planes are the encoding's (z_start, thickness): every
//     member sits on the source's build plate, as Make Print Job transfers it;
//   direct (options.encoding null): each placed member sliced directly on the plate's planes,
//     options.slicing's thickness from its z_start (NaN: the lowest vertex of all members).
// The plate has the planes z_start + (k + 1/2) h up to its tallest member's top; each member's
// layers are those its own direct slicing from the same z_start would have (a shorter member
// simply ends). Layer k's contours are the members' layer k contours one after another: their
// footprints lie apart (arrange_plates.h), so the nonzero rule fills exactly the union of
// their own masks, and no anti-aliased pixel is shared when they are more than a pixel apart.
// Memory: reusing, each member's transfer is prepared once for the plate (ExactTransfer,
// transfer_contours.h), and each member's layer k is transferred where layer k's mask is drawn,
// on that thread (LayerMaker, export_masks.h): the plate holds a few layers of points, and those
// of the layers its members cannot transfer, which are sliced directly beforehand (the layers
// the certificate refuses; a member changed in z fails it on some). When those would hold more
// than the budget below, or slicing directly, the layers are made and exported a range at a time
// (SliceChunks, export_masks.h), a range holding at most options.range_budget_bytes of contour
// points of all members (0: the whole plate at once; reusing, at most 256 MB, so that a plate
// fills at most that much fresh memory), each member's as it was made (the masks draw them where
// they are, with no merged copy). Every way gives the same masks as the plate made whole.
// Output: the print file of the profile (export_masks: PNG folder, .sl1, .sl1s, .goo), atomic, and
// the figures. Throws Error for no members, an encoding without a layer thickness, or whatever
// transfer, slicing or export refuse.
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/masks/export_masks.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct PlateJobOptions {
  const Slices* encoding = nullptr;  // the source's encoding (reuse), or null (direct slicing)
  // Its encoded_edge_ends (transfer_contours.h), or null: then looked up in each member's faces.
  const Buffer<uint32_t>* edge_ends = nullptr;
  // With edge_ends, their vertex_order (transfer_contours.h), or null: then each member's layers
  // are transferred from its own vertex array, in its own order.
  const VertexOrder* vertex_order = nullptr;
  SliceOptions slicing;              // direct slicing's thickness and z_start
  uint64_t range_budget_bytes = 0;
};

struct PlateJobStats {
  size_t layers = 0;              // the plate's
  size_t points = 0;              // all members' contour points
  size_t transferred_layers = 0;  // member layers, summed over members
  size_t resliced_layers = 0;     // member layers sliced directly (all of them without an encoding)
  size_t ranges = 1;               // of layers made before their masks; 0: made where drawn
  double z_start = 0, thickness = 0;
  // Transfer or slicing, in all ranges; made where drawn, summed over the threads that made the
  // layers (it overlaps the masks then), plus the slicing beforehand.
  double slicing_seconds = 0;
  MaskExportStats masks;
};

// The plate's planes for options (see above), and its z_start and thickness.
std::vector<double> plate_planes(const std::vector<Mesh>& placed, const PlateJobOptions& options, double* z_start,
                                 double* thickness);

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& options,
                           const PrinterProfile& profile, const std::string& output_path,
                           const Progress& progress = {});

}  // namespace slicereuse
