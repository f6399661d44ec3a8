#include "slicereuse/printability/check_layers.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "layer_facts.h"
#include "overhang_pixels.h"
#include "uvtools_settings.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
struct LayerChecker::State {
  double pixel_x = 0, pixel_y = 0, height = 0;
  size_t layers = 0;
  int width = 0, rows = 0;
  LayerFacts below;
  AirRegions air;
  std::optional<Finding> touching;  // touching bounds still growing
  std::vector<Finding> findings;

  Finding finding(FindingKind kind, size_t first, size_t last, const PixelBox& box) const {
    Finding f;
    f.kind = kind;
    f.first_layer = first;
    f.last_layer = last;
    f.x0 = box.x0;
    f.y0 = box.y0;
    f.x1 = box.x1;
    f.y1 = box.y1;
    f.center_mm[0] = 0.5 * (box.x0 + box.x1) * pixel_x;
    f.center_mm[1] = 0.5 * (box.y0 + box.y1) * pixel_y;
    f.center_mm[2] = 0.5 * double(first + last + 1) * height;
    f.size_mm[0] = (box.x1 - box.x0) * pixel_x;
    f.size_mm[1] = (box.y1 - box.y0) * pixel_y;
    f.size_mm[2] = double(last + 1 - first) * height;
    return f;
  }

  void add_air_findings(const std::vector<AirRegion>& closed) {
    for (const AirRegion& r : closed) {
      if (r.border) continue;  // drains to the vat
      FindingKind kind;
      if (r.top) {
        // Open only upwards: a cup at every peel, if big enough to pull.
        if (r.max_layer_pixels < kCupMinArea || double(r.last_layer + 1 - r.first_layer) * height < kCupMinHeightMm - 1e-9)
          continue;
        kind = FindingKind::SuctionCup;
      } else if (r.plate) {
        continue;  // UVtools: a cavity sealed by the plate is not a trap
      } else {
        kind = FindingKind::ResinTrap;
      }
      Finding f = finding(kind, r.first_layer, r.last_layer, PixelBox{r.x0, r.y0, r.x1, r.y1});
      f.volume_mm3 = double(r.pixels) * pixel_x * pixel_y * height;
      findings.push_back(f);
    }
  }

  void check_touching(const PixelBox& box, uint64_t pixels, size_t layer) {
    const bool continues = touching && touching->last_layer + 1 == layer;
    if (touching && (box.empty() || !continues)) {
      findings.push_back(*touching);
      touching.reset();
    }
    if (box.empty()) return;
    const double area = double(pixels) * pixel_x * pixel_y;
    if (!touching) {
      touching = finding(FindingKind::TouchingBounds, layer, layer, box);
      touching->area_mm2 = area;
      return;
    }
    PixelBox grown{touching->x0, touching->y0, touching->x1, touching->y1};
    grown.add(box);
    const double summed = touching->area_mm2 + area;
    touching = finding(FindingKind::TouchingBounds, touching->first_layer, layer, grown);
    touching->area_mm2 = summed;
  }

  // The overhangs' regions (8-connected: contours, as UVtools finds them) of a layer's
  // overhanging pixels.
  void add_overhang_findings(const LevelRuns& overhang, size_t layer) {
    const RunLabels overhang_labels = label_runs(overhang, true);
    std::vector<PixelBox> overhang_boxes(overhang_labels.count);
    std::vector<uint64_t> overhang_pixels_of(overhang_labels.count, 0);
    for (int y = 0; y < overhang.height; ++y)
      for (uint32_t i = overhang.row_begin[size_t(y)]; i < overhang.row_begin[size_t(y) + 1]; ++i) {
        overhang_boxes[overhang_labels.of_run[i]].add(overhang.lo[i], overhang.hi[i], y);
        overhang_pixels_of[overhang_labels.of_run[i]] += overhang.hi[i] - overhang.lo[i];
      }
    for (uint32_t c = 0; c < overhang_labels.count; ++c) {
      if (overhang_pixels_of[c] < kOverhangMinPixels) continue;
      Finding o = finding(FindingKind::Overhang, layer, layer, overhang_boxes[c]);
      o.area_mm2 = double(overhang_pixels_of[c]) * pixel_x * pixel_y;
      findings.push_back(o);
    }
  }

