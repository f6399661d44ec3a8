#pragma once
// export_masks: every layer's mask (rasterize_layer.h) written as a folder of PNGs, a Prusa
// .sl1/.sl1s archive, an Elegoo .goo file, a Chitubox .ctb file or an Anycubic Photon Workshop
// file, from a whole stack of slices or from ranges of layers made one at a time.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/printability/printability_report.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct MaskExportStats {
  size_t layers = 0;
  size_t ignored_open_contours = 0;
  // The closed contours' extent in mm, model coordinates, and whether it leaves the display
  // (the masks are then cut off at the display's edges).
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  bool outside_display = false;
  double seconds = 0;
};

// Printability checked on the masks as they are written (check_layers.h, with the profile's pixel
// size and the stack's layer thickness): every layer's mask, the levels the file holds, in
// order, then done(report) after the last layer and before the file is committed, so that done
// may refuse the file by throwing (nothing is written then). A PNG folder's layers, written out
// of order, are checked as they are read back (check_print_file.h), before the folder appears.
struct MaskChecks {
  std::function<void(PrintabilityReport report)> done;
};

// Writes one PNG per layer as <folder>/<prefix>NNNNN.png, or, when output_path ends in .sl1 or
// .sl1s (any case), a Prusa SL1/SL1S archive of the same PNGs plus config.ini and
// prusaslicer.ini, or, when it ends in .goo, an Elegoo .goo file (goo_writer.h; a portrait
// profile is refused), or, when it ends in .ctb, a Chitubox .ctb file of the profile's
// file_version, 3 or 4 (0: 4), unencrypted (ctb_writer.h), or, when it ends in .pwmx, .pwma,
// .pwmb, .pm5, .pm5s or .pm4n, an Anycubic Photon Workshop file of the version that extension's
// printer takes, or the profile's file_version (photon_workshop_writer.h; a portrait profile is
// refused). The masks have the grey levels the file holds (print_formats.h). Multithreaded; only
// a few layers are held in memory at a time. Atomic:
// nothing is left under the final name on failure. A point of a closed contour whose x or y is
// not finite is refused (Error naming the point and layer).
MaskExportStats export_masks(const Slices& s, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress = {}, const MaskChecks* checks = nullptr);

// Part of a range's layers: the range's layers [first, first + slices.layers()), counted from 0
// within the range.
struct SlicePart {
  Slices slices;
  size_t first = 0;
  bool support = false;  // a support's layers: the resin traps supports close are lit (support_traps.h)
};

// A stack with supports (SliceChunks::supports, LayerMaker::supports: a part's support flag set
// on some layer) has every layer's mask made before any is written: the resin traps its supports
// close are found over the whole stack and lit whole in every file (support_traps.h). Memory then
// holds every layer's mask (runs of levels: 13 kB a layer for an ear shell on the SL1S), refused
// in words beforehand when it would not fit; each layer is made once.

// A stack too large to hold at once, made a range of layers at a time (layer_chunks.h):
// make(i, progress) returns the slices of layers [first[i], first[i + 1]) in parts, a layer's
// contours being those of every part that has it (a build plate: one part per member, drawn as
// it is, without a merged copy; a layer no part has is empty). Export calls it once per range, in
// order, on the calling thread, and frees each range's parts before it makes the next, so memory
// holds one range (plus a few images).
struct SliceChunks {
  std::vector<size_t> first;  // range starts, then the layer count
  double thickness = 0;
  std::function<std::vector<SlicePart>(size_t i, const Progress& progress)> make;
  bool supports = false;  // some part is a support's
};

// The same export of the stack the ranges make up, equal to exporting it whole.
MaskExportStats export_masks(const SliceChunks& chunks, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress = {}, const MaskChecks* checks = nullptr);

// A stack made a layer at a time, where its mask is drawn: make(k, parts) puts layer k's
// contours into parts, as parts of one layer each (first 0; a layer's contours are those of every
// part, and a part may have none). It is called on the encoding threads, for different layers at
// once, each thread with its own parts, kept between its calls so that their buffers are reused:
// memory holds a few layers, and a layer's points are drawn while they are in cache. For a stack
// whose layers cost little to make apart (a build plate's transferred members, plate_job.h).
struct LayerMaker {
  size_t layers = 0;
  double thickness = 0;
  std::function<void(size_t k, std::vector<SlicePart>& parts)> make;
  bool supports = false;  // some part is a support's
};

// The same export of the stack the maker makes, equal to exporting it whole.
MaskExportStats export_masks(const LayerMaker& maker, const PrinterProfile& profile, const std::string& output_path,
                             const Progress& progress = {}, const MaskChecks* checks = nullptr);

}  // namespace slicereuse
