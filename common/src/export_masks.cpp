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
#include <string>
#include <vector>

#include <omp.h>

#include "slicereuse/atomic_file.h"
#include "slicereuse/buffer.h"
#include "slicereuse/error.h"
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

// Resin volume from the contours' areas (shoelace; holes run clockwise and subtract).
double used_material_ml(const Slices& s) {
  // Layers on all cores, summed in layer order so the result does not depend on the schedule.
  std::vector<double> area(s.layers(), 0);
  const long long L = static_cast<long long>(s.layers());
#pragma omp parallel for schedule(dynamic, 64)
  for (long long k = 0; k < L; ++k) {
    double a = 0;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c)
      if (!s.contour_open[c]) a += contour_area(s, c);
    area[size_t(k)] = a;
  }
  double mm3 = 0;
  for (double a : area) mm3 += std::max(0.0, a) * s.thickness;
  return mm3 / 1000;
}

void encode_layer(const Slices& s, size_t k, const PrinterProfile& p, int bits,
                  std::vector<uint8_t>& png) {
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
                   const Progress& progress) {
  StagedOutputs outputs;
  const std::string staged = outputs.folder(folder);
  parallel_blocks(
      s.layers(),
      [&](size_t k) {
        thread_local std::vector<uint8_t> png;
        encode_layer(s, k, p, p.antialiasing ? 8 : 1, png);
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
  Sl1Layers(const Slices& s, const PrinterProfile& p, const Progress& progress)
      : s_(s), progress_(progress),
        items_(s.layers(), size_t(16) * size_t(omp_get_max_threads()),
               [&s, &p](size_t k, std::vector<uint8_t>& png) { encode_layer(s, k, p, 8, png); }) {}

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

namespace {

// The display covers |x + offset_x| <= width * pixel / 2 around the model origin (likewise y).
void measure_extent(const Slices& s, const PrinterProfile& p, MaskExportStats& stats) {
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  const long long C = static_cast<long long>(s.contours());
#pragma omp parallel for reduction(min : lo_x, lo_y) reduction(max : hi_x, hi_y) schedule(dynamic, 256)
  for (long long c = 0; c < C; ++c) {
    if (s.contour_open[c]) continue;
    for (size_t i = s.contour_begin[c]; i < s.contour_begin[c + 1]; ++i) {
      lo_x = std::min(lo_x, s.xyz[3 * i]);
      hi_x = std::max(hi_x, s.xyz[3 * i]);
      lo_y = std::min(lo_y, s.xyz[3 * i + 1]);
      hi_y = std::max(hi_y, s.xyz[3 * i + 1]);
    }
  }
  if (lo_x > hi_x) return;  // no closed contour: nothing is drawn
  stats.min_x = lo_x;
  stats.max_x = hi_x;
  stats.min_y = lo_y;
  stats.max_y = hi_y;
  const double half_w = 0.5e-3 * p.width_px * p.pixel_size_x_um, half_h = 0.5e-3 * p.height_px * p.pixel_size_y_um;
  stats.outside_display = lo_x + p.offset_x_mm < -half_w || hi_x + p.offset_x_mm > half_w ||
                          lo_y + p.offset_y_mm < -half_h || hi_y + p.offset_y_mm > half_h;
}

}  // namespace

MaskExportStats export_masks(const Slices& s, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  validate_printer_profile(profile);
  validate_slices(s);
  if (!s.has_points())
    throw Error("mask export needs contour points, but the slices carry only an encoding");
  if (s.layers() == 0) throw Error("mask export: the slices have no layers");
  if (output_path.empty()) throw Error("mask export: no output path given");
  report_progress(progress, 0, PHASE);
  if (is_sl1(output_path)) {
    Sl1Layers encoder(s, profile, progress);
    write_sl1(output_path, Sl1Job{profile, s.layers(), s.thickness, used_material_ml(s)},
              std::ref(encoder));
  } else {
    export_folder(s, profile, output_path, progress);
  }
  MaskExportStats stats;
  stats.layers = s.layers();
  stats.ignored_open_contours = s.open_contours();
  measure_extent(s, profile, stats);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace slicereuse
