#pragma once
// What the lift-and-retract print files (.goo, .ctb, Anycubic's) say alike besides the images,
// from the profile (printer_profile.h):
//   layer_moves(p, bottom)          a layer's lift and retract, the bottom layers' own or the others'
//   wait_after_retract_s(p, moves)  the wait after each retract: the light-off delay, or what makes
//                                   the moves take the profile's layer_move_s when that is longer
//                                   (a preset's layer_move_s counts the light-off delay already)
//   antialiasing_level(p)           the slicer's anti-aliasing setting as ChiTuBox and UVtools write
//                                   it: 1 ("off") for binary masks, 8 (their highest
//                                   supersampling, standing for exact coverage) for grey ones;
//                                   informative, the grey levels are in the images
//   kResinGramsPerMm3               the weight the files state per mm^3: 1.1 g/ml, a typical resin
#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct LayerMoves {
  double lift_mm, lift_speed, retract_speed, light_off_s;
};

inline constexpr double kResinGramsPerMm3 = 1.1e-3;

LayerMoves layer_moves(const PrinterProfile& p, bool bottom);
double wait_after_retract_s(const PrinterProfile& p, const LayerMoves& m);
unsigned antialiasing_level(const PrinterProfile& p);

}  // namespace slicereuse
