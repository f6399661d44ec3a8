#include "sl1_writer.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <exception>
#include <memory>

#include "mask_stack.h"
#include "zip_file_sink.h"
#include "slicereuse/printer/print_estimate.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// The shortest decimal that reads back as v, never with an exponent: the firmware's TOML reader
// takes "1e-05" for a string, and a string for expTime or layerHeight is not used.
std::string num(double v) {
  char buf[400];  // a finite double in fixed notation
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed).ptr);
}

// The pictures PrusaSlicer writes into the archive for the SL1 and SL1S (their printer profiles'
// thumbnails = 400x400,800x480), as thumbnail/thumbnail<W>x<H>.png.
struct ThumbnailSize {
  int width, height;
};
constexpr ThumbnailSize kThumbnails[] = {{400, 400}, {800, 480}};
constexpr size_t kThumbnailCount = sizeof kThumbnails / sizeof kThumbnails[0];

std::string thumbnail_entry(const ThumbnailSize& t) {
  return "thumbnail/thumbnail" + std::to_string(t.width) + "x" + std::to_string(t.height) + ".png";
}

std::string thumbnails_setting() {
  std::string list;
  for (const ThumbnailSize& t : kThumbnails)
    list += (list.empty() ? "" : ",") + std::to_string(t.width) + "x" + std::to_string(t.height);
  return list;
}

std::string config_ini(const Sl1Job& j, const std::string& job, std::time_t now, double used_material_ml) {
  const PrinterProfile& p = j.profile;
  return "action = print\n"
         "expTime = " + num(p.exposure_s) + "\n"
         "expTimeFirst = " + num(p.bottom_exposure_s) + "\n"
         "expUserProfile = 0\n"
         "fileCreationTimestamp = " + utc_time(now, "%Y-%m-%d at %H:%M:%S UTC") + "\n"
         "hollow = 0\n"
         "jobDir = " + job + "\n"
         "layerHeight = " + num(j.layer_height_mm) + "\n"
         "materialName = slicereuse\n"
         "numFade = " + std::to_string(p.faded_layers) + "\n"
         "numFast = " + std::to_string(j.layers) + "\n"
         "numSlow = 0\n"
         "printProfile = slicereuse\n"
         "printTime = " + num(std::round(print_seconds(p, j.layers))) + "\n"
         "printerModel = " + p.printer_model + "\n"
         "printerProfile = slicereuse\n"
         "printerVariant = default\n"
         "prusaSlicerVersion = slicereuse\n"
         "usedMaterial = " + num(std::round(used_material_ml * 1000) / 1000) + "\n";
}

std::string prusaslicer_ini(const Sl1Job& j) {
  const PrinterProfile& p = j.profile;
  const std::string w = num(p.width_px * p.pixel_size_x_um / 1000);
  const std::string h = num(p.height_px * p.pixel_size_y_um / 1000);
  // Besides the display, the settings a PrusaSlicer profile would have to give these masks: no
  // supports, pad, hollowing or size corrections (they are in the part already), so that a model
  // imported with its profile and sliced again comes out the same (elephant-foot compensation
  // too: a plate's first mask has it already, plate_job.h).
  return "absolute_correction = 0\n"
         "bed_shape = 0x0," + w + "x0," + w + "x" + h + ",0x" + h + "\n"
         "display_height = " + h + "\n"
         "display_mirror_x = " + std::to_string(int(p.mirror_x)) + "\n"
         "display_mirror_y = " + std::to_string(int(p.mirror_y)) + "\n"
         "display_orientation = " + (p.portrait ? "portrait" : "landscape") + "\n"
         "display_pixels_x = " + std::to_string(p.width_px) + "\n"
         "display_pixels_y = " + std::to_string(p.height_px) + "\n"
         "display_width = " + w + "\n"
         "elefant_foot_compensation = 0\n"
         "exposure_time = " + num(p.exposure_s) + "\n"
         "faded_layers = " + std::to_string(p.faded_layers) + "\n"
         "gamma_correction = " + num(p.antialiasing ? p.gamma : 0) + "\n"
         "hollowing_enable = 0\n"
         "initial_exposure_time = " + num(p.bottom_exposure_s) + "\n"
         "initial_layer_height = " + num(j.layer_height_mm) + "\n"
         "layer_height = " + num(j.layer_height_mm) + "\n"
         "material_correction = 1,1,1\n"
         "material_print_speed = fast\n"
         "max_print_height = " + num(print_height_mm(j.layers, j.layer_height_mm)) + "\n"
         "pad_enable = 0\n"
         "printer_model = " + p.printer_model + "\n"
         "printer_settings_id = slicereuse\n"
         "printer_technology = SLA\n"
         "printer_variant = default\n"
         "relative_correction = 1,1\n"
         "sla_material_settings_id = slicereuse\n"
         "sla_print_settings_id = slicereuse\n"
         "supports_enable = 0\n"
         "thumbnails = " + thumbnails_setting() + "\n";
}

