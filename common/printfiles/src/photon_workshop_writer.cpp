#include "photon_workshop_writer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

#include "byte_fields.h"
#include "lift_fields.h"
#include "mask_stack.h"
#include "merged_runs.h"
#include "photon_workshop_format.h"
#include "slicereuse/printer/print_estimate.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// A named table's start: its name and length.
void table(LittleEndian& w, const char* name, uint64_t length) {
  w.text(name, kPwsNameSize);
  w.u32(uint32_t(length));
}

constexpr uint32_t kMaxAddress = std::numeric_limits<uint32_t>::max();

// The version written and the kind of file, checked.
struct Target {
  const PwsFileKind* kind;
  unsigned version;
};

// Table sizes, whole (name, length and contents), by version.
size_t file_mark_size(unsigned v) { return v >= 518 ? 64 : v >= 517 ? 56 : 52; }
size_t header_length(unsigned v) { return v >= 518 ? 96 : v >= 517 ? 92 : 84; }  // after name and length
size_t machine_size(unsigned v) { return v >= 518 ? 224 : 156; }
constexpr size_t kPreviewSize = kPwsTableBase + 12 + size_t(kPwsPreviewWidth) * kPwsPreviewHeight * 2;
constexpr size_t kPreview2Size = kPwsTableBase + 12 + size_t(kPwsPreview2Width) * kPwsPreview2Height * 2;
constexpr size_t kColourTableSize = 4 + 4 + 16 + 4;
constexpr size_t kExtraSize = kPwsTableBase + 4 + 6 * 4 + 4 + 6 * 4;
constexpr size_t kSoftwareSize = 164, kModelSize = kPwsTableBase + 32;

// Where each table goes: everything before the layers' data, whose size L fixes.
struct Layout {
  uint64_t header = 0, preview = 0, colours = 0, layer_def = 0, extra = 0, machine = 0, software = 0, model = 0,
           sub_layer_def = 0, preview2 = 0, layer_data = 0;
};

Layout layout(unsigned v, size_t layers) {
  Layout a;
  uint64_t at = file_mark_size(v);
  const auto place = [&at](uint64_t& where, uint64_t size) {
    where = at;
    at += size;
  };
  place(a.header, kPwsTableBase + header_length(v));
  place(a.preview, kPreviewSize);
  place(a.colours, kColourTableSize);
  place(a.layer_def, kPwsTableBase + 4 + uint64_t(layers) * kPwsLayerDefSize);
  place(a.extra, kExtraSize);
  place(a.machine, machine_size(v));
  if (v >= 517) {
    place(a.software, kSoftwareSize);
    place(a.model, kModelSize);
  }
  if (v >= 518) {
    place(a.sub_layer_def, kPwsTableBase + 8 + uint64_t(layers) * kPwsSubLayerDefSize);
    place(a.preview2, kPreview2Size);
  }
  a.layer_data = at;
  return a;
}

Target check_job(const std::string& path, const PhotonWorkshopJob& job) {
  const PrinterProfile& p = job.profile;
  const std::string ext = lower_extension(path);
  const PwsFileKind* kind = photon_workshop_kind(ext);
  if (!kind) {
    std::string known;
    for (const PwsFileKind& k : kPwsFileKinds) known += std::string(known.empty() ? "" : ", ") + k.extension;
    throw Error("cannot write '" + path + "' as an Anycubic Photon Workshop file: its extension is none of " + known);
  }
  std::string held;
  for (unsigned v : kind->versions)
    if (v) held += (held.empty() ? "" : ", ") + std::to_string(v);
  if (p.file_version != 0 && !kind->holds(unsigned(p.file_version)))
    throw Error(format("cannot write '%s': file version %d is not one slicereuse writes for a %s file (the %s takes "
                       "version %s)",
                       path.c_str(), p.file_version, ext.c_str(), kind->machine, held.c_str()));
  const Target t{kind, p.file_version ? unsigned(p.file_version) : kind->newest()};
  if (p.portrait)
    throw Error("cannot write '" + path +
                "': an Anycubic Photon Workshop image is as wide as the display's x resolution, with no portrait "
                "orientation (Anycubic's displays are landscape): choose a landscape display");
  const MaskImageLayout m = mask_image_layout(p);
  if (m.width < 1 || m.height < 1 || m.width > 0xFFFF || m.height > 0xFFFF)
    throw Error(format("cannot write '%s': an image of %d x %d pixels, beyond the 1..65535 pixels a side that the "
                       "file's resolution fields hold",
                       path.c_str(), m.width, m.height));
  if (layout(t.version, job.layers).layer_data > kMaxAddress)
    throw Error(format("cannot write '%s': %zu layers, more than the tables of a %s file hold (their entries would "
                       "reach beyond the 4 GiB its addresses count)",
                       path.c_str(), job.layers, ext.c_str()));
  for (const auto& [name, s] : {std::make_pair("exposure_s", p.exposure_s),
                                std::make_pair("bottom_exposure_s", p.bottom_exposure_s)})
    if (!(s >= 0 && s <= FLT_MAX))
      throw Error(format("cannot write '%s': an exposure (%s) of %g s, out of the range its 32-bit field holds",
                         path.c_str(), name, s));
  const double seconds = std::round(print_seconds(p, job.layers));
  if (!(seconds <= double(kMaxAddress)))
    throw Error(format("cannot write '%s': a print time of %.0f s, more than its 32-bit field holds (4294967295 s)",
                       path.c_str(), seconds));
  return t;
}

