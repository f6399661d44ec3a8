#pragma once
// PrinterProfile: the display the masks are made for, where the part sits on it, and what the
// printer's file says besides the images (exposure, bottom and faded layers). Named presets of
// real printers are in printer_presets.h.
// validate_printer_profile throws Error naming the bad field when a profile cannot be
// rasterized or written: display size outside 1..kMaxDisplayPixels px per side, a pixel size
// that is not a positive finite number, a non-finite offset, a gamma that is not a finite number
// >= 0, exposure settings, lift moves or elephant-foot figures that are negative or not finite,
// a lift speed of 0, grey levels other than 16, 128 or 256, a negative file version. Exporters
// call it before creating any output.
//
// The display is given as PrusaSlicer's printer settings give it: width_px x height_px pixels
// (display_pixels_x/y) of pixel_size_x_um x pixel_size_y_um along the build plate's x and y.
// Placement: the model's XY origin sits at the display centre, shifted by offset_x/y_mm.
// The image as written (mask_image_layout) follows PrusaSlicer's display_orientation and
// display_mirror_x/y, as PrusaSlicer 2.5 writes them (checked against its --export-sla):
//   landscape: width_px x height_px, columns along +x, row 0 at the largest y;
//   portrait:  height_px x width_px, the landscape image turned 90 degrees counter-clockwise
//              (columns along -y, row 0 at the largest x);
//   then mirror_x flips the image's columns, mirror_y its rows.
//
// Its defaults are the method's display (1024 x 768 pixels of 75 um, landscape, no mirrors),
// written only here: hosts take their parameters' defaults from it (PrinterProfile{}.width_px).
#include <string>

namespace slicereuse {

struct PrinterProfile {
  int width_px = 1024;
  int height_px = 768;
  double pixel_size_x_um = 75;
  double pixel_size_y_um = 75;
  bool portrait = false;
  double offset_x_mm = 0;
  double offset_y_mm = 0;
  bool mirror_x = false;
  bool mirror_y = false;
  bool antialiasing = false;  // 8-bit coverage instead of 1-bit
  // Anti-aliased masks have 256 grey levels round(255 * f^gamma) of each pixel's exactly covered
  // area f (rasterize_layer.h): PrusaSlicer's gamma_correction. 1 is linear coverage; 0 its
  // threshold, which is the binary mask itself (a pixel is on when its centre is inside); other
  // values bend the curve as PrusaSlicer's AGG rasterizer does (agg::gamma_power). Not used when
  // antialiasing is off.
  double gamma = 1;
  // How many grey levels an anti-aliased mask may have: 256, or as few as the printer's own file
  // holds, with the levels its readers decode them to (grey_levels.h): 128 (Chitubox .ctb: 0 and
  // the odd levels 3..255), 16 (Anycubic Photon Workshop: the multiples of 17). Each pixel gets
  // the representable level nearest its 256-level value, so the PNG folder of such a printer
  // equals what its file decodes to.
  int grey_levels = 256;

  // What the print file carries for the printer besides the images.
  std::string printer_model;       // .sl1 printerModel (SL1, SL1S); empty for other printers
  double exposure_s = 6;           // each layer's exposure
  double bottom_exposure_s = 35;   // the first layers' exposure
  int bottom_layers = 1;           // layers exposed bottom_exposure_s long
  int faded_layers = 10;           // layers after those whose exposure steps down (SL1 numFade),
                                   // and over which elephant_foot_mm fades
  double layer_move_s = 5;         // time between two exposures (tilt, or lift and retract)

  // Lift-and-retract printers (.goo, .ctb, Anycubic files): after each exposure the platform
  // rises lift_mm at lift_speed and comes back at retract_speed (the bottom layers' own figures
  // first), then the light stays off light_off_s before the next exposure. Defaults: typical
  // Elegoo values. Tilting printers (Prusa) do not use them.
  double bottom_lift_mm = 5, lift_mm = 5;
  double bottom_lift_speed_mm_min = 65, lift_speed_mm_min = 65;
  double bottom_retract_speed_mm_min = 150, retract_speed_mm_min = 150;
  double bottom_light_off_s = 0, light_off_s = 0;
  // The print file's version where its format has several the printer may take (.ctb: 3 or 4);
  // 0: the newest written.
  int file_version = 0;

  // The layers on the build plate spread (elephant foot): the first is shrunk by this much, the
  // next ones less, fading to none over faded_layers (faded_layers.h, elephant_foot.h;
  // PrusaSlicer's elefant_foot_compensation), keeping features at least the min width wide
  // (elefant_foot_min_width). 0: no compensation.
  double elephant_foot_mm = 0;
  double elephant_foot_min_width_mm = 0.2;
};

// The image a profile's masks have: its size in pixels, and how build-plate coordinates map to
// it (printer_profile.h's placement, orientation and mirrors).
struct MaskImageLayout {
  int width = 0, height = 0;
  // Which model coordinate (0 = x, 1 = y) runs along the image's columns and rows.
  int column_axis = 0, row_axis = 1;
  // Whether columns run against that coordinate (column 0 at its largest value), and rows along
  // it (row 0 at its smallest value): the image's flips from orientation and mirrors together.
  bool columns_descend = false, rows_ascend = false;
  double column_um = 0, row_um = 0;        // a pixel's size along the columns and rows
  double column_offset_mm = 0, row_offset_mm = 0;  // the profile's offset along those coordinates
};

MaskImageLayout mask_image_layout(const PrinterProfile& profile);

// The build-plate point (xy, mm) at continuous coordinates of such an image: u along its columns,
// v down its rows, pixel (c, r) being [c, c + 1] x [r, r + 1]; where something seen on a mask lies.
void plate_point_at_pixel(const MaskImageLayout& m, double u, double v, double xy[2]);

// Largest display side, in pixels, accepted by the core and by the mask filters' parameters.
constexpr int kMaxDisplayPixels = 65535;

void validate_printer_profile(const PrinterProfile& profile);

}  // namespace slicereuse