struct ZipError {
  zip_error_t e;
  ZipError() { zip_error_init(&e); }
  ~ZipError() { zip_error_fini(&e); }
};

// One layer entry: its bytes are asked for only when libzip reaches it on close.
struct Layers {
  const LayerPng* layer_png;
  std::exception_ptr failure;
  ZipError error;
};

struct LayerEntry {
  Layers* layers;
  size_t k;
  size_t pos = 0;
  const std::vector<uint8_t>* bytes = nullptr;
};

zip_int64_t layer_cb(void* ud, void* data, zip_uint64_t len, zip_source_cmd_t cmd) {
  LayerEntry& e = *static_cast<LayerEntry*>(ud);
  Layers& ls = *e.layers;
  try {
    switch (cmd) {
      case ZIP_SOURCE_SUPPORTS:
        return ZIP_SOURCE_SUPPORTS_READABLE;
      case ZIP_SOURCE_STAT: {
        auto* st = ZIP_SOURCE_GET_ARGS(zip_stat_t, data, len, &ls.error.e);
        if (!st) return -1;
        zip_stat_init(st);
        e.bytes = &(*ls.layer_png)(e.k);
        st->size = e.bytes->size();
        st->valid = ZIP_STAT_SIZE;
        return sizeof(zip_stat_t);
      }
      case ZIP_SOURCE_OPEN:
        e.bytes = &(*ls.layer_png)(e.k);
        e.pos = 0;
        return 0;
      case ZIP_SOURCE_READ: {
        const size_t n = std::min<size_t>(len, e.bytes->size() - e.pos);
        std::memcpy(data, e.bytes->data() + e.pos, n);
        e.pos += n;
        return zip_int64_t(n);
      }
      case ZIP_SOURCE_ERROR:
        return zip_error_to_data(&ls.error.e, data, len);
      case ZIP_SOURCE_CLOSE:
      case ZIP_SOURCE_FREE:
        return 0;
      default:
        zip_error_set(&ls.error.e, ZIP_ER_OPNOTSUPP, 0);
        return -1;
    }
  } catch (...) {
    // Exceptions must not unwind through libzip's C frames; carried out after zip_close.
    if (!ls.failure) ls.failure = std::current_exception();
    zip_error_set(&ls.error.e, ZIP_ER_INTERNAL, 0);
    return -1;
  }
}

std::string job_name(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) name.resize(dot);  // ".sl1", ".sl1s"
  return name;
}

// The layers are the PNGs named <job>NNNNN.png, and each reader tells them from the thumbnails
// its own way: PrusaSlicer's import skips every entry whose name contains "thumbnail" (in any
// case), the firmware takes every PNG whose name starts with jobDir.
void check_job_name(const std::string& path, const std::string& job) {
  std::string lower = job;
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find("thumbnail") != std::string::npos || thumbnail_entry(kThumbnails[0]).rfind(job, 0) == 0)
    throw Error("cannot write '" + path + "': its layers would be named " + mask_layer_file_name(job, 0) +
                ", ..., which the readers of the archive cannot tell from its thumbnails (PrusaSlicer's import "
                "skips every entry whose name contains 'thumbnail', the printer takes every PNG whose name "
                "starts with '" + job + "'): give the file another name");
}

// What the SL1 and SL1S firmware (Prusa's slafw, project config) would not print as written.
void check_firmware_limits(const std::string& path, const Sl1Job& j) {
  const PrinterProfile& p = j.profile;
  if (p.printer_model != "SL1" && p.printer_model != "SL1S") return;
  const std::string job = "cannot write '" + path + "' for the " + p.printer_model + ": ";
  if (!(j.layer_height_mm >= 0.01))
    throw Error(job + "its layer height " + num(j.layer_height_mm) +
                " mm is under 0.01 mm, which the printer does not take (it would move 0.05 mm per layer)");
  if (p.faded_layers < 2 || p.faded_layers > 200)
    throw Error(job + "its " + std::to_string(p.faded_layers) +
                " faded layers (numFade) are outside 2..200, which the printer would change");
  if (!(p.exposure_s >= 0.1 && p.exposure_s <= 60))
    throw Error(job + "its exposure time " + num(p.exposure_s) +
                " s (expTime) is outside 0.1..60 s, which the printer would change");
  if (!(p.bottom_exposure_s >= 0.1 && p.bottom_exposure_s <= 120))
    throw Error(job + "its first layers' exposure time " + num(p.bottom_exposure_s) +
                " s (expTimeFirst) is outside 0.1..120 s, which the printer would change");
}