// Appends a pw0Img run of n pixels of a 4-bit code: black and white (codes 0 and 0xF) in 2 bytes
// with a 12-bit length, grey in 1 byte with a 4-bit one, split at those lengths.
void append_pw0_run(std::vector<uint8_t>& out, unsigned code, uint64_t n) {
  const bool wide = code == 0 || code == 0xF;
  const uint64_t most = wide ? kPwsMaxRun : kPwsMaxGreyRun;
  while (n > 0) {
    const unsigned m = unsigned(std::min(n, most));
    if (wide) {
      out.push_back(uint8_t(code << 4 | m >> 8));
      out.push_back(uint8_t(m & 0xFF));
    } else {
      out.push_back(uint8_t(code << 4 | m));
    }
    n -= m;
  }
}

// Layer k's moves: the bottom layers' or the others'.
bool bottom_layer(const PrinterProfile& p, size_t k) { return k < size_t(std::max(0, p.bottom_layers)); }

void preview_table(LittleEndian& w, const std::vector<uint16_t>& pixels, int width, int height, bool second) {
  if (pixels.size() != size_t(width) * size_t(height))
    throw Error(format("Photon Workshop writer: a preview image of %zu pixels, expected %d x %d", pixels.size(), width,
                       height));
  table(w, second ? "PREVIEW2" : "PREVIEW", (second ? kPreview2Size : kPreviewSize));
  w.u32(unsigned(width));
  if (second) {
    w.u16(4293);  // background colours, as UVtools writes them
    w.u16(0);
  } else {
    w.text("x", 4);  // the mark between width and height
  }
  w.u32(unsigned(height));
  for (uint16_t px : pixels) w.u16(px);
}

