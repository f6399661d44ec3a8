#include "ctb_writer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <ctime>
#include <limits>

#include "byte_fields.h"
#include "ctb_format.h"
#include "goo_stack.h"
#include "lift_fields.h"
#include "merged_runs.h"
#include "slicereuse/printer/print_estimate.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// The version a profile asks for; Error for one not written.
int ctb_version(const std::string& path, const PrinterProfile& p) {
  if (p.file_version == 0 || p.file_version == 4) return 4;
  if (p.file_version == 3) return 3;
  if (p.file_version == 5)
    throw Error("cannot write '" + path +
                "': .ctb version 5 is the encrypted CTB of newer Chitu boards, whose closed scheme is not written: "
                "choose file version 3 or 4");
  throw Error(format("cannot write '%s': there is no .ctb version %d to write: choose 3 or 4", path.c_str(),
                     p.file_version));
}

// Where each section goes: the fixed ones first, in Chitubox's order, then the layer table and
// the layers. Each preview has the place of its largest encoding (2 bytes a pixel), since the
// previews are made only once every layer is.
struct Layout {
  int version;
  uint64_t large_at, small_at, parameters_at, slicer_at, name_at, disclaimer_at, v4_at, table_at, layers_at;
  std::string machine;
};

uint64_t preview_place(int width, int height) { return kCtbPreviewHeaderSize + 2 * uint64_t(width) * uint64_t(height); }

Layout layout(const CtbJob& job, int version) {
  Layout l;
  l.version = version;
  l.machine = job.profile.printer_model.empty() ? "custom" : job.profile.printer_model;
  l.large_at = kCtbHeaderSize;
  l.small_at = l.large_at + preview_place(kCtbLargePreviewWidth, kCtbLargePreviewHeight);
  l.parameters_at = l.small_at + preview_place(kCtbSmallPreviewWidth, kCtbSmallPreviewHeight);
  l.slicer_at = l.parameters_at + kCtbPrintParametersSize;
  l.name_at = l.slicer_at + kCtbSlicerInfoSize;
  l.disclaimer_at = l.name_at + l.machine.size();
  l.v4_at = l.disclaimer_at + (version >= 4 ? kCtbDisclaimerSize : 0);
  l.table_at = l.v4_at + (version >= 4 ? kCtbPrintParametersV4Size : 0);
  l.layers_at = l.table_at + kCtbLayerDefSize * job.layers;
  return l;
}

// The light-off delay: the wait after the retract (lift_fields.h), as the v4 rest times are left
// at 0 (Chitubox uses either).
double light_off_s(const PrinterProfile& p, bool bottom) { return wait_after_retract_s(p, layer_moves(p, bottom)); }

void check_float(const std::string& path, const char* what, double v) {
  if (!(std::fabs(v) <= FLT_MAX))
    throw Error(
        format("cannot write '%s': %s is %g, beyond the range of a .ctb's float fields", path.c_str(), what, v));
}

int check_job(const std::string& path, const CtbJob& job) {
  const int version = ctb_version(path, job.profile);
  const PrinterProfile& p = job.profile;
  const MaskImageLayout m = mask_image_layout(p);
  if (job.layers == 0) throw Error("cannot write '" + path + "': the stack has no layers");
  if (uint64_t(m.width) * uint64_t(m.height) > kGooMaxPixels)
    throw Error(format("cannot write '%s': images of %d x %d pixels, more than the %llu pixels the .ctb and .goo "
                       "readers here take back",
                       path.c_str(), m.width, m.height, (unsigned long long)kGooMaxPixels));
  if (job.layers > std::numeric_limits<uint32_t>::max())
    throw Error(format("cannot write '%s': %zu layers, more than a .ctb holds (4294967295)", path.c_str(), job.layers));
  const struct {
    const char* what;
    double v;
  } floats[] = {{"the exposure", p.exposure_s},
                {"the bottom exposure", p.bottom_exposure_s},
                {"the bottom lift", p.bottom_lift_mm},
                {"the lift", p.lift_mm},
                {"the bottom lift speed", p.bottom_lift_speed_mm_min},
                {"the lift speed", p.lift_speed_mm_min},
                {"the bottom retract speed", p.bottom_retract_speed_mm_min},
                {"the retract speed", p.retract_speed_mm_min},
                {"the bottom light-off delay", light_off_s(p, true)},
                {"the light-off delay", light_off_s(p, false)},
                {"the display's width in mm", m.width * m.column_um / 1000},
                {"the display's height in mm", m.height * m.row_um / 1000},
                {"the layer height", job.layer_height_mm},
                {"the print height", print_height_mm(job.layers, job.layer_height_mm)}};
  for (const auto& f : floats) check_float(path, f.what, f.v);
  const double seconds = std::round(print_seconds(p, job.layers));
  if (!(seconds <= std::numeric_limits<uint32_t>::max()))
    throw Error(format("cannot write '%s': a print time of %g s, more than a .ctb's print time holds (4294967295 s)",
                       path.c_str(), seconds));
  return version;
}

