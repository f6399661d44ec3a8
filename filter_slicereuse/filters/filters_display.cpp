// The printer, shared by Export Mask Images and Make Print Job: its parameters (a named preset,
// or the custom values bound to PrinterProfile, whose defaults they are), the warning for a part
// that does not fit the display, and the figures both filters return about it.
#include <initializer_list>
#include <utility>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

// The printer choice's values: every preset's id, then "custom".
std::vector<std::string> printer_choices() {
  std::vector<std::string> ids;
  for (const PrinterPreset& p : printer_presets()) ids.push_back(p.id);
  ids.push_back(kCustomPrinter);
  return ids;
}

ParamList<PrinterProfile> custom_printer_params() {
  const PrinterProfile d;
  const Range pixels = Range::between(1, kMaxDisplayPixels, "pixels");
  ParamList<PrinterProfile> l;
  l.whole(&PrinterProfile::width_px, "width_px", "Display pixels x", d.width_px, pixels,
          "Custom printer: the display's pixels along the build plate's x (PrusaSlicer's display_pixels_x).")
      .whole(&PrinterProfile::height_px, "height_px", "Display pixels y", d.height_px, pixels,
             "Custom printer: the display's pixels along the build plate's y (PrusaSlicer's display_pixels_y).")
      .number(&PrinterProfile::pixel_size_x_um, "pixel_size_x_um", "Pixel size x (um)", d.pixel_size_x_um,
              Range::above(0, "um"), "Custom printer: width of one pixel on the build plate along x, in micrometres.")
      .number(&PrinterProfile::pixel_size_y_um, "pixel_size_y_um", "Pixel size y (um)", d.pixel_size_y_um,
              Range::above(0, "um"), "Custom printer: height of one pixel on the build plate along y, in micrometres.")
      .flag(&PrinterProfile::portrait, "portrait", "Portrait", d.portrait,
            "Custom printer: write the images turned 90 degrees, as PrusaSlicer's display_orientation = portrait "
            "(the image is pixels y wide and pixels x tall).")
      .flag(&PrinterProfile::mirror_x, "mirror_x", "Mirror x", d.mirror_x,
            "Custom printer: flip the images left-right, as PrusaSlicer's display_mirror_x.")
      .flag(&PrinterProfile::mirror_y, "mirror_y", "Mirror y", d.mirror_y,
            "Custom printer: flip the images top-bottom, as PrusaSlicer's display_mirror_y.")
      .number(&PrinterProfile::exposure_s, "exposure_s", "Exposure (s)", d.exposure_s, Range::at_least(0, "s"),
              "Custom printer: exposure time of each layer, written into the print file.")
      .number(&PrinterProfile::bottom_exposure_s, "bottom_exposure_s", "Bottom exposure (s)", d.bottom_exposure_s,
              Range::at_least(0, "s"), "Custom printer: exposure time of the first (bottom) layers.")
      .whole(&PrinterProfile::bottom_layers, "bottom_layers", "Bottom layers", d.bottom_layers,
             Range::between(0, 1000, "layers"), "Custom printer: how many layers get the bottom exposure.")
      .whole(&PrinterProfile::faded_layers, "faded_layers", "Faded layers", d.faded_layers,
             Range::between(0, 1000, "layers"),
             "Custom printer: layers after the bottom ones whose exposure steps down to the normal one (SL1's "
             "numFade); the elephant-foot compensation fades over as many from the first (0: the first alone).")
      .whole(&PrinterProfile::file_version, "file_version", "Print file version", d.file_version,
             Range::between(0, 1000, ""),
             "Custom printer: the print file's version where its format has several: .ctb 3 or 4 (5, Chitu's "
             "encrypted CTB, is refused: its scheme is closed), Anycubic files 516 to 518 as their extension "
             "allows. 0 (the default): the newest the file takes.")
      .number(&PrinterProfile::offset_x_mm, "offset_x_mm", "Offset x (mm)", d.offset_x_mm, Range::any(),
              "Shift of the model along the build plate's x from the display centre, in mm (every printer).")
      .number(&PrinterProfile::offset_y_mm, "offset_y_mm", "Offset y (mm)", d.offset_y_mm, Range::any(),
              "Shift of the model along the build plate's y from the display centre, in mm (every printer).")
      .flag(&PrinterProfile::antialiasing, "antialiasing", "Anti-aliasing", d.antialiasing,
            "Grey edge pixels from the exact area of each pixel the part covers (256 levels) instead of black/white "
            "masks (every printer).")
      .number(&PrinterProfile::gamma, "gamma", "Anti-aliasing gamma", d.gamma, Range::at_least(0, ""),
              "PrusaSlicer's gamma_correction: grey level 255 * coverage^gamma; 1 linear, 0 the binary threshold "
              "(every printer; used with anti-aliasing).");
  return l;
}

}  // namespace

PrinterProfile PrinterSettings::profile() const {
  PrinterProfile p = profile_before_elephant_foot();
  if (elephant_foot != kPrintersElephantFoot) p.elephant_foot_mm = elephant_foot;
  return p;
}