// Everything before the layers' data: the file mark and every table, with the layers' entries.
std::vector<uint8_t> tables(const Target& t, const PhotonWorkshopJob& job, const PhotonWorkshopSummary& s,
                            const std::vector<uint8_t>& layer_defs, const std::vector<uint8_t>& sub_layer_defs) {
  const PrinterProfile& p = job.profile;
  const unsigned v = t.version;
  const MaskImageLayout m = mask_image_layout(p);
  const Layout a = layout(v, job.layers);
  const bool grey = p.antialiasing && p.gamma > 0;
  const unsigned antialiasing = grey ? 16 : 1;
  const double volume_ml = s.volume_ml;
  std::vector<uint8_t> out;
  out.reserve(size_t(a.layer_data));
  LittleEndian w{out};
  // File mark.
  w.text(kPwsMark, kPwsNameSize);
  w.u32(v);
  w.u32(v >= 518 ? 11 : v >= 517 ? 9 : 8);  // number of tables
  w.u32(a.header);
  w.u32(a.software);
  w.u32(a.preview);
  w.u32(a.colours);
  w.u32(a.layer_def);
  w.u32(a.extra);
  w.u32(a.machine);
  w.u32(a.layer_data);
  if (v >= 517) w.u32(a.model);
  if (v >= 518) w.u32(a.sub_layer_def), w.u32(a.preview2);
  // HEADER.
  table(w, "HEADER", header_length(v));
  w.f32(std::max(m.column_um, m.row_um));
  w.f32(job.layer_height_mm);
  w.f32(p.exposure_s);
  w.f32(wait_after_retract_s(p, layer_moves(p, false)));  // wait before cure: the light-off delay
  w.f32(p.bottom_exposure_s);
  w.f32(p.bottom_layers);
  w.f32(p.lift_mm);
  w.f32(p.lift_speed_mm_min / 60);
  w.f32(p.retract_speed_mm_min / 60);
  w.f32(volume_ml);
  w.u32(antialiasing);
  w.u32(unsigned(m.width));
  w.u32(unsigned(m.height));
  w.f32(volume_ml * 1000 * kResinGramsPerMm3);
  w.f32(0);       // price: unknown
  w.text("$", 4);  // its currency
  w.u32(1);       // per-layer settings: the printer uses each layer's entry (faded layers, bottom lifts)
  w.u32(uint32_t(std::round(print_seconds(p, job.layers))));
  w.u32(uint32_t(std::max(0, p.faded_layers)));  // transition layers
  w.u32(0);                                      // transition type: linear
  w.u32(0);  // advanced mode off: one-stage moves (two-stage motion control unused)
  if (v >= 517) {
    w.u16(0);  // grey
    w.u16(0);  // blur level
    w.u32(0);  // resin type
  }
  if (v >= 518) w.u32(0);  // intelligent mode off: the exposures are the file's
  preview_table(w, s.preview, kPwsPreviewWidth, kPwsPreviewHeight, false);
  // The grey colour table: 16 levels, (i + 1) * 255 / antialiasing, as UVtools fills it.
  w.u32(0);  // full greyscale: no
  w.u32(16);
  for (unsigned i = 0; i < 16; ++i) w.u8(unsigned(std::min(255.0, std::floor((i + 1) * (255.0 / antialiasing)))));
  w.u32(0);
  // LAYERDEF.
  table(w, "LAYERDEF", 4 + uint64_t(job.layers) * kPwsLayerDefSize);
  w.u32(uint32_t(job.layers));
  out.insert(out.end(), layer_defs.begin(), layer_defs.end());
  // EXTRA: the bottom layers' and the others' moves in two stages, the second not used (0 mm at
  // the first stage's speeds). Its length is 24, as every writer in the open writes it.
  table(w, "EXTRA", 24);
  for (bool bottom : {true, false}) {
    const LayerMoves m = layer_moves(p, bottom);
    w.u32(2);  // stages
    for (double height : {m.lift_mm, 0.0}) w.f32(height), w.f32(m.lift_speed / 60), w.f32(m.retract_speed / 60);
  }
  // MACHINE.
  table(w, "MACHINE", machine_size(v));
  w.text((p.printer_model.empty() ? t.kind->machine : p.printer_model).substr(0, 95), 96);  // zero-terminated
  w.text("pw0Img", 16);
  w.u32(16);                                  // highest anti-aliasing level
  w.u32(v >= 518 ? 15 : v >= 517 ? 7 : 1);    // property fields, as UVtools writes them per version
  w.f32(m.width * m.column_um / 1000);
  w.f32(m.height * m.row_um / 1000);
  w.f32(print_height_mm(job.layers, job.layer_height_mm));  // machine z
  w.u32(t.kind->newest());                                  // highest file version of the kind
  w.u32(6506241);                                           // machine background, as UVtools writes it
  if (v >= 518) {
    w.f32(m.column_um);
    w.f32(m.row_um);
    for (int i = 0; i < 8; ++i) w.u32(0);
    w.u32(1);  // displays
    w.u32(0);
    w.u16(unsigned(m.width));
    w.u16(unsigned(m.height));
    for (int i = 0; i < 4; ++i) w.u32(0);
  }
  if (v >= 517) {
    // SOFTWARE (no name field: its own name comes first).
    w.text("slicereuse", 32);
    w.u32(kSoftwareSize);
    w.text("", 32);  // its version: none
    w.text("", 64);  // operating system
    w.text("", 32);  // OpenGL version
    // MODEL: the part's extent around the display centre, from the plate to the top layer.
    table(w, "MODEL", kModelSize);
    for (double c : {s.min_x, s.min_y, 0.0, s.max_x, s.max_y, double(job.layers) * job.layer_height_mm}) w.f32(c);
    w.u32(0);  // supports: none known
    w.f32(0);  // their density
  }
  if (v >= 518) {
    table(w, "SUBIMGS", 8 + kPwsTableBase + uint64_t(job.layers) * kPwsSubLayerDefSize);
    w.u32(uint32_t(job.layers));
    w.u32(1);  // index
    out.insert(out.end(), sub_layer_defs.begin(), sub_layer_defs.end());
    preview_table(w, s.preview2, kPwsPreview2Width, kPwsPreview2Height, true);
  }
  if (out.size() != a.layer_data)
    throw Error(format("Photon Workshop writer: tables of %zu bytes, expected %llu", out.size(),
                       (unsigned long long)a.layer_data));
  return out;
}

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

}  // namespace