// Appends a run of n pixels of a 7-bit code: the code alone for one pixel, else with the run flag
// and the length in 1 to 4 bytes, split at kCtbMaxRun.
void append_ctb_run(std::vector<uint8_t>& out, uint8_t code, uint64_t n) {
  while (n > 0) {
    const uint32_t m = uint32_t(std::min<uint64_t>(n, kCtbMaxRun));
    n -= m;
    if (m == 1) {
      out.push_back(code);
      continue;
    }
    out.push_back(uint8_t(code | kCtbRunFlag));
    if (m <= 0x7F) {
      out.push_back(uint8_t(m));
    } else if (m <= 0x3FFF) {
      out.push_back(uint8_t(0x80 | m >> 8));
      out.push_back(uint8_t(m));
    } else if (m <= 0x1FFFFF) {
      out.push_back(uint8_t(0xC0 | m >> 16));
      out.push_back(uint8_t(m >> 8));
      out.push_back(uint8_t(m));
    } else {
      out.push_back(uint8_t(0xE0 | m >> 24));
      out.push_back(uint8_t(m >> 16));
      out.push_back(uint8_t(m >> 8));
      out.push_back(uint8_t(m));
    }
  }
}

// A preview's header and its run-length RGB565 (the green's low bit dropped for the run flag):
// one word for a pixel alone, two for two, the flagged colour and 0x3000 | (n - 1) for 3 to
// 0xFFF pixels, as Chitubox writes them.
void preview(LittleEndian& w, uint64_t at, const std::vector<uint16_t>& pixels, int width, int height) {
  if (pixels.size() != size_t(width) * size_t(height))
    throw Error(format(".ctb writer: a preview image of %zu pixels, expected %d x %d", pixels.size(), width, height));
  std::vector<uint8_t> data;
  LittleEndian d{data};
  for (size_t i = 0; i < pixels.size();) {
    const uint16_t colour = pixels[i] & uint16_t(~kCtbPreviewRunFlag);
    size_t n = 1;
    while (n < kCtbPreviewMaxRun && i + n < pixels.size() && (pixels[i + n] & uint16_t(~kCtbPreviewRunFlag)) == colour)
      ++n;
    if (n <= 2) {
      for (size_t j = 0; j < n; ++j) d.u16(colour);
    } else {
      d.u16(colour | kCtbPreviewRunFlag);
      d.u16(0x3000 | unsigned(n - 1));
    }
    i += n;
  }
  w.u32(uint32_t(width));
  w.u32(uint32_t(height));
  w.u32(uint32_t(at + kCtbPreviewHeaderSize));
  w.u32(uint32_t(data.size()));
  w.zeros(16);
  w.bytes(data.data(), data.size());
  w.zeros(preview_place(width, height) - kCtbPreviewHeaderSize - data.size());
}

// A layer's definition: where its data lies (page of 4 GB and the address within it).
void layer_definition(LittleEndian& w, const CtbJob& job, size_t k, uint64_t data_at,
                      uint32_t data_size) {
  const PrinterProfile& p = job.profile;
  w.f32(double(k + 1) * job.layer_height_mm);  // the platform's height
  w.f32(layer_exposure_s(p, k));
  w.f32(light_off_s(p, k < size_t(p.bottom_layers)));
  w.u32(uint32_t(data_at));
  w.u32(data_size);
  w.u32(uint32_t(data_at >> 32));
  w.u32(uint32_t(kCtbLayerDefExSize));  // the table size UVtools writes for v3 and v4: with the extended definition
  w.zeros(8);
}

