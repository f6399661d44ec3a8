#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstring>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <omp.h>

#include "slicereuse/atomic_file.h"
#include "slicereuse/buffer.h"
#include "slicereuse/error.h"
#include "slicereuse/format.h"
#include "slicereuse/mask_png.h"
#include "slicereuse/mask_stack.h"
#include "slicereuse/masks.h"
#include "slicereuse/ordered_parallel.h"
#include "slicereuse/parallel_blocks.h"
#include "slicereuse/printer_profile.h"
#include "slicereuse/sl1_writer.h"

namespace slicereuse {
namespace {

// Folder output names its images layer00000.png, layer00001.png, ...
const char* const FOLDER_PREFIX = "layer";
const char* const PHASE = "writing mask images";

bool is_sl1(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".sl1";
}

// What export needs of a layer besides its image, found in the same visit to its points (hot in
// cache then), not in passes of their own over the whole stack: the closed contours' area
// (shoelace; holes run clockwise and subtract) for the resin volume, and their extent. A
// non-finite point anywhere in the layer is refused here (validate_slices leaves the points to
// this pass).
struct LayerSummary {
  double area = 0;
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
};

LayerSummary summarize_layer(const Slices& s, size_t k) {
  LayerSummary m;
  for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
    const uint64_t b = s.contour_begin[c], e = s.contour_begin[c + 1];
    bool finite = true;
    for (uint64_t i = b; i < e; ++i)
      finite &= std::isfinite(s.xyz[3 * i]) & std::isfinite(s.xyz[3 * i + 1]) & std::isfinite(s.xyz[3 * i + 2]);
    if (!finite)
      for (uint64_t i = b; i < e; ++i)
        for (int d = 0; d < 3; ++d)
          if (!std::isfinite(s.xyz[3 * i + d]))
            throw Error(format("contour point %llu (layer %zu) has a coordinate that is not a finite number",
                               (unsigned long long)i, k));
    if (s.contour_open[c]) continue;
    m.area += contour_area(s, c);
    for (uint64_t i = b; i < e; ++i) {
      m.lo_x = std::min(m.lo_x, s.xyz[3 * i]);
      m.hi_x = std::max(m.hi_x, s.xyz[3 * i]);
      m.lo_y = std::min(m.lo_y, s.xyz[3 * i + 1]);
      m.hi_y = std::max(m.hi_y, s.xyz[3 * i + 1]);
    }
  }
  return m;
}

// The layers' summaries as the encoders make them, on any thread, in any order: areas kept per
// layer and summed in layer order, so the volume does not depend on the schedule.
class StackSummary {
 public:
  explicit StackSummary(size_t layers) : area_(layers, 0) {}

  void add(size_t k, const LayerSummary& m) {
    area_[k] = m.area;
    std::lock_guard<std::mutex> lock(mutex_);
    extent_.lo_x = std::min(extent_.lo_x, m.lo_x);
    extent_.hi_x = std::max(extent_.hi_x, m.hi_x);
    extent_.lo_y = std::min(extent_.lo_y, m.lo_y);
    extent_.hi_y = std::max(extent_.hi_y, m.hi_y);
  }

  // Resin volume in ml; layer thickness in mm.
  double used_material_ml(double thickness) const {
    double mm3 = 0;
    for (double a : area_) mm3 += std::max(0.0, a) * thickness;
    return mm3 / 1000;
  }

  // The display covers |x + offset_x| <= width * pixel / 2 around the model origin (likewise y).
  void measure_extent(const PrinterProfile& p, MaskExportStats& stats) const {
    const LayerSummary& e = extent_;
    if (e.lo_x > e.hi_x) return;  // no closed contour: nothing is drawn
    stats.min_x = e.lo_x;
    stats.max_x = e.hi_x;
    stats.min_y = e.lo_y;
    stats.max_y = e.hi_y;
    const double half_w = 0.5e-3 * p.width_px * p.pixel_size_x_um, half_h = 0.5e-3 * p.height_px * p.pixel_size_y_um;
    stats.outside_display = e.lo_x + p.offset_x_mm < -half_w || e.hi_x + p.offset_x_mm > half_w ||
                            e.lo_y + p.offset_y_mm < -half_h || e.hi_y + p.offset_y_mm > half_h;
  }