// Every entry carries the archive's creation time (creation_time): made again, it is the same bytes.
void add_entry(zip_t* za, const std::string& name, zip_source_t* src, bool store, std::time_t when,
               const std::string& path) {
  if (!src) throw Error("cannot write '" + path + "': " + zip_strerror(za));
  const zip_int64_t i = zip_file_add(za, name.c_str(), src, ZIP_FL_ENC_UTF_8);
  if (i < 0) {
    zip_source_free(src);
    throw Error("cannot write '" + path + "': entry '" + name + "': " + zip_strerror(za));
  }
  if ((store && zip_set_file_compression(za, zip_uint64_t(i), ZIP_CM_STORE, 0) != 0) ||
      zip_file_set_mtime(za, zip_uint64_t(i), when, 0) != 0)
    throw Error("cannot write '" + path + "': " + zip_strerror(za));
}

}  // namespace

void write_sl1(const std::string& path, const Sl1Job& job, const LayerPng& layer_png) {
  const std::time_t now = creation_time();
  const std::string name = job_name(path);
  check_job_name(path, name);
  check_firmware_limits(path, job);
  // Entry k < layers is layer k's PNG; entry `layers` is config.ini, then come the thumbnails:
  // made when libzip reaches them, after the last layer, when the material and the top view
  // are known.
  // libzip asks for an entry's bytes three times (its size, then its data): made once.
  std::vector<uint8_t> made;
  size_t made_entry = SIZE_MAX;
  const LayerPng entry_bytes = [&](size_t k) -> const std::vector<uint8_t>& {
    if (k < job.layers) return layer_png(k);
    if (k == made_entry) return made;
    if (k == job.layers) {
      const std::string text = config_ini(job, name, now, job.used_material_ml());
      made.assign(text.begin(), text.end());
    } else {
      const ThumbnailSize& t = kThumbnails[k - job.layers - 1];
      job.thumbnail_png(t.width, t.height, made);
    }
    made_entry = k;
    return made;
  };
  // Declared before the archive: zip_discard (on any error) calls layer_cb to free each entry's
  // source, so the entries must outlive the archive.
  Layers layers{&entry_bytes, nullptr, {}};
  std::vector<LayerEntry> entries(job.layers + 1 + kThumbnailCount);
  // libzip writes the archive on zip_close into the staged file (zip_file_sink, which starts its
  // writeback as it goes), which then replaces path.
  StagedOutputs outputs;
  const std::string staged = outputs.file(path);
  ZipError e;
  zip_source_t* sink = zip_file_sink(staged, &e.e);
  zip_t* za = sink ? zip_open_from_source(sink, ZIP_CREATE | ZIP_TRUNCATE, &e.e) : nullptr;
  if (!za) {
    if (sink) zip_source_free(sink);
    throw Error("cannot write '" + path + "': " + zip_error_strerror(&e.e));
  }
  std::unique_ptr<zip_t, void (*)(zip_t*)> archive(za, zip_discard);

  const std::string slicer = prusaslicer_ini(job);
  add_entry(za, "prusaslicer.ini", zip_source_buffer(za, slicer.data(), slicer.size(), 0), false, now,
            path);
  // Layers and thumbnails are PNGs, deflated already: stored.
  for (size_t k = 0; k < entries.size(); ++k) {
    entries[k].layers = &layers;
    entries[k].k = k;
    const std::string entry = k < job.layers    ? mask_layer_file_name(name, k)
                              : k == job.layers ? std::string("config.ini")
                                                : thumbnail_entry(kThumbnails[k - job.layers - 1]);
    add_entry(za, entry, zip_source_function(za, layer_cb, &entries[k]), k != job.layers, now, path);
  }
  if (zip_close(za) != 0) {
    if (layers.failure) std::rethrow_exception(layers.failure);
    throw Error("cannot write '" + path + "': " + zip_strerror(za));
  }
  archive.release();
  outputs.commit();
}

}  // namespace slicereuse