// v3 and v4: the extended definition before a layer's data: its definition again, then its
// moves (one stage; v4 names the second stages: 0 mm at the first stages' speeds).
void layer_definition_ex(LittleEndian& w, const CtbJob& job, const Layout& l, size_t k, uint64_t data_at,
                         uint32_t data_size) {
  layer_definition(w, job, k, data_at, data_size);
  const LayerMoves m = layer_moves(job.profile, k < size_t(job.profile.bottom_layers));
  const bool v4 = l.version >= 4;
  w.u32(uint32_t(kCtbLayerDefExSize + data_size));
  for (double v : {m.lift_mm, m.lift_speed, 0.0, v4 ? m.lift_speed : 0.0, m.retract_speed, 0.0,
                   v4 ? m.retract_speed : 0.0, 0.0, 0.0, 0.0, 255.0})
    w.f32(v);
}

// Everything before the layer table.
std::vector<uint8_t> front(const CtbJob& job, const Layout& l, const CtbSummary& s, std::time_t now) {
  const PrinterProfile& p = job.profile;
  const MaskImageLayout m = mask_image_layout(p);
  const LayerMoves bottom = layer_moves(p, true), other = layer_moves(p, false);
  const double volume_ml = s.volume_ml;
  std::vector<uint8_t> out;
  out.reserve(l.table_at);
  LittleEndian w{out};
  w.u32(l.version >= 4 ? kCtbMagicV4 : kCtbMagic);
  w.u32(uint32_t(l.version));
  w.f32(m.width * m.column_um / 1000);
  w.f32(m.height * m.row_um / 1000);
  w.f32(print_height_mm(job.layers, job.layer_height_mm));  // the machine's height
  w.zeros(8);
  w.f32(double(job.layers) * job.layer_height_mm);  // the stack's height
  w.f32(job.layer_height_mm);
  w.f32(p.exposure_s);
  w.f32(p.bottom_exposure_s);
  w.f32(light_off_s(p, false));
  w.u32(uint32_t(p.bottom_layers));
  w.u32(uint32_t(m.width));
  w.u32(uint32_t(m.height));
  w.u32(uint32_t(l.large_at));
  w.u32(uint32_t(l.table_at));
  w.u32(uint32_t(job.layers));
  w.u32(uint32_t(l.small_at));
  w.u32(uint32_t(std::lround(print_seconds(p, job.layers))));
  w.u32(p.mirror_x || p.mirror_y);  // projector type: the images are mirrored already, the flag says so
  w.u32(uint32_t(l.parameters_at));
  w.u32(uint32_t(kCtbPrintParametersSize));
  w.u32(1);    // level sets: one image per layer (grey levels are in it)
  w.u16(255);  // light PWM
  w.u16(255);  // bottom light PWM
  w.u32(job.encryption_key);
  w.u32(uint32_t(l.slicer_at));
  w.u32(uint32_t(kCtbSlicerInfoSize));

  preview(w, l.large_at, s.large_preview, kCtbLargePreviewWidth, kCtbLargePreviewHeight);
  preview(w, l.small_at, s.small_preview, kCtbSmallPreviewWidth, kCtbSmallPreviewHeight);

  // Print parameters; v4 lift heights are the two stages' sum (the second is 0 mm).
  w.f32(bottom.lift_mm);
  w.f32(bottom.lift_speed);
  w.f32(other.lift_mm);
  w.f32(other.lift_speed);
  w.f32(other.retract_speed);
  w.f32(volume_ml);
  w.f32(volume_ml * 1000 * kResinGramsPerMm3);
  w.f32(0);  // cost: unknown
  w.f32(light_off_s(p, true));
  w.f32(light_off_s(p, false));
  w.u32(uint32_t(p.bottom_layers));
  w.zeros(16);

  // Slicer info: the second stages (0 mm at the first stages' speeds), then the machine.
  for (double v : {0.0, bottom.lift_speed, 0.0, other.lift_speed, 0.0, other.retract_speed, 0.0}) w.f32(v);
  w.u32(uint32_t(l.name_at));
  w.u32(uint32_t(l.machine.size()));
  w.u8(antialiasing_level(p) > 1 ? 0x0F : 0x07);  // anti-aliasing flag, as Chitubox writes it
  w.u16(0);
  w.u8(unsigned(l.version) * 0x10);               // per-layer settings: the layer table's figures hold
  w.u32(uint32_t(now / 60));                       // minutes since 1970
  w.u32(antialiasing_level(p));
  w.u32(l.version >= 4 ? 0x01090000 : 0x01060300);  // the Chitubox version the file's version came with
  w.f32(0);                                         // rest after retract (the light-off delay holds it)
  w.f32(0);                                         // rest after the second lift
  w.u32(uint32_t(p.faded_layers));                  // transition layers
  w.u32(l.version >= 4 ? uint32_t(l.v4_at) : 0);
  w.zeros(8);
  w.text(l.machine, l.machine.size());

  if (l.version >= 4) {
    w.bytes(reinterpret_cast<const uint8_t*>(kCtbDisclaimer), kCtbDisclaimerSize);
    w.f32(bottom.retract_speed);
    w.f32(bottom.retract_speed);  // second stage
    w.u32(0);
    w.f32(4);  // a constant Chitubox writes
    w.u32(0);
    w.f32(4);
    w.f32(0);  // rests after retract, after lift, before lift
    w.f32(0);
    w.f32(0);
    w.f32(0);  // bottom second retract
    w.f32(0);  // two figures of unknown meaning
    w.u32(0);
    w.u32(5);  // a constant Chitubox writes
    w.u32(uint32_t(job.layers - 1));  // the last layer
    w.zeros(16);
    w.u32(uint32_t(l.disclaimer_at));
    w.u32(uint32_t(kCtbDisclaimerSize));
    w.u32(0);  // resin parameters (version 5)
    w.zeros(380);
  }
  if (out.size() != l.table_at)
    throw Error(format(".ctb writer: %zu bytes before the layer table, expected %llu", out.size(),
                       (unsigned long long)l.table_at));
  return out;
}

}  // namespace

