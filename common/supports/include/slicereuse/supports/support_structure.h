#pragma once
// support_structure: a part's support structure as plain data, before it is meshed, after
// PrusaSlicer's SupportTreeBuilder (its heads, pillars, junctions, bridges and pad), in the
// part's frame. build_support_structure (support_tree.h) makes it in stages; mesh_support_
// structure (support_tree.h) turns it into closed shells.
//   heads: one per support point kept, a vertical cone whose narrow end (tip) lies penetration
//     above the point, inside the part, widening to the pillar's radius at its back below;
//   pillars: vertical cylinders from a head's back down to the pad's top (or the ground) on a
//     base cone, to a foot on the part, or to a junction where a bridge takes them on;
//   feet: small heads upside down, from a pillar's bottom into the part (leaning to where the
//     part blocked the pillar's rim);
//   junctions: where a bridge ends, on a pillar's axis or at a head's back;
//   bridges: cylinders between two junctions, descending from the upper at least as steeply as
//     the critical angle: a head's to a neighbouring pillar, or between tall pillars;
//   pad: its bottom and top outlines under the pillars on the ground.
// head_zones_of: where the structure may enter the part (each head and foot), as vertical cones:
// a head's cone, a foot's the vertical cone around its tip that holds it (its lean added to
// its back's radius).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicereuse {

constexpr size_t kNoPiece = SIZE_MAX;
using Point3 = std::array<double, 3>;

// A cone between two horizontal circles: the narrow end (tip) in the part, the wide end (back)
// on the rest of the structure.
struct SupportCone {
  Point3 tip{}, back{};
  double r_tip = 0, r_back = 0;
};

// What a head's back rests on: its pillar, a bridge (a junction at its back), or the part below
// (the part is nearer than the head's width: the back lies in it).
enum class HeadRest : uint8_t { Pillar, Bridge, Part };

struct SupportHead {
  SupportCone cone;          // vertical, tip above back
  size_t point = 0;          // the support point it holds
  double penetration = 0;    // the tip's height above the point
  HeadRest rest = HeadRest::Pillar;
  size_t pillar = kNoPiece;  // rest == Pillar
};

// What a pillar's bottom stands on: the pad's top (or the ground) on a base, a foot, or a
// junction at the upper end of a bridge.
enum class PillarEnd : uint8_t { Ground, Foot, Bridge };

struct SupportPillar {
  double x = 0, y = 0, z_bottom = 0, z_top = 0, radius = 0;
  PillarEnd end = PillarEnd::Ground;
  // end == Ground: the base, a cone from base_radius at z_bottom to the pillar's radius at base_top.
  double base_radius = 0, base_top = 0;
  size_t head = kNoPiece;  // the head it hangs from
  size_t foot = kNoPiece;  // end == Foot
};

struct SupportFoot {
  SupportCone cone;        // tip below back, leaning when the tip is off the pillar's axis
  double penetration = 0;  // the tip's depth below where the part blocked the pillar
  size_t pillar = 0;
};

struct SupportJunction {
  Point3 at{};
  size_t pillar = kNoPiece;  // the pillar whose axis it lies on, or
  size_t head = kNoPiece;    // the head whose back it is
};

struct SupportBridge {
  size_t upper = 0, lower = 0;  // junctions
  double radius = 0;
  bool link = false;  // between two pillars (stiffening), not carrying a head
};

// Corner i of bottom lies under corner i of top; both counter-clockwise seen from +z. Empty: no pad.
struct SupportPad {
  std::vector<std::array<double, 2>> bottom, top;
  double z_bottom = 0, z_top = 0;
};

// A vertical cone where supports may enter the part: radius r_bottom at z_bottom, r_top at z_top.
struct HeadZone {
  double x = 0, y = 0;
  double z_bottom = 0, z_top = 0;
  double r_bottom = 0, r_top = 0;
};

struct SupportStructure {
  std::vector<SupportHead> heads;
  std::vector<SupportPillar> pillars;
  std::vector<SupportFoot> feet;
  std::vector<SupportJunction> junctions;
  std::vector<SupportBridge> bridges;
  SupportPad pad;
};

// In the heads' order, each head's zone followed by its foot's.
std::vector<HeadZone> head_zones_of(const SupportStructure& s);

}  // namespace slicereuse
