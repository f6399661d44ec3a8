#pragma once
// PrinterProfile: the display the masks are made for and where the part sits on it, and
// validate_printer_profile, which throws Error naming the bad field when a profile cannot be
// rasterized: display size outside 1..kMaxDisplayPixels px per side, a pixel size that is not a
// positive finite number, a non-finite offset, or a gamma that is not a finite number >= 0.
// Exporters call it before creating any output.
//
// Placement: the model's XY origin sits at the display centre, shifted by offset_x/y_mm; row 0
// is the top of the image (largest y). mirror_x / mirror_y flip the image.
//
// Its defaults are the display defaults (1024 x 768 pixels of 75 um), written only here: hosts
// take their parameters' defaults from it (PrinterProfile{}.width_px, ...).

namespace slicereuse {

struct PrinterProfile {
  int width_px = 1024;
  int height_px = 768;
  double pixel_size_x_um = 75;
  double pixel_size_y_um = 75;
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
};

// Largest display side, in pixels, accepted by the core and by the mask filters' parameters.
constexpr int kMaxDisplayPixels = 65535;

void validate_printer_profile(const PrinterProfile& profile);

}  // namespace slicereuse