void encode_ctb_layer(const CtbJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out) {
  out.clear();
  for_each_merged_run(
      runs, [](uint8_t level) { return uint8_t(level >> 1); },
      [&](uint8_t code, uint64_t n) { append_ctb_run(out, code, n); });
  if (out.size() > std::numeric_limits<uint32_t>::max())
    throw Error(format(".ctb writer: layer %zu encodes to %zu bytes, more than a .ctb layer holds", k, out.size()));
  if (job.encryption_key != 0) CtbKeyStream(job.encryption_key, uint32_t(k)).apply(out.data(), out.size());
}

void write_ctb(const std::string& path, const CtbJob& job, const CtbLayerRecord& layer_record,
               const std::function<CtbSummary()>& summary) {
  const Layout l = layout(job, check_job(path, job));
  const std::time_t now = creation_time();
  AtomicFile file(path);
  // What comes before the layers is known after the last one: its place is kept and it is
  // written there at the end.
  const std::vector<uint8_t> zeros(1 << 16, 0);
  for (uint64_t left = l.layers_at; left > 0;) {
    const size_t n = size_t(std::min<uint64_t>(left, zeros.size()));
    file.write(zeros.data(), n);
    left -= n;
  }
  std::vector<uint8_t> table, ex;
  table.reserve(kCtbLayerDefSize * job.layers);
  LittleEndian t{table};
  uint64_t at = l.layers_at;
  for (size_t k = 0; k < job.layers; ++k) {
    const std::vector<uint8_t>& data = layer_record(k);
    const uint32_t size = uint32_t(data.size());
    if (l.version >= 3) {
      ex.clear();
      LittleEndian e{ex};
      layer_definition_ex(e, job, l, k, at + kCtbLayerDefExSize, size);
      file.write(ex.data(), ex.size());
      at += ex.size();
    }
    layer_definition(t, job, k, at, size);
    file.write(data.data(), data.size());
    at += data.size();
  }
  const CtbSummary s = summary();
  check_float(path, "the resin volume", s.volume_ml * 1000);
  const std::vector<uint8_t> head = front(job, l, s, now);
  file.write_at(0, head.data(), head.size());
  file.write_at(l.table_at, table.data(), table.size());
  file.commit();
}

}  // namespace slicereuse
