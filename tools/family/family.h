#pragma once
// Mass-customization families for tests and benchmarks: a base closed shape (member 0) and
// members with exactly the same faces whose vertices are moved by smooth, seeded deformations.
//
// Shapes (all closed, consistently oriented outward):
//   arch   - dental-arch-like shell: an inverted-U wall profile with tooth ridges swept along a
//            horseshoe, rounded closed ends; sections are thin U-shaped rings (outer loop + hole).
//   ear    - ear-canal-like hollow cup: a bent, tapering elliptic tube with inner and outer walls
//            joined by a rounded rim, closed tip; sections have a hole, the tilted rim merges them.
//   handle - mug-handle-like torus standing upright (genus 1): mid sections are two loops.
//   box, sphere, torus (axis z; genus 1).
// Every base is scaled uniformly and shifted so that its z range is exactly [0, height].
//
// Members: x-y deformed as smooth functions of z (scale, shear, bend, twist, Gaussian bumps),
// each a bijection of every plane z = const, so no member self-intersects and z is untouched:
// every member has the base's z range. Then z is remapped monotonically per (x, y) column, so
// slice topology changes between members; z min stays 0:
//   ZChange::Everywhere  z scaled by up to 3 %, local bumps of up to 3 % of the height that
//                        vanish at the bottom and top: nearly every layer moves (the transfer
//                        re-slices all layers at once).
//   ZChange::Band        a local edit: within one band of heights (a fifth of the height,
//                        somewhere between 20 % and 80 %) z moves by up to 2 % of the height,
//                        smoothly in (x, y) and vanishing at the band's ends; outside the band
//                        z is untouched, so most layers stay certifiable and only the band's
//                        are re-sliced.
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse::test {

enum class ZChange { None, Everywhere, Band };

struct FamilyOptions {
  std::string shape = "arch";  // one of family_shapes()
  size_t faces = 20000;        // target face count; the base has it within a few per cent
  double height = 14.484;      // mm; the base spans z in [0, height] exactly
  uint64_t seed = 1;           // member parameters depend only on (seed, member index)
  ZChange z_change = ZChange::None;
};

// The accepted shape names, in the order listed above.
const std::vector<std::string>& family_shapes();
// Genus of a shape's surface: 0, or 1 for handle and torus. Throws Error for an unknown name.
int family_shape_genus(const std::string& shape);

// Member 0. Throws Error for an unknown shape, faces < 500 or height <= 0.
Mesh make_family_base(const FamilyOptions& options);
// Member `index` (>= 0) of the family whose base is `base`: the same F, V deformed as described
// above; index 0 returns the base unchanged. Deterministic in (base, options.seed,
// options.z_change, index).
Mesh make_family_member(const Mesh& base, const FamilyOptions& options, int index);
// The deformation that make_family_member(base, options, index) applies to base's vertices,
// applied to other points (3 per point), e.g. the vertices of another tessellation of the same
// shape: the true images of a cross-parameterization test.
std::vector<double> deform_like_family_member(const Mesh& base, const FamilyOptions& options, int index,
                                              const std::vector<double>& points);

// The rigid turn gen_family --tilt gives every member, as a lab orients a shell for printing (its
// overhangs then need supports): deg degrees about the x axis, then moved in z so that the turned
// base's lowest vertex lies at z = 0; the same turn for all, so the family keeps its faces.
struct FamilyTilt {
  FamilyTilt(const Mesh& base, double deg);
  void apply(Mesh& member) const;
  double c = 1, s = 0, dz = 0;  // cos, sin of the angle; the move down
};

}  // namespace slicereuse::test