  // Islands and overhangs of a layer above layer 0.
  void check_islands_and_overhangs(const LayerFacts& f, size_t layer) {
    const LevelRuns overhang = overhang_pixels({&f.mask, &f.nonzero_box, &f.solid, &f.support},
                                               {&below.mask, &below.nonzero_box, &below.solid, &below.support});
    if (overhang.runs() > 0) add_overhang_findings(overhang, layer);

    // Per region, its pixels >= 10 on pixels >= 150 below (the rows of its pixels > 0 hold them).
    std::vector<uint64_t> supported(f.lit_labels.count, 0);
    for (int y = f.nonzero_box.y0; y < f.nonzero_box.y1; ++y)
      for_each_overlap(f.points, below.support, y, [&](uint32_t i, uint32_t, int lo, int hi) {
        supported[f.point_region[i]] += uint64_t(hi - lo);
      });
    std::vector<uint64_t> overhanging;  // only where a region is held well enough to need it
    for (uint32_t c = 0; c < f.lit_labels.count; ++c) {
      const LitRegion& r = f.lit_regions[c];
      if (r.pixels < kIslandMinArea || r.point_pixels == 0) continue;
      const double required = std::max(1.0, double(r.point_pixels) * kSupportMultiplier);
      if (double(supported[c]) >= required) continue;
      // Enhanced detection: well enough held to be an island only where it overhangs.
      if (supported[c] >= kPixelsToSupport && double(supported[c]) >= required / 4) {
        if (overhanging.empty()) overhanging = pixels_inside(overhang, f.lit, f.lit_labels);
        if (overhanging[c] < kOverhangMinPixels) continue;
      }
      Finding i = finding(FindingKind::Island, layer, layer, r.box);
      i.area_mm2 = double(r.point_pixels) * pixel_x * pixel_y;
      findings.push_back(i);
    }
  }
};

PreparedLayer::PreparedLayer() = default;
PreparedLayer::~PreparedLayer() = default;
PreparedLayer::PreparedLayer(PreparedLayer&&) noexcept = default;
PreparedLayer& PreparedLayer::operator=(PreparedLayer&&) noexcept = default;

PreparedLayer prepare_layer(MaskRuns layer) {
  PreparedLayer p;
  p.facts = std::make_unique<LayerFacts>(layer_facts_of(std::move(layer)));
  return p;
}

LayerChecker::LayerChecker(double pixel_x_mm, double pixel_y_mm, double layer_height_mm) : state_(new State) {
  if (!(pixel_x_mm > 0) || !(pixel_y_mm > 0) || !(layer_height_mm > 0))
    throw Error(format("printability check: the pixel size (%g x %g mm) and the layer height (%g mm) must be positive",
                       pixel_x_mm, pixel_y_mm, layer_height_mm));
  state_->pixel_x = pixel_x_mm;
  state_->pixel_y = pixel_y_mm;
  state_->height = layer_height_mm;
}

LayerChecker::~LayerChecker() = default;

void LayerChecker::add_layer(const MaskImage& layer) { add_layer(prepare_layer(mask_runs_of(layer))); }

void LayerChecker::add_layer(MaskRuns layer) { add_layer(prepare_layer(std::move(layer))); }

void LayerChecker::add_layer(PreparedLayer prepared) {
  State& s = *state_;
  LayerFacts& f = *prepared.facts;
  const size_t k = s.layers;
  if (k == 0) {
    s.width = f.mask.width;
    s.rows = f.mask.height;
  } else if (f.mask.width != s.width || f.mask.height != s.rows) {
    throw Error(format("printability check: layer %zu is %d x %d pixels, layer 0 is %d x %d", k, f.mask.width,
                       f.mask.height, s.width, s.rows));
  }
  s.check_touching(f.touching_box, f.touching_pixels, k);
  if (k > 0) s.check_islands_and_overhangs(f, k);
  s.air.add_layer(std::move(f.air), k);
  s.add_air_findings(s.air.take_closed());
  s.below = std::move(f);
  ++s.layers;
}

PrintabilityReport LayerChecker::finish() {
  State& s = *state_;
  s.air.finish();
  s.add_air_findings(s.air.take_closed());
  if (s.touching) s.findings.push_back(*s.touching);
  PrintabilityReport report;
  report.layers = s.layers;
  report.findings = std::move(s.findings);
  std::stable_sort(report.findings.begin(), report.findings.end(), [](const Finding& a, const Finding& b) {
    return a.kind != b.kind ? a.kind < b.kind : a.first_layer < b.first_layer;
  });
  for (const Finding& f : report.findings) ++report.counts[size_t(f.kind)];
  return report;
}

}  // namespace slicereuse
