#include "goo_writer.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

#include "byte_fields.h"
#include "goo_format.h"
#include "lift_fields.h"
#include "merged_runs.h"
#include "slicereuse/printer/print_estimate.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// Lift, second lift, retract, second retract: distance and speed each. The second stages are
// not used (0 mm), at the first stages' speeds so that no reader divides by a zero speed.
void moves(BigEndian& w, const LayerMoves& m) {
  for (double v : {m.lift_mm, m.lift_speed, 0.0, m.lift_speed, m.lift_mm, m.retract_speed, 0.0, m.retract_speed})
    w.f32(v);
}

void preview(BigEndian& w, const std::vector<uint16_t>& pixels, int n) {
  if (pixels.size() != size_t(n) * size_t(n))
    throw Error(".goo writer: a preview image of " + std::to_string(pixels.size()) + " pixels, expected " +
                std::to_string(n) + " x " + std::to_string(n));
  for (uint16_t p : pixels) w.u16(p);
  w.bytes(kGooDelimiter, 2);
}

std::vector<uint8_t> header(const GooJob& job, const GooSummary& s, std::time_t now) {
  const PrinterProfile& p = job.profile;
  const MaskImageLayout m = mask_image_layout(p);
  const LayerMoves bottom = layer_moves(p, true), other = layer_moves(p, false);
  const double volume_mm3 = s.volume_ml * 1000;
  std::vector<uint8_t> out;
  out.reserve(kGooHeaderSize);
  BigEndian w{out};
  w.text("V3.0", 4);
  w.bytes(kGooMagic, 8);
  w.text("slicereuse", 32);                                               // software
  w.text("", 24);                                                         // its version: none
  w.text(utc_time(now, "%Y-%m-%d %H:%M:%S"), 24);
  w.text(p.printer_model.empty() ? "custom" : p.printer_model, 32);  // printer name
  w.text("MSLA", 32);                                                     // printer type
  w.text("slicereuse", 32);                                               // resin profile
  w.u16(antialiasing_level(p));
  w.u16(0);  // grey level
  w.u16(0);  // blur level
  preview(w, s.small_preview, kGooSmallPreview);
  preview(w, s.big_preview, kGooBigPreview);
  w.u32(uint32_t(job.layers));
  w.u16(unsigned(m.width));
  w.u16(unsigned(m.height));
  w.u8(p.mirror_x);
  w.u8(p.mirror_y);
  w.f32(m.width * m.column_um / 1000);
  w.f32(m.height * m.row_um / 1000);
  w.f32(print_height_mm(job.layers, job.layer_height_mm));
  w.f32(job.layer_height_mm);
  w.f32(p.exposure_s);
  w.u8(1);  // delay mode: the waits below ("static time"), not a turn-off time
  w.f32(0);  // turn-off time
  // Bottom, then other layers: waits before the lift, after it, after the retract.
  for (double v : {0.0, 0.0, wait_after_retract_s(p, bottom), 0.0, 0.0, wait_after_retract_s(p, other)}) w.f32(v);
  w.f32(p.bottom_exposure_s);
  w.u32(uint32_t(p.bottom_layers));
  // Bottom, then other layers: lift, retract (distance, speed); then their second stages.
  for (const LayerMoves* m : {&bottom, &other}) w.f32(m->lift_mm), w.f32(m->lift_speed);
  for (const LayerMoves* m : {&bottom, &other}) w.f32(m->lift_mm), w.f32(m->retract_speed);
  for (const LayerMoves* m : {&bottom, &other}) w.f32(0), w.f32(m->lift_speed);
  for (const LayerMoves* m : {&bottom, &other}) w.f32(0), w.f32(m->retract_speed);
  w.u16(255);  // bottom light PWM
  w.u16(255);  // light PWM
  w.u8(1);     // advance mode: each layer's definition holds, so the faded layers' exposures too
  w.u32(uint32_t(std::lround(print_seconds(p, job.layers))));
  w.f32(volume_mm3);
  w.f32(volume_mm3 * kResinGramsPerMm3);
  w.f32(0);  // price: unknown
  w.text("$", 8);
  w.u32(uint32_t(kGooHeaderSize));  // where the layers begin
  w.u8(1);                          // grey levels 0x00..0xFF
  w.u16(unsigned(p.faded_layers));  // transition layers
  if (out.size() != kGooHeaderSize)
    throw Error(".goo writer: header of " + std::to_string(out.size()) + " bytes, expected " +
                std::to_string(kGooHeaderSize));
  return out;
}