PrinterProfile PrinterSettings::profile_before_elephant_foot() const {
  const std::vector<PrinterPreset>& presets = printer_presets();
  if (printer >= presets.size()) return given;
  // A custom value given with a preset would be silently replaced by the preset's: refused.
  const PrinterProfile d;
  std::string set;
  for (const auto& [name, differs] : std::initializer_list<std::pair<const char*, bool>>{
           {"width_px", given.width_px != d.width_px},
           {"height_px", given.height_px != d.height_px},
           {"pixel_size_x_um", given.pixel_size_x_um != d.pixel_size_x_um},
           {"pixel_size_y_um", given.pixel_size_y_um != d.pixel_size_y_um},
           {"portrait", given.portrait != d.portrait},
           {"mirror_x", given.mirror_x != d.mirror_x},
           {"mirror_y", given.mirror_y != d.mirror_y},
           {"exposure_s", given.exposure_s != d.exposure_s},
           {"bottom_exposure_s", given.bottom_exposure_s != d.bottom_exposure_s},
           {"bottom_layers", given.bottom_layers != d.bottom_layers},
           {"faded_layers", given.faded_layers != d.faded_layers},
           {"file_version", given.file_version != d.file_version}})
    if (differs) set += (set.empty() ? "" : ", ") + std::string(name);
  if (!set.empty())
    throw Error("printer " + presets[printer].id + " sets the display and exposure, but " + set +
                " were given too: choose printer custom to give them, or leave them at their defaults");
  PrinterProfile p = presets[printer].profile;
  p.offset_x_mm = given.offset_x_mm;
  p.offset_y_mm = given.offset_y_mm;
  p.antialiasing = given.antialiasing;
  p.gamma = given.gamma;
  return p;
}

std::string print_file_patterns() {
  std::string patterns;
  for (const PrintFormat& f : print_formats()) patterns += (patterns.empty() ? "*" : " *") + f.extension;
  return patterns;
}

std::string print_file_tooltip(const char* tooltip) {
  std::string list;
  for (const PrintFormat& f : print_formats()) list += (list.empty() ? "" : ", ") + f.extension + " (" + f.name + ")";
  return std::string(tooltip) + " Print files by extension: " + list + "; any other name is a folder of PNG images.";
}

std::string PrinterSettings::name() const {
  const std::vector<PrinterPreset>& presets = printer_presets();
  return printer < presets.size() ? presets[printer].id : kCustomPrinter;
}

ParamList<PrinterSettings> printer_params() {
  std::string tooltip = "The printer the masks are made for: ";
  for (const PrinterPreset& p : printer_presets())
    tooltip += p.id + " (" + p.name + "), ";
  tooltip += "or custom (the default: the display and exposure values below, which default to the method's "
             "display). A preset sets the display and exposure (leave their values at the defaults); the offsets and "
             "anti-aliasing below apply to every printer.";
  ParamList<PrinterSettings> l;
  l.choice(&PrinterSettings::printer, "printer", "Printer", printer_choices(), printer_presets().size(),
           tooltip.c_str())
      .include(&PrinterSettings::given, custom_printer_params())
      .number(&PrinterSettings::elephant_foot, "elephant_foot", "Elephant-foot compensation (mm)",
              kPrintersElephantFoot, Range::at_least(kPrintersElephantFoot, "mm"),
              "How much the first layer (on the plate, or the pad's bottom) shrinks against elephant-foot spread, "
              "in mm (PrusaSlicer's elefant_foot_compensation; features narrower than the printer's "
              "elefant_foot_min_width keep their width); as PrusaSlicer's, it fades layer by layer to none over "
              "the printer's faded layers (10 on the SL1S: 0.2 mm on layer 0, 0.022 mm on layer 8). -1 (the "
              "default): the printer's own, 0.2 mm on the SL1S SPEED as PrusaSlicer's profile, 0 on the others "
              "(every printer).");
  return l;
}

void log_printer(Host& host, const char* filter, const PrinterSettings& settings) {
  const PrinterProfile p = settings.profile();
  const MaskImageLayout image = mask_image_layout(p);
  host.log(format("%s: printer %s: %dx%d display of %g x %g um pixels, %s%s%s, images %dx%d, %s", filter,
                  settings.name().c_str(), p.width_px, p.height_px, p.pixel_size_x_um, p.pixel_size_y_um,
                  p.portrait ? "portrait" : "landscape", p.mirror_x ? ", mirror x" : "", p.mirror_y ? ", mirror y" : "",
                  image.width, image.height,
                  p.antialiasing ? format("anti-aliased (gamma %g)", p.gamma).c_str() : "binary"));
}

void log_display_warning(Host& host, const char* filter, const MaskExportStats& stats, const PrinterProfile& profile) {
  if (stats.outside_display)
    host.log(format("%s: warning: the part (x %.2f to %.2f mm, y %.2f to %.2f mm, offset %g, %g mm) "
                    "does not fit the %.2f x %.2f mm display; its masks are cut off at the edges",
                    filter, stats.min_x, stats.max_x, stats.min_y, stats.max_y, profile.offset_x_mm,
                    profile.offset_y_mm, 1e-3 * profile.width_px * profile.pixel_size_x_um,
                    1e-3 * profile.height_px * profile.pixel_size_y_um));
}


void add_display_figures(const MaskExportStats& stats, Result& result) {
  result["ignored_open_contours"] = int64_t(stats.ignored_open_contours);
  result["outside_display"] = int64_t(stats.outside_display);
  result["part_min_x_mm"] = stats.min_x;
  result["part_max_x_mm"] = stats.max_x;
  result["part_min_y_mm"] = stats.min_y;
  result["part_max_y_mm"] = stats.max_y;
}

std::vector<std::string> with_display_keys(std::vector<std::string> keys) {
  Result figures;
  add_display_figures(MaskExportStats{}, figures);
  for (const auto& entry : figures) keys.push_back(entry.first);
  return keys;
}

}  // namespace slicereuse::plugin
