#include "slicereuse/regions/region_triangles.h"

#include <algorithm>
#include <limits>

#include "slicereuse/regions/region_pieces.h"

namespace slicereuse {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

// Twice the signed area of (a, b, c), exactly: positive when counter-clockwise.
__int128 cross(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  return __int128(b.X - a.X) * __int128(c.Y - a.Y) - __int128(b.Y - a.Y) * __int128(c.X - a.X);
}

// The piece's part on one side of the line y = c (below: y <= c, else y >= c).
Paths side_of(const Paths& piece, cInt c, bool below) {
  constexpr cInt far = cInt(1) << 50;
  const Path half = below ? Path{{-far, -far}, {far, -far}, {far, c}, {-far, c}}
                          : Path{{-far, c}, {far, c}, {far, far}, {-far, far}};
  ClipperLib::Clipper clipper;
  clipper.AddPaths(piece, ClipperLib::ptSubject, true);
  clipper.AddPath(half, ClipperLib::ptClip, true);
  Paths out;
  clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

// Ear clipping of a simple counter-clockwise loop: a convex corner whose triangle holds no other
// corner is cut off, collinear corners are dropped, until three are left.
void clip_ears(Path loop, std::vector<RegionTriangle>& out) {
  std::vector<size_t> next(loop.size()), prev(loop.size());
  for (size_t i = 0; i < loop.size(); ++i) next[i] = (i + 1) % loop.size(), prev[i] = (i + loop.size() - 1) % loop.size();
  size_t left = loop.size(), i = 0, tried = 0;
  const auto inside = [&](size_t a, size_t b, size_t c) {  // another corner in or on triangle abc
    for (size_t j = next[c]; j != a; j = next[j]) {
      const IntPoint& p = loop[j];
      if ((p.X == loop[a].X && p.Y == loop[a].Y) || (p.X == loop[b].X && p.Y == loop[b].Y) ||
          (p.X == loop[c].X && p.Y == loop[c].Y))
        continue;
      if (cross(loop[a], loop[b], p) >= 0 && cross(loop[b], loop[c], p) >= 0 && cross(loop[c], loop[a], p) >= 0)
        return true;
    }
    return false;
  };
  while (left > 3) {
    const size_t a = prev[i], c = next[i];
    const __int128 turn = cross(loop[a], loop[i], loop[c]);
    // An ear, or, after a full round without one (corners rounded onto the grid), any convex corner.
    const bool cut = turn > 0 && (tried > left ? true : !inside(a, i, c));
    if (turn == 0 || cut) {
      if (cut) out.push_back({loop[a], loop[i], loop[c]});
      next[a] = c, prev[c] = a, --left, tried = 0;
      i = a;
      continue;
    }
    i = c;
    if (++tried > 2 * left) return;  // no convex corner at all: a degenerate remainder, no area
  }
  if (cross(loop[prev[i]], loop[i], loop[next[i]]) > 0) out.push_back({loop[prev[i]], loop[i], loop[next[i]]});
}

}  // namespace

std::vector<RegionTriangle> region_triangles(const ClipperLib::Paths& region) {
  std::vector<RegionTriangle> out;
  std::vector<Paths> todo = region_pieces(region);
  while (!todo.empty()) {
    Paths piece = std::move(todo.back());
    todo.pop_back();
    if (piece.size() == 1) {
      if (piece[0].size() >= 3) clip_ears(std::move(piece[0]), out);
      continue;
    }
    cInt lo = std::numeric_limits<cInt>::max(), hi = std::numeric_limits<cInt>::min();
    for (const IntPoint& p : piece[1]) lo = std::min(lo, p.Y), hi = std::max(hi, p.Y);
    if (hi - lo < 2) {  // a hole under 2 nm tall: no line runs through it; its area is nothing
      piece.erase(piece.begin() + 1);
      todo.push_back(std::move(piece));
      continue;
    }
    const cInt c = lo + (hi - lo) / 2;
    for (bool below : {true, false})
      for (Paths& p : region_pieces(side_of(piece, c, below))) todo.push_back(std::move(p));
  }
  return out;
}

}  // namespace slicereuse