void check_job(const std::string& path, const GooJob& job) {
  if (job.profile.portrait)
    throw Error("cannot write '" + path +
                "': a .goo image is as wide as the display's x resolution, with no portrait orientation (Elegoo's "
                "displays are landscape): choose a landscape display");
  if (job.layers > std::numeric_limits<uint32_t>::max())
    throw Error("cannot write '" + path + "': " + std::to_string(job.layers) +
                " layers, more than a .goo holds (4294967295)");
  if (job.profile.faded_layers > 0xFFFF)
    throw Error("cannot write '" + path + "': " + std::to_string(job.profile.faded_layers) +
                " faded layers, more than a .goo's transition layers hold (65535)");
}

// Appends one layer's chunks (goo_format.h), a run of pixels of one level at a time: a diff chunk
// where the level is near the last chunk's, which the encoder remembers.
class GooChunks {
 public:
  explicit GooChunks(std::vector<uint8_t>& out) : out_(out) {}

  void run(uint8_t level, uint64_t n) {
    while (n > 0) n -= chunk(level, n);
  }

 private:
  // One chunk of at most n pixels of level; returns how many it holds.
  uint64_t chunk(uint8_t level, uint64_t n) {
    const bool grey = level != 0 && level != 255;
    const int diff = int(level) - previous_;
    // A grey run short enough for a diff chunk: 1 byte for one pixel, 2 for up to 255.
    if (grey && previous_ >= 0 && std::abs(diff) <= 15 && n <= 255) {
      out_.push_back(uint8_t(kGooDiff << 6 | (diff < 0) << 5 | (n > 1) << 4 | std::abs(diff)));
      if (n > 1) out_.push_back(uint8_t(n));
      previous_ = level;
      return n;
    }
    const uint32_t m = uint32_t(std::min<uint64_t>(n, kGooMaxRun));
    const unsigned extra = m <= 0xF ? 0 : m <= 0xFFF ? 1 : m <= 0xFFFFF ? 2 : 3;
    const GooChunk kind = level == 0 ? kGooBlack : level == 255 ? kGooWhite : kGooGrey;
    out_.push_back(uint8_t(kind << 6 | extra << 4 | (m & 0xF)));
    if (kind == kGooGrey) out_.push_back(level);
    for (unsigned i = extra; i > 0; --i) out_.push_back(uint8_t(m >> (4 + 8 * (i - 1))));
    previous_ = level;
    return m;
  }

  std::vector<uint8_t>& out_;
  int previous_ = -1;  // the last chunk's level; none before the first
};

}  // namespace

void encode_goo_layer(const GooJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out) {
  const PrinterProfile& p = job.profile;
  out.clear();
  BigEndian w{out};
  w.u16(0);                                                    // no pause
  w.f32(print_height_mm(job.layers, job.layer_height_mm));  // where a pause would go
  w.f32(double(k + 1) * job.layer_height_mm);                  // the platform's height
  w.f32(layer_exposure_s(p, k));
  w.f32(0);  // turn-off time
  const LayerMoves m = layer_moves(p, k < size_t(p.bottom_layers));
  for (double v : {0.0, 0.0, wait_after_retract_s(p, m)}) w.f32(v);
  moves(w, m);
  w.u16(255);  // light PWM
  w.bytes(kGooDelimiter, 2);
  const size_t size_at = out.size();
  w.u32(0);  // the data size, once known
  const size_t data_at = out.size();
  out.push_back(kGooLayerMagic);
  GooChunks chunks(out);
  for_each_merged_run(
      runs, [](uint8_t level) { return level; }, [&](uint8_t level, uint64_t n) { chunks.run(level, n); });
  uint8_t sum = 0;
  for (size_t i = data_at + 1; i < out.size(); ++i) sum = uint8_t(sum + out[i]);
  out.push_back(uint8_t(~sum));
  const uint64_t data_size = out.size() - data_at;
  if (data_size > std::numeric_limits<uint32_t>::max())
    throw Error(".goo writer: layer " + std::to_string(k) + " encodes to " + std::to_string(data_size) +
                " bytes, more than a .goo layer holds");
  for (int i = 0; i < 4; ++i) out[size_at + size_t(i)] = uint8_t(data_size >> (24 - 8 * i));
  w.bytes(kGooDelimiter, 2);
}

void write_goo(const std::string& path, const GooJob& job, const GooLayerRecord& layer_record,
               const std::function<GooSummary()>& summary) {
  check_job(path, job);
  const std::time_t now = creation_time();
  AtomicFile file(path);
  // The header's volume and previews are known after the last layer: its place is kept and it
  // is written there at the end.
  const std::vector<uint8_t> placeholder(kGooHeaderSize, 0);
  file.write(placeholder.data(), placeholder.size());
  for (size_t k = 0; k < job.layers; ++k) {
    const std::vector<uint8_t>& record = layer_record(k);
    file.write(record.data(), record.size());
  }
  file.write(kGooEnding, sizeof kGooEnding);
  const std::vector<uint8_t> head = header(job, summary(), now);
  file.write_at(0, head.data(), head.size());
  file.commit();
}

}  // namespace slicereuse
