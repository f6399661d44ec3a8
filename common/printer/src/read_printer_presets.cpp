#include "read_printer_presets.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <set>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/json_value.h"

namespace slicereuse::detail {
namespace {

// An object's keys, read with messages that say whose key it is (where: "the job of printer
// preset 'prusa_sl1' (presets.json)").
struct Fields {
  const JsonValue& object;
  std::string where;

  const JsonValue& at(const char* key) const { return object.at(key, where); }
  std::string of(const char* key) const { return format("\"%s\" in %s", key, where.c_str()); }
  const std::string& text(const char* key) const { return at(key).as_string(of(key)); }
  double number(const char* key) const { return at(key).as_number(of(key)); }
  bool flag(const char* key) const { return at(key).as_bool(of(key)); }
  int whole(const char* key) const {
    const double x = number(key);
    if (x != std::floor(x) || x < INT_MIN || x > INT_MAX)
      throw Error(format("%s is %g, not a whole number", of(key).c_str(), x));
    return int(x);
  }
};

// A lift-and-retract printer's moves (printer_profile.h), when the preset gives them.
void read_lift(const Fields& lift, PrinterProfile& p) {
  p.bottom_lift_mm = lift.number("bottom_height_mm");
  p.lift_mm = lift.number("height_mm");
  p.bottom_lift_speed_mm_min = lift.number("bottom_speed_mm_min");
  p.lift_speed_mm_min = lift.number("speed_mm_min");
  p.bottom_retract_speed_mm_min = lift.number("bottom_retract_speed_mm_min");
  p.retract_speed_mm_min = lift.number("retract_speed_mm_min");
  p.bottom_light_off_s = lift.number("bottom_light_off_s");
  p.light_off_s = lift.number("light_off_s");
}

PrinterProfile profile_of(const Fields& display, bool antialiasing, const Fields& job) {
  PrinterProfile p;
  p.width_px = display.whole("width_px");
  p.height_px = display.whole("height_px");
  p.pixel_size_x_um = display.number("pixel_x_um");
  p.pixel_size_y_um = display.number("pixel_y_um");
  p.portrait = display.flag("portrait");
  p.mirror_x = display.flag("mirror_x");
  p.mirror_y = display.flag("mirror_y");
  p.antialiasing = antialiasing;
  p.gamma = 1;
  p.printer_model = job.text("model");
  p.exposure_s = job.number("exposure_s");
  p.bottom_exposure_s = job.number("bottom_exposure_s");
  p.bottom_layers = job.whole("bottom_layers");
  p.faded_layers = job.whole("faded_layers");
  p.layer_move_s = job.number("layer_move_s");
  p.elephant_foot_mm = job.number("elephant_foot_mm");
  p.elephant_foot_min_width_mm = job.number("elephant_foot_min_width_mm");
  if (display.object.find("grey_levels")) p.grey_levels = display.whole("grey_levels");
  if (job.object.find("file_version")) p.file_version = job.whole("file_version");
  if (const JsonValue* lift = job.object.find("lift")) read_lift({*lift, "the lift of " + job.where}, p);
  return p;
}

}  // namespace

std::vector<PrintFormat> read_print_formats(const std::string& text, const std::string& name) {
  const JsonValue doc = parse_json(text, name);
  const auto& list = doc.at("formats", name).as_array("\"formats\" in " + name);
  std::vector<PrintFormat> formats;
  for (size_t k = 0; k < list.size(); ++k) {
    const Fields f{list[k], format("print format %zu (%s)", k + 1, name.c_str())};
    PrintFormat pf{f.text("extension"), f.text("name"), f.whole("grey_levels")};
    const std::string& e = pf.extension;
    if (e.size() < 2 || e[0] != '.' ||
        !std::all_of(e.begin() + 1, e.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }))
      throw Error(f.of("extension") + " is '" + e + "', not a dot and lower-case letters and digits");
    if (pf.grey_levels != 16 && pf.grey_levels != 128 && pf.grey_levels != 256)
      throw Error(f.of("grey_levels") + " is " + std::to_string(pf.grey_levels) + ", not 16, 128 or 256");
    for (const PrintFormat& g : formats)
      if (g.extension == e) throw Error(f.where + ": extension '" + e + "' is given twice");
    formats.push_back(std::move(pf));
  }
  return formats;
}

std::vector<PrinterPreset> read_printer_presets(const std::string& text, const std::string& name) {
  const JsonValue doc = parse_json(text, name);
  const auto& list = doc.at("presets", name).as_array("\"presets\" in " + name);
  if (list.empty()) throw Error(name + " has no presets");
  const std::vector<PrintFormat> formats = read_print_formats(text, name);
  std::vector<PrinterPreset> presets;
  std::set<std::string> ids;
  for (size_t k = 0; k < list.size(); ++k) {
    const Fields unnamed{list[k], format("printer preset %zu (%s)", k + 1, name.c_str())};
    const std::string& id = unnamed.text("id");
    const Fields preset{list[k], format("printer preset '%s' (%s)", id.c_str(), name.c_str())};
    if (!ids.insert(id).second) throw Error(preset.where + " is given twice");
    PrinterPreset p{id, preset.text("name"), preset.text("extension"), {}};
    if (!p.extension.empty() &&
        std::none_of(formats.begin(), formats.end(), [&](const PrintFormat& f) { return f.extension == p.extension; }))
      throw Error(preset.of("extension") + " is '" + p.extension + "', none of the print formats in " + name);
    p.profile = profile_of({preset.at("display"), "the display of " + preset.where}, preset.flag("antialiasing"),
                           {preset.at("job"), "the job of " + preset.where});
    try {
      validate_printer_profile(p.profile);
    } catch (const Error& e) {
      throw Error(preset.where + ": " + e.what());
    }
    presets.push_back(std::move(p));
  }
  return presets;
}

}  // namespace slicereuse::detail