 private:
  std::vector<double> area_;
  std::mutex mutex_;
  LayerSummary extent_;
};

void encode_layer(const Slices& s, size_t k, const PrinterProfile& p, int bits,
                  std::vector<uint8_t>& png, StackSummary& summary) {
  summary.add(k, summarize_layer(s, k));
  if (bits == 8 && !p.antialiasing) {  // binary 8-bit (.sl1): straight from the runs
    thread_local MaskRuns runs;
    rasterize_layer_runs(s, k, p, runs);
    encode_mask_png(runs, png);
    return;
  }
  thread_local Buffer<uint8_t> image;
  image.resize(size_t(p.width_px) * size_t(p.height_px));
  rasterize_layer(s, k, p, image.data());
  encode_mask_png(image.data(), p.width_px, p.height_px, bits, png);
}

void write_file(const std::string& path, const std::vector<uint8_t>& data) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw Error("cannot create '" + path + "': " + std::strerror(errno));
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int e = errno;
      ::close(fd);
      throw Error("cannot write '" + path + "': " + std::strerror(n < 0 ? e : ENOSPC));
    }
    done += size_t(n);
  }
  if (::close(fd) != 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
}

// The images are written into a staged folder that replaces the target (or moves its images
// into an existing target) only when all are written; images of a former, longer export there
// are removed then.
void export_folder(const Slices& s, const PrinterProfile& p, const std::string& folder,
                   StackSummary& summary, const Progress& progress) {
  StagedOutputs outputs;
  const std::string staged = outputs.folder(folder);
  parallel_blocks(
      s.layers(),
      [&](size_t k) {
        thread_local std::vector<uint8_t> png;
        encode_layer(s, k, p, p.antialiasing ? 8 : 1, png, summary);
        // Plain writes: the staged folder as a whole is what appears atomically.
        write_file(staged + "/" + mask_layer_file_name(FOLDER_PREFIX, k), png);
      },
      progress, PHASE);
  // Last chance to cancel: once committed, the export is done and no longer reports.
  report_progress(progress, 1, PHASE);
  outputs.commit();
  for (size_t k = s.layers();; ++k) {
    const std::string stale = folder + "/" + mask_layer_file_name(FOLDER_PREFIX, k);
    if (::unlink(stale.c_str()) != 0) break;
  }
}

// Encodes layers on all cores, a window ahead of write_sl1, which asks for them in order.
// Always 8-bit: PrusaSlicer's SL1 import decodes only 8-bit greyscale PNGs (1-bit layers would
// import as empty).
class Sl1Layers {
 public:
  Sl1Layers(const Slices& s, const PrinterProfile& p, StackSummary& summary, const Progress& progress)
      : s_(s), progress_(progress),
        items_(s.layers(), size_t(16) * size_t(omp_get_max_threads()),
               [&s, &p, &summary](size_t k, std::vector<uint8_t>& png) { encode_layer(s, k, p, 8, png, summary); }) {}

  const std::vector<uint8_t>& operator()(size_t k) {
    if (k % 64 == 0) report_progress(progress_, double(k) / double(s_.layers()), PHASE);
    return items_.get(k);
  }

 private:
  const Slices& s_;
  const Progress& progress_;
  OrderedParallel items_;
};

}  // namespace

MaskExportStats export_masks(const Slices& s, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  validate_printer_profile(profile);
  validate_slices(s, false);  // the points: summarize_layer
  if (!s.has_points())
    throw Error("mask export needs contour points, but the slices carry only an encoding");
  if (s.layers() == 0) throw Error("mask export: the slices have no layers");
  if (output_path.empty()) throw Error("mask export: no output path given");
  report_progress(progress, 0, PHASE);
  StackSummary summary(s.layers());
  if (is_sl1(output_path)) {
    Sl1Layers encoder(s, profile, summary, progress);
    write_sl1(output_path,
              Sl1Job{profile, s.layers(), s.thickness, [&] { return summary.used_material_ml(s.thickness); }},
              std::ref(encoder));
  } else {
    export_folder(s, profile, output_path, summary, progress);
  }
  MaskExportStats stats;
  stats.layers = s.layers();
  stats.ignored_open_contours = s.open_contours();
  summary.measure_extent(profile, stats);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace slicereuse
