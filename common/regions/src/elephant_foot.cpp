#include "slicereuse/regions/elephant_foot.h"

#include <cmath>
#include <vector>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/simplify_paths.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

namespace {

// Miter joins, limit 3: PrusaSlicer's offsets' defaults (ClipperUtils). A straight contour moves
// by exactly the compensation and a corner stays a corner (no arc of new vertices); a round
// opening would also cut slivers off convex corners, kept unshrunk as islands.
constexpr double kMiterLimit = 3;
// The opening by min_width / 2 + compensation gives back the region only up to rounding: along
// the whole boundary of a dense contour it leaves slivers some micrometres wide (the boundary's
// tiny bumps, its miters), which would count as narrow features and keep nearly all the
// boundary unshrunk (an arch's first layer lost 10 of the 66 mm^2 the compensation takes), and
// which depend on every other part clipped with it. Parts of the difference thinner than this
// twice over are no features: a fifth of the finest display's pixel (the SL1S's 50 um).
constexpr double kSliverMm = 0.005;
constexpr double kSimplifyMm = 0.001;

ClipperLib::Paths offset_region(const ClipperLib::Paths& region, double delta_mm) {
  ClipperLib::ClipperOffset offset(kMiterLimit);
  offset.AddPaths(region, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths out;
  offset.Execute(out, double(region_units(delta_mm)));
  return out;
}

// The pieces of a less b with room for a disc of radius_mm: those of area below the disc's are
// left out, since no erosion by radius_mm leaves anything of them (pieces meet at most at
// points, so a disc lies within one), and the sliver opening that follows gives the same at a
// fraction of the cost: a dense contour's difference is thousands of slivers (2,600 on an arch's
// nine faded layers, 21 of them kept).
ClipperLib::Paths difference_pieces_holding_disc(const ClipperLib::Paths& a, const ClipperLib::Paths& b,
                                                 double radius_mm) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const double r = double(region_units(radius_mm)), disc = M_PI * r * r;
  ClipperLib::Paths out;
  std::vector<const ClipperLib::PolyNode*> outers(tree.Childs.begin(), tree.Childs.end());
  while (!outers.empty()) {
    const ClipperLib::PolyNode* outer = outers.back();
    outers.pop_back();
    double area = std::abs(ClipperLib::Area(outer->Contour));
    for (const ClipperLib::PolyNode* hole : outer->Childs) {
      area -= std::abs(ClipperLib::Area(hole->Contour));
      outers.insert(outers.end(), hole->Childs.begin(), hole->Childs.end());  // islands in the hole
    }
    if (area < disc) continue;
    out.push_back(outer->Contour);
    for (const ClipperLib::PolyNode* hole : outer->Childs) out.push_back(hole->Contour);
  }
  return out;
}

}  // namespace

void compensate_elephant_foot(const LayerView& layer, double z, double compensation_mm, double min_width_mm,
                              Slices& out) {
  if (!(std::isfinite(compensation_mm) && compensation_mm >= 0))
    throw Error(format("the elephant-foot compensation is %g mm; it must be a finite, non-negative number",
                       compensation_mm));
  if (!(std::isfinite(min_width_mm) && min_width_mm >= 0))
    throw Error(format("the elephant-foot minimal width is %g mm; it must be a finite, non-negative number",
                       min_width_mm));
  ClipperLib::Paths region = layer_region(layer);
  if (compensation_mm > 0) {
    // Features an opening by min_width + 2 compensation removes: shrunk, they would be narrower
    // than min_width (or gone), so they keep their own width, and a collar of the compensation
    // into the rest of the region, which shrinks away from them, keeps them joined to it.
    // Found on the region simplified to a micrometre, a fifth of the slivers' width: a dense
    // contour's offsets cross themselves at every bump, and resolving that is most of the cost.
    const double half = min_width_mm / 2 + compensation_mm;
    const ClipperLib::Paths coarse = simplify_paths(region, double(region_units(kSimplifyMm)));
    const ClipperLib::Paths opened = offset_region(offset_region(coarse, -half), half);
    const ClipperLib::Paths narrow =
        offset_region(offset_region(difference_pieces_holding_disc(coarse, opened, kSliverMm), -kSliverMm), kSliverMm);
    if (narrow.empty()) {
      region = offset_region(region, -compensation_mm);  // most layers: nothing narrow to keep
    } else {
      const ClipperLib::Paths kept = clip_regions(region, offset_region(narrow, compensation_mm), ClipperLib::ctIntersection);
      region = clip_regions(offset_region(region, -compensation_mm), kept, ClipperLib::ctUnion);
    }
  }
  region_into_layer(region, z, out);
}

}  // namespace slicereuse
