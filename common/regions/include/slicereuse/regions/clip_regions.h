#pragma once
// clip_regions: two regions (Clipper polygons, either orientation, filled by the nonzero rule)
// -> their union, intersection, difference (a less b) or xor, as simple polygons.
#include <clipper.hpp>

namespace slicereuse {

inline ClipperLib::Paths clip_regions(const ClipperLib::Paths& a, const ClipperLib::Paths& b, ClipperLib::ClipType type) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

}  // namespace slicereuse