void encode_pw0_layer(const PhotonWorkshopJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out) {
  const PrinterProfile& p = job.profile;
  const LayerMoves m = layer_moves(p, bottom_layer(p, k));
  out.clear();
  LittleEndian w{out};
  w.u32(0);  // data address: the writer's
  w.u32(0);  // data length, once known
  w.f32(m.lift_mm);
  w.f32(m.lift_speed / 60);
  w.f32(layer_exposure_s(p, k));
  w.f32(job.layer_height_mm);
  const size_t lit_at = out.size();
  w.u32(0);  // lit pixels, once counted
  w.u32(0);
  uint64_t lit = 0;  // pixels a reader finds lit: those of a code other than 0
  for_each_merged_run(
      runs, [](uint8_t level) { return unsigned(level >> 4); },
      [&](unsigned code, uint64_t n) {
        append_pw0_run(out, code, n);
        if (code != 0) lit += n;
      });
  const uint64_t size = out.size() - kPwsLayerDefSize;
  if (size > kMaxAddress || lit > kMaxAddress)
    throw Error(format("Photon Workshop writer: layer %zu encodes to %llu bytes, more than a layer holds", k,
                       (unsigned long long)size));
  for (int i = 0; i < 4; ++i) {
    out[4 + size_t(i)] = uint8_t(size >> (8 * i));
    out[lit_at + size_t(i)] = uint8_t(lit >> (8 * i));
  }
}

void write_photon_workshop(const std::string& path, const PhotonWorkshopJob& job,
                           const PhotonWorkshopLayerRecord& layer_record,
                           const std::function<PhotonWorkshopSummary()>& summary) {
  const Target t = check_job(path, job);
  const Layout a = layout(t.version, job.layers);
  AtomicFile file(path);
  // The tables hold what is known after the last layer (addresses, volume, previews): their
  // place is kept and they are written there at the end.
  const std::vector<uint8_t> placeholder(size_t(a.layer_data), 0);
  file.write(placeholder.data(), placeholder.size());
  std::vector<uint8_t> layer_defs, sub_layer_defs;
  layer_defs.reserve(job.layers * kPwsLayerDefSize);
  if (t.version >= 518) sub_layer_defs.reserve(job.layers * kPwsSubLayerDefSize);
  uint64_t at = a.layer_data;
  for (size_t k = 0; k < job.layers; ++k) {
    const std::vector<uint8_t>& record = layer_record(k);
    if (record.size() < kPwsLayerDefSize)
      throw Error(format("Photon Workshop writer: layer %zu's record has %zu bytes, less than its entry", k,
                         record.size()));
    const uint64_t size = record.size() - kPwsLayerDefSize;
    if (at + size > kMaxAddress)
      throw Error(format("cannot write '%s': its layers' data reaches beyond 4 GiB at layer %zu, which the file's "
                         "32-bit addresses cannot point to",
                         path.c_str(), k));
    const size_t entry = layer_defs.size();
    layer_defs.insert(layer_defs.end(), record.begin(), record.begin() + long(kPwsLayerDefSize));
    for (size_t i = 0; i < 4; ++i) layer_defs[entry + i] = uint8_t(at >> (8 * i));
    if (t.version >= 518) {
      LittleEndian w{sub_layer_defs};
      w.u32(at);
      w.u32(size);
      w.u32(le32(record.data() + kPwsLayerDefLitAt));
      for (int i = 0; i < 8; ++i) w.u32(0);
    }
    file.write(record.data() + kPwsLayerDefSize, size_t(size));
    at += size;
  }
  const std::vector<uint8_t> head = tables(t, job, summary(), layer_defs, sub_layer_defs);
  file.write_at(0, head.data(), head.size());
  file.commit();
}

}  // namespace slicereuse
