#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <omp.h>

#include "ctb_format.h"
#include "ctb_writer.h"
#include "goo_format.h"
#include "goo_writer.h"
#include "mask_stack.h"
#include "photon_workshop_format.h"
#include "photon_workshop_writer.h"
#include "sl1_writer.h"
#include "thumbnail_png.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printability/check_layers.h"
#include "slicereuse/printability/support_traps.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/check_print_file.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/raster/top_view.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/memory_budget.h"
#include "slicereuse/util/ordered_parallel.h"
#include "slicereuse/util/parallel_blocks.h"
#include "slicereuse/util/seconds_since.h"

namespace slicereuse {
namespace {

// Folder output names its images layer00000.png, layer00001.png, ...
const char* const FOLDER_PREFIX = "layer";
const char* const PHASE = "writing mask images";
const char* const TRAPS_PHASE = "finding the resin traps supports close";

// What export needs of a layer besides its image, found in the same visit to its points (hot in
// cache for the rasterizer then), not in passes of their own over the whole stack: the closed
// contours' area (shoelace; holes run clockwise and subtract) for the resin volume, and their
// extent. validate_slices leaves the points to this pass: a non-finite x or y makes a contour's
// shoelace sum non-finite, so only then are its points looked at, and a point that cannot be
// drawn is refused (open contours are not drawn, and z is not used).
struct LayerSummary {
  double area = 0;
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
};

// Layer k of the stack; a point is named by its number in its part's slices.
LayerSummary summarize_layer(const LayerView& layer, size_t k) {
  LayerSummary m;
  for (const LayerPart& part : layer) {
    const Slices& s = *part.slices;
    for (uint64_t c = s.layer_begin[part.layer]; c < s.layer_begin[part.layer + 1]; ++c) {
      if (s.contour_open[c]) continue;
      const uint64_t b = s.contour_begin[c], e = s.contour_begin[c + 1];
      const double* p = s.xyz.data();
      const double area = contour_area(s, c);
      if (!std::isfinite(area))  // a non-finite point, or products beyond the double range
        for (uint64_t i = b; i < e; ++i)
          if (!std::isfinite(p[3 * i]) || !std::isfinite(p[3 * i + 1]))
            throw Error(format("contour point %llu (layer %zu) has a coordinate that is not a finite number",
                               (unsigned long long)i, k));
      m.area += area;
      for (uint64_t i = b; i < e; ++i) {
        m.lo_x = std::min(m.lo_x, p[3 * i]);
        m.hi_x = std::max(m.hi_x, p[3 * i]);
        m.lo_y = std::min(m.lo_y, p[3 * i + 1]);
        m.hi_y = std::max(m.hi_y, p[3 * i + 1]);
      }
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

// What a thread keeps to draw a layer a maker makes (LayerMaker): its parts and their view.
struct MadeLayer {
  std::vector<SlicePart> parts;
  std::vector<LayerPart> view;
};

// The stack an export works on: one Slices, ranges of layers made on demand in parts
// (SliceChunks), each dropped before the next is made, or layers made where they are drawn
// (LayerMaker: one range). Layer numbers are the stack's; a range's own layers count from 0.
class Stack {
 public:
  explicit Stack(const Slices& s) : whole_(&s), first_{0, s.layers()}, thickness_(s.thickness) {}
  explicit Stack(const SliceChunks& c)
      : chunks_(&c), first_(c.first), thickness_(c.thickness), supported_(c.supports) {
    if (first_.size() < 2 || first_.front() != 0 ||
        std::adjacent_find(first_.begin(), first_.end(), std::greater_equal<size_t>()) != first_.end())
      throw Error("mask export: the layer ranges must start at layer 0 and each hold at least one layer");
  }
  explicit Stack(const LayerMaker& m)
      : maker_(&m), first_{0, m.layers}, thickness_(m.thickness), supported_(m.supports) {}

  size_t layers() const { return first_.back(); }
  size_t ranges() const { return first_.size() - 1; }
  size_t begin(size_t i) const { return first_[i]; }
  size_t end(size_t i) const { return first_[i + 1]; }
  double thickness() const { return thickness_; }
  bool supported() const { return supported_; }  // holds support parts (support_traps.h)
  // Where range i's share of the export begins and ends, and where its encoding begins within it:
  // a range made on demand spends the first half of its share being made.
  double share_begin(size_t i) const { return double(begin(i)) / double(layers()); }
  double share_end(size_t i) const { return double(end(i)) / double(layers()); }
  double encoding_begin(size_t i) const {
    return whole_ || maker_ ? share_begin(i) : 0.5 * (share_begin(i) + share_end(i));
  }
  // Range i's encoding, 0 to 1, as progress of the whole export.
  Progress encoding_progress(size_t i, const Progress& progress) const {
    return sub_progress(progress, encoding_begin(i), share_end(i));
  }

  // Makes range i, checked (the previous range's parts are freed first), whose layer `local` is
  // then layer(local); returns its open contours (a maker's are counted as its layers are made,
  // made_open_contours).
  size_t open_range(size_t i, const Progress& progress) {
    if (whole_) return whole_->open_contours();
    if (maker_) return 0;
    held_.clear();
    held_ = chunks_->make(i, sub_progress(progress, share_begin(i), encoding_begin(i)));
    const size_t n = end(i) - begin(i);
    size_t open = 0;
    // Each layer's parts, layer after layer: layer j's are parts_[part_begin_[j] .. part_begin_[j + 1]).
    part_begin_.assign(n + 1, 0);
    for (const SlicePart& p : held_) {
      if (p.first > n || p.slices.layers() > n - p.first)
        throw Error(format("mask export: layer range %zu holds a part of %zu layers from its layer %zu, beyond "
                           "its %zu layers",
                           i, p.slices.layers(), p.first, n));
      check(p.slices);
      open += p.slices.open_contours();
      for (size_t j = p.first; j < p.first + p.slices.layers(); ++j) ++part_begin_[j + 1];
    }
    for (size_t j = 0; j < n; ++j) part_begin_[j + 1] += part_begin_[j];
    parts_.resize(part_begin_[n]);
    std::vector<size_t> at(part_begin_.begin(), part_begin_.end() - 1);
    for (const SlicePart& p : held_)
      for (size_t j = p.first; j < p.first + p.slices.layers(); ++j) parts_[at[j]++] = {&p.slices, j - p.first, p.support};
    return open;
  }

  // Layer `local` of the range opened last; a maker's is made into `made`, the calling thread's,
  // and checked.
  LayerView layer(size_t local, MadeLayer& made) {
    if (whole_) return LayerView(*whole_, local);
    if (!maker_) return LayerView(parts_.data() + part_begin_[local], part_begin_[local + 1] - part_begin_[local]);
    maker_->make(local, made.parts);
    made.view.clear();
    size_t open = 0;
    for (const SlicePart& p : made.parts) {
      if (p.first != 0 || p.slices.layers() != 1)
        throw Error(format("mask export: layer %zu was made as a part of %zu layers from its layer %zu, not as one layer",
                           local, p.slices.layers(), p.first));
      check(p.slices);
      open += p.slices.open_contours();
      made.view.push_back({&p.slices, 0, p.support});
    }
    made_open_ += open;
    return LayerView(made.view.data(), made.view.size());
  }

  // The open contours of the layers a maker made.
  size_t made_open_contours() const { return made_open_; }

  static void check(const Slices& s) {
    validate_slices(s, false);  // the points: summarize_layer
    if (!s.has_points()) throw Error("mask export needs contour points, but the slices carry only an encoding");
  }

 private:
  const Slices* whole_ = nullptr;
  const SliceChunks* chunks_ = nullptr;
  const LayerMaker* maker_ = nullptr;
  std::atomic<size_t> made_open_{0};
  std::vector<size_t> first_;
  double thickness_ = 0;
  bool supported_ = false;
  std::vector<SlicePart> held_;
  std::vector<LayerPart> parts_;
  std::vector<size_t> part_begin_;
};

// The layer's mask as runs (mask_png.h) into out.
void layer_mask_runs(const LayerView& layer, const PrinterProfile& p, MaskRuns& out) {
  if (p.antialiasing)
    rasterize_layer_antialiased_runs(layer, p, out);
  else
    rasterize_layer_runs(layer, p, out);
}

// A supported stack's masks, every one made before any is written, so that the resin traps its
// supports close are found over the whole stack and lit whole (support_traps.h); each is taken
// once, lit, as its layer is encoded, and its layer is not made again: visit(layer, k) sees each
// layer as it is made, for what an export takes from its contours (the resin, the extent, the
// top view). Memory: every layer's mask, refused in words beforehand when they would not fit.
class PremadeMasks {
 public:
  PremadeMasks(Stack& stack, const PrinterProfile& p, size_t& open_contours,
               const std::function<void(const LayerView& layer, size_t k)>& visit, const Progress& progress)
      : masks_(stack.layers()),
        traps_(uint64_t(kSupportTrapMm3 / (1e-6 * p.pixel_size_x_um * p.pixel_size_y_um * stack.thickness()))) {
    PrinterProfile binary = p;
    binary.antialiasing = false;
    const size_t window = size_t(16) * size_t(omp_get_max_threads());
    std::vector<TrapLayer> prepared(window);
    uint64_t bytes = 0;
    bool checked = false;
    for (size_t i = 0; i < stack.ranges(); ++i) {
      open_contours += stack.open_range(i, progress);
      const Progress range_progress = stack.encoding_progress(i, progress);
      const size_t first = stack.begin(i), n = stack.end(i) - first;
      for (size_t a = 0; a < n; a += window) {
        const size_t count = std::min(window, n - a);
        parallel_blocks(
            count,
            [&](size_t j) {
              thread_local MadeLayer made;
              thread_local std::vector<LayerPart> supports;
              thread_local MaskRuns drawn, support_runs;
              const size_t k = first + a + j;
              const LayerView layer = stack.layer(a + j, made);
              visit(layer, k);
              layer_mask_runs(layer, p, drawn);
              masks_[k] = drawn;  // a copy of its size: the drawing buffer stays the thread's
              supports.clear();
              for (const LayerPart& part : layer)
                if (part.support) supports.push_back(part);
              rasterize_layer_runs(LayerView(supports.data(), supports.size()), binary, support_runs);
              prepared[j] = prepare_trap_layer(drawn, support_runs);
            },
            {}, TRAPS_PHASE);
        for (size_t j = 0; j < count; ++j) {
          traps_.add_layer(std::move(prepared[j]));
          const MaskRuns& m = masks_[first + a + j];
          bytes += m.row_begin.size() * 4 + m.columns.size() * 2 + m.levels.size();
        }
        if (!checked) {  // all of them as the first layers go
          checked = true;
          check_memory_for(bytes / (first + a + count) * stack.layers(),
                           format("holding the masks of all %zu layers of a supported print to find the resin traps "
                                  "its supports close",
                                  stack.layers()),
                           "print it in thicker layers, or fewer members per plate");
        }
        report_progress(range_progress, double(a + count) / double(n), TRAPS_PHASE);
      }
    }
    traps_.finish();
  }

  // Layer k's mask, with its traps lit; once.
  void take(size_t k, MaskRuns& out) {
    out = std::move(masks_[k]);
    masks_[k] = MaskRuns();
    traps_.light(k, out);
  }

 private:
  std::vector<MaskRuns> masks_;
  SupportTraps traps_;
};

// Made for a supported stack (on the first half of the progress, the encoding then taking the
// second, encoding_progress), else none.
std::unique_ptr<PremadeMasks> premade_masks(Stack& stack, const PrinterProfile& p, size_t& open_contours,
                                            const std::function<void(const LayerView& layer, size_t k)>& visit,
                                            const Progress& progress) {
  if (!stack.supported()) return nullptr;
  return std::make_unique<PremadeMasks>(stack, p, open_contours, visit, sub_progress(progress, 0, 0.5));
}

Progress encoding_progress(const PremadeMasks* premade, const Progress& progress) {
  return premade ? sub_progress(progress, 0.5, 1) : progress;
}

// The layer, layer `k` of the stack, as a PNG of bits per pixel: its mask premade (a supported
// stack's, PremadeMasks, which took its summary; the view is then empty) or drawn from the layer;
// mask, when not null (the checks'), gets its mask as runs too (8 bits only: .sl1 archives).
void encode_layer(const LayerView& layer, size_t k, const PrinterProfile& p, int bits, std::vector<uint8_t>& png,
                  StackSummary& summary, PremadeMasks* premade, MaskRuns* mask = nullptr) {
  if (!premade) summary.add(k, summarize_layer(layer, k));
  if (bits == 8 && p.antialiasing && !premade) {  // anti-aliased: straight into the PNG (and the runs)
    rasterize_layer_antialiased_png(layer, p, png, mask);
    return;
  }
  thread_local MaskRuns runs;
  MaskRuns& out = mask ? *mask : runs;
  if (premade)
    premade->take(k, out);
  else if (bits == 8)
    layer_mask_runs(layer, p, out);
  if (bits == 8) {  // 8-bit (.sl1): from the runs, the same PNG
    encode_mask_png(out, png);
    return;
  }
  thread_local Buffer<uint8_t> image;
  const MaskImageLayout layout = mask_image_layout(p);
  image.resize(size_t(layout.width) * size_t(layout.height));
  if (premade)
    draw_mask_runs(out, image.data());
  else
    rasterize_layer(layer, p, image.data());
  encode_mask_png(image.data(), layout.width, layout.height, bits, png);
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
void export_folder(Stack& stack, const PrinterProfile& p, const std::string& folder, StackSummary& summary,
                   size_t& open_contours, const MaskChecks* checks, const Progress& progress) {
  StagedOutputs outputs;
  const std::string staged = outputs.folder(folder);
  const std::unique_ptr<PremadeMasks> premade = premade_masks(
      stack, p, open_contours, [&](const LayerView& layer, size_t k) { summary.add(k, summarize_layer(layer, k)); },
      progress);
  const Progress encoding = encoding_progress(premade.get(), progress);
  for (size_t i = 0; i < stack.ranges(); ++i) {
    if (!premade) open_contours += stack.open_range(i, encoding);
    const size_t first = stack.begin(i);
    parallel_blocks(
        stack.end(i) - first,
        [&](size_t local) {
          thread_local std::vector<uint8_t> png;
          thread_local MadeLayer made;
          encode_layer(premade ? LayerView(nullptr, 0) : stack.layer(local, made), first + local, p,
                       p.antialiasing ? 8 : 1, png, summary, premade.get());
          // Plain writes: the staged folder as a whole is what appears atomically.
          write_file(staged + "/" + mask_layer_file_name(FOLDER_PREFIX, first + local), png);
        },
        stack.encoding_progress(i, encoding), PHASE);
  }
  // Written out of order: checked as read back, before it is committed.
  if (checks) {
    const MaskImageLayout layout = mask_image_layout(p);
    checks->done(check_print_file(staged, layout.column_um / 1000, layout.row_um / 1000, stack.thickness(), ""));
  }
  // Last chance to cancel: once committed, the export is done and no longer reports.
  report_progress(progress, 1, PHASE);
  outputs.commit();
  for (size_t k = stack.layers();; ++k) {
    const std::string stale = folder + "/" + mask_layer_file_name(FOLDER_PREFIX, k);
    if (::unlink(stale.c_str()) != 0) break;
  }
}

// Encodes layers on all cores, a window ahead of the archive writer (write_sl1, write_goo, write_ctb), which
// asks for them in order: range by range, the next one made when the writer first asks for one
// of its layers (with premade masks, PremadeMasks, no layer is made: the view is empty).
// encode(layer, k, bytes, mask) makes the layer, layer k of the stack; with checks,
// mask is not null and receives its mask as runs, which the same worker prepares for the checks
// (prepare_layer: most of their work, in parallel); the checker takes the prepared layers in order
// as the writer takes each layer, and the report goes to checks->done once it takes the last,
// before the writer commits.
class OrderedLayers {
 public:
  using Encode = std::function<void(const LayerView& layer, size_t k, std::vector<uint8_t>& bytes, MaskRuns* mask)>;

  OrderedLayers(Stack& stack, size_t& open_contours, const PrinterProfile& p, const MaskChecks* checks,
                const PremadeMasks* premade, const Progress& progress, Encode encode)
      : stack_(stack),
        open_contours_(open_contours),
        premade_(premade),
        progress_(encoding_progress(premade, progress)),
        encode_(std::move(encode)),
        window_(size_t(16) * size_t(omp_get_max_threads())), checks_(checks) {
    if (!checks) return;
    const MaskImageLayout layout = mask_image_layout(p);
    checker_ = std::make_unique<LayerChecker>(layout.column_um / 1000, layout.row_um / 1000, stack.thickness());
    prepared_.resize(window_);
  }

  const std::vector<uint8_t>& operator()(size_t k) {
    if (!items_ || k >= stack_.end(range_)) next_range();
    const size_t local = k - stack_.begin(range_);
    if (local % 64 == 0)
      report_progress(range_progress_, double(local) / double(stack_.end(range_) - stack_.begin(range_)), PHASE);
    const std::vector<uint8_t>& bytes = items_->get(local);
    if (checker_ && k == checked_) {  // a writer may ask for a layer twice (libzip: its size, then its bytes)
      // Item local's slot is not made again before the writer asks for item local + 1.
      checker_->add_layer(std::move(prepared_[local % window_]));
      if (++checked_ == stack_.layers()) checks_->done(checker_->finish());
    }
    return bytes;
  }

 private:
  void next_range() {
    if (items_) ++range_;
    items_.reset();  // all of the range's layers were taken: its workers are idle
    if (!premade_) open_contours_ += stack_.open_range(range_, progress_);
    range_progress_ = stack_.encoding_progress(range_, progress_);
    const size_t first = stack_.begin(range_);
    items_ = std::make_unique<OrderedParallel>(stack_.end(range_) - first, window_,
                                               [this, first](size_t local, std::vector<uint8_t>& bytes) {
                                                 thread_local MadeLayer made;
                                                 const LayerView layer =
                                                     premade_ ? LayerView(nullptr, 0) : stack_.layer(local, made);
                                                 if (!checker_) {
                                                   encode_(layer, first + local, bytes, nullptr);
                                                   return;
                                                 }
                                                 MaskRuns mask;
                                                 encode_(layer, first + local, bytes, &mask);
                                                 prepared_[local % window_] = prepare_layer(std::move(mask));
                                               });
  }

  Stack& stack_;
  size_t& open_contours_;
  const PremadeMasks* premade_;
  const Progress progress_;
  const Encode encode_;
  const size_t window_;
  const MaskChecks* checks_;
  std::unique_ptr<LayerChecker> checker_;
  std::vector<PreparedLayer> prepared_;  // per slot of the window: its layer, prepared for the checker
  size_t checked_ = 0;           // layers given to the checker
  Progress range_progress_;
  size_t range_ = 0;
  std::unique_ptr<OrderedParallel> items_;
};

// What a file with a top view takes from a layer's contours besides its mask: its summary, and
// its drawing into the top view.
std::function<void(const LayerView& layer, size_t k)> contours_taken(StackSummary& summary, TopView& top_view) {
  return [&summary, &top_view](const LayerView& layer, size_t k) {
    summary.add(k, summarize_layer(layer, k));
    top_view.add(layer, k);
  };
}

// An .sl1: always 8-bit PNGs, since PrusaSlicer's SL1 import decodes only 8-bit greyscale PNGs
// (1-bit layers would import as empty). Each layer is also drawn into the top view the
// thumbnails are made from.
void export_sl1(Stack& stack, const PrinterProfile& p, const std::string& path, StackSummary& summary,
                size_t& open_contours, const MaskChecks* checks, const Progress& progress) {
  TopView top_view(p, stack.layers());
  const std::unique_ptr<PremadeMasks> premade =
      premade_masks(stack, p, open_contours, contours_taken(summary, top_view), progress);
  OrderedLayers encoder(stack, open_contours, p, checks, premade.get(), progress,
                        [&](const LayerView& layer, size_t k, std::vector<uint8_t>& png, MaskRuns* mask) {
                          encode_layer(layer, k, p, 8, png, summary, premade.get(), mask);
                          if (!premade) top_view.add(layer, k);
                        });
  write_sl1(path,
            Sl1Job{p, stack.layers(), stack.thickness(), [&] { return summary.used_material_ml(stack.thickness()); },
                   [&](int width, int height, std::vector<uint8_t>& png) {
                     thumbnail_png(top_view.finish(), width, height, png);
                   }},
            std::ref(encoder));
}

// A layer of a file made from runs (.goo, .ctb): its mask as runs (into mask, the checks', or the
// calling thread's), premade (PremadeMasks, which took its contours) or drawn from the layer,
// then also drawn into the top view the previews are made from.
const MaskRuns& layer_runs(const LayerView& layer, size_t k, const PrinterProfile& p, StackSummary& summary,
                           TopView& top_view, PremadeMasks* premade, MaskRuns* mask) {
  thread_local MaskRuns runs;
  MaskRuns& out = mask ? *mask : runs;
  if (premade) {
    premade->take(k, out);
    return out;
  }
  contours_taken(summary, top_view)(layer, k);
  layer_mask_runs(layer, p, out);
  return out;
}

// A .goo: each layer's record straight from its runs.
void export_goo(Stack& stack, const PrinterProfile& p, const std::string& path, StackSummary& summary,
                size_t& open_contours, const MaskChecks* checks, const Progress& progress) {
  const GooJob job{p, stack.layers(), stack.thickness()};
  TopView top_view(p, stack.layers());
  const std::unique_ptr<PremadeMasks> premade =
      premade_masks(stack, p, open_contours, contours_taken(summary, top_view), progress);
  OrderedLayers encoder(stack, open_contours, p, checks, premade.get(), progress,
                        [&](const LayerView& layer, size_t k, std::vector<uint8_t>& record, MaskRuns* mask) {
                          encode_goo_layer(job, k, layer_runs(layer, k, p, summary, top_view, premade.get(), mask),
                                           record);
                        });
  write_goo(path, job, std::ref(encoder), [&] {
    return GooSummary{summary.used_material_ml(stack.thickness()), rgb565_preview(top_view.finish(), kGooSmallPreview, kGooSmallPreview),
                      rgb565_preview(top_view.finish(), kGooBigPreview, kGooBigPreview)};
  });
}

// A .ctb: each layer's data straight from its runs, unencrypted.
void export_ctb(Stack& stack, const PrinterProfile& p, const std::string& path, StackSummary& summary,
                size_t& open_contours, const MaskChecks* checks, const Progress& progress) {
  const CtbJob job{p, stack.layers(), stack.thickness()};
  TopView top_view(p, stack.layers());
  const std::unique_ptr<PremadeMasks> premade =
      premade_masks(stack, p, open_contours, contours_taken(summary, top_view), progress);
  OrderedLayers encoder(stack, open_contours, p, checks, premade.get(), progress,
                        [&](const LayerView& layer, size_t k, std::vector<uint8_t>& data, MaskRuns* mask) {
                          encode_ctb_layer(job, k, layer_runs(layer, k, p, summary, top_view, premade.get(), mask),
                                           data);
                        });
  write_ctb(path, job, std::ref(encoder), [&] {
    return CtbSummary{summary.used_material_ml(stack.thickness()),
                      rgb565_preview(top_view.finish(), kCtbLargePreviewWidth, kCtbLargePreviewHeight),
                      rgb565_preview(top_view.finish(), kCtbSmallPreviewWidth, kCtbSmallPreviewHeight)};
  });
}

// An Anycubic Photon Workshop file: each layer's entry and pw0Img data straight from its runs,
// which also go into the previews.
void export_photon_workshop(Stack& stack, const PrinterProfile& p, const std::string& path, StackSummary& summary,
                            size_t& open_contours, const MaskChecks* checks, const Progress& progress) {
  const PhotonWorkshopJob job{p, stack.layers(), stack.thickness()};
  TopView top_view(p, stack.layers());
  const std::unique_ptr<PremadeMasks> premade =
      premade_masks(stack, p, open_contours, contours_taken(summary, top_view), progress);
  OrderedLayers encoder(stack, open_contours, p, checks, premade.get(), progress,
                        [&](const LayerView& layer, size_t k, std::vector<uint8_t>& record, MaskRuns* mask) {
                          encode_pw0_layer(job, k, layer_runs(layer, k, p, summary, top_view, premade.get(), mask),
                                           record);
                        });
  write_photon_workshop(path, job, std::ref(encoder), [&] {
    MaskExportStats extent;  // the model's extent, moved onto the plate
    summary.measure_extent(p, extent);
    const bool any = extent.min_x < extent.max_x || extent.min_y < extent.max_y;
    const HeightMap& view = top_view.finish();
    return PhotonWorkshopSummary{summary.used_material_ml(stack.thickness()),
                                 rgb565_preview(view, kPwsPreviewWidth, kPwsPreviewHeight),
                                 rgb565_preview(view, kPwsPreview2Width, kPwsPreview2Height),
                                 any ? extent.min_x + p.offset_x_mm : 0,
                                 any ? extent.max_x + p.offset_x_mm : 0,
                                 any ? extent.min_y + p.offset_y_mm : 0,
                                 any ? extent.max_y + p.offset_y_mm : 0};
  });
}

MaskExportStats export_stack(Stack& stack, const PrinterProfile& printer, const std::string& output_path,
                             const MaskChecks* checks, const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  validate_printer_profile(printer);
  // The output's kind by its extension: one of print_formats(), else a folder.
  const std::string ext = lower_extension(output_path);
  const PrinterProfile profile = profile_for_format(printer, print_format(ext));
  if (stack.layers() == 0) throw Error("mask export: the slices have no layers");
  if (output_path.empty()) throw Error("mask export: no output path given");
  report_progress(progress, 0, PHASE);
  StackSummary summary(stack.layers());
  MaskExportStats stats;
  // ".sl1" and ".sl1s" are the same format (PrusaSlicer names the file after the printer).
  if (ext == ".sl1" || ext == ".sl1s") {
    export_sl1(stack, profile, output_path, summary, stats.ignored_open_contours, checks, progress);
  } else if (ext == ".goo") {
    export_goo(stack, profile, output_path, summary, stats.ignored_open_contours, checks, progress);
  } else if (photon_workshop_kind(ext)) {
    export_photon_workshop(stack, profile, output_path, summary, stats.ignored_open_contours, checks, progress);
  } else if (ext == ".ctb") {
    export_ctb(stack, profile, output_path, summary, stats.ignored_open_contours, checks, progress);
  } else {
    export_folder(stack, profile, output_path, summary, stats.ignored_open_contours, checks, progress);
  }
  stats.ignored_open_contours += stack.made_open_contours();
  stats.layers = stack.layers();
  summary.measure_extent(profile, stats);
  stats.seconds = seconds_since(start);
  return stats;
}

}  // namespace

MaskExportStats export_masks(const Slices& s, const PrinterProfile& profile, const std::string& output_path,
                             const Progress& progress, const MaskChecks* checks) {
  Stack::check(s);
  Stack stack(s);
  return export_stack(stack, profile, output_path, checks, progress);
}

MaskExportStats export_masks(const SliceChunks& chunks, const PrinterProfile& profile, const std::string& output_path,
                             const Progress& progress, const MaskChecks* checks) {
  Stack stack(chunks);
  return export_stack(stack, profile, output_path, checks, progress);
}

MaskExportStats export_masks(const LayerMaker& maker, const PrinterProfile& profile, const std::string& output_path,
                             const Progress& progress, const MaskChecks* checks) {
  Stack stack(maker);
  return export_stack(stack, profile, output_path, checks, progress);
}

}  // namespace slicereuse
