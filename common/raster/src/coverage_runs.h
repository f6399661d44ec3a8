#pragma once
// coverage_runs: a layer's anti-aliased mask (rasterize_layer.h) as runs of equal non-zero
// grey levels, replacing out's content; coverage_png: the same mask straight into an 8-bit PNG
// (png replaced), the bytes encode_mask_png gives for those runs, without keeping them unless
// runs is not null (then replaced by them, from the same sweep: the pixels are made once). The
// caller has checked the layer and the profile (antialiasing on, gamma > 0). Both return the
// number of open contours ignored.
//
// Each pixel's grey level is round(255 * f^gamma) of f, the exact area of the pixel covered
// by the region, as font rasterizers compute it (FreeType's "gray" rasterizer, stb_truetype's
// v2, libart): every oriented edge adds to each pixel it crosses the signed area between
// itself and the pixel's right side (the trapezoid rule on its piece in that pixel), and its
// height to every pixel further right, which a sweep along the row carries; pixels no edge
// crosses come out as runs. f is the integral of the winding number over the pixel, taken as
// an absolute value (so either orientation of a part fills it, as the nonzero rule does) and
// clamped to 1. That equals the area the nonzero rule covers wherever the winding number
// takes only the values 0 and +1 (or 0 and -1) within the pixel: loops that do not overlap,
// with holes running against their outer loop. Where loops overlap (winding 2), a pixel that
// the overlap covers only in part comes out brighter than the united area would make it (the
// overlap counts twice before the clamp); inside the overlap, pixels are full as they should be.
//
// Exactness: positions inside a pixel are fixed point (1/65536 of a pixel side), and all sums
// are of integers, so the result does not depend on the order in which edges are added (contour
// order, loop start point) and an edge and its reverse cancel exactly; each edge is cut at row
// and column boundaries from its lower endpoint, alone. A pixel no edge enters has exactly full
// or no coverage. The image's flips (mirrors, orientation) are applied to the finished rows
// (rather than to the coordinates, whose rounding would not be symmetric), so they flip the
// image exactly.
//
// Speed: the pieces are added straight into the sums of a strip of rows small enough to stay
// in cache (the edges are sorted by strip first, not the pieces), and the rows are swept from a
// bit mask of the pixels touched, visiting only its words that are not zero. Within a strip the
// edges are sorted by kind (one pixel, one or two row or column crossings, the rest), and each
// kind is added by code without a loop or branch that depends on the edge, the same numbers
// add_edge's general walk gives: which kind an edge is follows no pattern, and the general
// walk's steps were mispredicted about once per edge. The sweep hands each row's runs to the
// PNG's deflater (png_rows.h) without a branch on their kind either. A strip without edges is
// not swept: its rows are black, added at once (on a 16K display most strips are).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/layer_view.h"

namespace slicereuse {

size_t coverage_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out);
size_t coverage_png(const LayerView& layer, const PrinterProfile& profile, std::vector<uint8_t>& png,
                    MaskRuns* runs = nullptr);

}  // namespace slicereuse
