#include "slicereuse/regions/clip_to_box.h"

#include <utility>

#include "slicereuse/regions/clip_regions.h"

namespace slicereuse {
namespace {

using ClipperLib::IntPoint;
using ClipperLib::IntRect;
using ClipperLib::Path;

// The sides of the box a point lies strictly beyond, a bit each.
unsigned beyond(const IntPoint& p, const IntRect& box) {
  return unsigned(p.X < box.left) | unsigned(p.X > box.right) << 1 | unsigned(p.Y < box.top) << 2 |
         unsigned(p.Y > box.bottom) << 3;
}

// A loop with its runs beyond one side cut to their ends (see the header); empty when it lies
// wholly beyond one side.
Path near_box(const Path& loop, const IntRect& box) {
  const size_t n = loop.size();
  unsigned common = ~0u;
  size_t start = n;  // a vertex beyond no side: no run goes round the loop's start
  for (size_t i = 0; i < n; ++i) {
    const unsigned b = beyond(loop[i], box);
    common &= b;
    if (b == 0 && start == n) start = i;
  }
  if (n == 0 || common != 0) return {};
  if (start == n) return loop;  // beyond several sides all round: kept whole
  Path kept;
  for (size_t j = 0; j < n;) {
    unsigned sides = beyond(loop[(start + j) % n], box);
    kept.push_back(loop[(start + j) % n]);
    size_t k = j + 1;  // past the run's last vertex
    for (; sides != 0 && k < n && (sides & beyond(loop[(start + k) % n], box)) != 0; ++k)
      sides &= beyond(loop[(start + k) % n], box);
    if (k - j > 1) kept.push_back(loop[(start + k - 1) % n]);
    j = k;
  }
  return kept;
}

}  // namespace

ClipperLib::Paths clip_to_box(const ClipperLib::Paths& region, const ClipperLib::IntRect& box) {
  ClipperLib::Paths near;
  for (const Path& loop : region) {
    Path kept = near_box(loop, box);
    if (!kept.empty()) near.push_back(std::move(kept));
  }
  if (near.empty()) return {};
  return clip_regions(near, {{{box.left, box.top}, {box.right, box.top}, {box.right, box.bottom}, {box.left, box.bottom}}},
                      ClipperLib::ctIntersection);
}

}  // namespace slicereuse
