#pragma once
// region_perimeter: the summed length of a region's loops (each closed), in its own units.
#include <clipper.hpp>

#include <cmath>

namespace slicereuse::test {

inline double region_perimeter(const ClipperLib::Paths& region) {
  double p = 0;
  for (const ClipperLib::Path& loop : region)
    for (size_t i = 0; i < loop.size(); ++i) {
      const ClipperLib::IntPoint& a = loop[i];
      const ClipperLib::IntPoint& b = loop[(i + 1) % loop.size()];
      p += std::hypot(double(b.X - a.X), double(b.Y - a.Y));
    }
  return p;
}

}  // namespace slicereuse::test
