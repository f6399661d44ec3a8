#include "slicereuse/printability/check_layers.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "air_regions.h"
#include "level_runs.h"
#include "overhang_pixels.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

constexpr uint8_t kIslandLit = 2;  // UVtools: Island BinaryThreshold 1 (pixels <= 1 are black)
constexpr uint8_t kIslandPointLevel = 10;  // UVtools: Island RequiredPixelBrightnessToProcessCheck
constexpr uint8_t kSupportLevel = 150;  // UVtools: Island RequiredPixelBrightnessToSupport
constexpr double kSupportMultiplier = 0.25;  // UVtools: Island RequiredPixelsToSupportMultiplier
constexpr uint64_t kPixelsToSupport = 10;  // UVtools: Island RequiredPixelsToSupport (enhanced detection)
constexpr uint64_t kIslandMinArea = 1;  // UVtools: Island RequiredAreaToProcessCheck
constexpr uint64_t kOverhangMinPixels = 1;  // UVtools: Overhang RequiredPixelsToConsider
constexpr uint8_t kTrapSolid = 101;  // UVtools: ResinTrap BinaryThreshold 100 (pixels <= 100 are air)
constexpr uint64_t kCupMinArea = 100;  // UVtools: ResinTrap RequiredAreaToConsiderSuctionCup
constexpr double kCupMinHeightMm = 0.5;  // UVtools: ResinTrap RequiredHeightToConsiderSuctionCup
constexpr uint8_t kTouchLevel = 127;  // UVtools: TouchingBound MinimumPixelBrightness
constexpr int kTouchMargin = 5;  // UVtools: TouchingBound MarginLeft/Top/Right/Bottom

// A box of pixels grown by runs and rows.
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  void add(int lo, int hi, int y) {
    x0 = std::min(x0, lo);
    x1 = std::max(x1, hi);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y + 1);
  }
  void add(const PixelBox& b) {
    x0 = std::min(x0, b.x0);
    x1 = std::max(x1, b.x1);
    y0 = std::min(y0, b.y0);
    y1 = std::max(y1, b.y1);
  }
  bool empty() const { return x1 < 0; }
};

// Per connected region of a layer's runs: pixels and box.
struct Region {
  uint64_t pixels = 0;
  PixelBox box;
};

std::vector<Region> regions_of(const LevelRuns& runs, const RunLabels& labels) {
  std::vector<Region> regions(labels.count);
  for (int y = 0; y < runs.height; ++y)
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i) {
      Region& r = regions[labels.of_run[i]];
      r.pixels += runs.hi[i] - runs.lo[i];
      r.box.add(runs.lo[i], runs.hi[i], y);
    }
  return regions;
}

// Per region of labels (over runs), the pixels of other inside it.
std::vector<uint64_t> pixels_inside(const LevelRuns& other, const LevelRuns& runs, const RunLabels& labels) {
  std::vector<uint64_t> n(labels.count, 0);
  for (int y = 0; y < runs.height; ++y)
    for_each_overlap(other, runs, y, [&](uint32_t, uint32_t j, int lo, int hi) { n[labels.of_run[j]] += uint64_t(hi - lo); });
  return n;
}

}  // namespace

struct LayerChecker::State {
  double pixel_x = 0, pixel_y = 0, height = 0;
  size_t layers = 0;
  int width = 0, rows = 0;
  // The layer below: its image and runs.
  MaskRuns below;
  LevelRuns below_nonzero, below_128, below_support;
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

  void check_touching(const LevelRuns& lit, size_t layer) {
    PixelBox box;
    uint64_t pixels = 0;
    const auto touch = [&](int lo, int hi, int y) {
      if (lo >= hi) return;
      box.add(lo, hi, y);
      pixels += uint64_t(hi - lo);
    };
    for (int y = 0; y < rows; ++y) {
      const bool edge_row = y < kTouchMargin || y >= rows - kTouchMargin;
      for (uint32_t i = lit.row_begin[size_t(y)]; i < lit.row_begin[size_t(y) + 1]; ++i) {
        if (edge_row) {
          touch(lit.lo[i], lit.hi[i], y);
          continue;
        }
        touch(lit.lo[i], std::min<int>(lit.hi[i], kTouchMargin), y);
        touch(std::max<int>(lit.lo[i], width - kTouchMargin), lit.hi[i], y);
      }
    }
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

  // Islands and overhangs of a layer above layer 0.
  void check_islands_and_overhangs(const MaskRuns& mask, const LevelRuns& nonzero, const LevelRuns& lit,
                                   const LevelRuns& points, const LevelRuns& at_least_128, size_t layer) {
    const LevelRuns overhang = overhang_pixels({&mask, &nonzero, &at_least_128}, {&below, &below_nonzero, &below_128});
    const RunLabels overhang_labels = label_runs(overhang, true);  // contours, as UVtools finds them
    for (const Region& r : regions_of(overhang, overhang_labels)) {
      if (r.pixels < kOverhangMinPixels) continue;
      Finding f = finding(FindingKind::Overhang, layer, layer, r.box);
      f.area_mm2 = double(r.pixels) * pixel_x * pixel_y;
      findings.push_back(f);
    }

    const RunLabels labels = label_runs(lit, false);  // UVtools: AllowDiagonalBonds false
    const std::vector<Region> regions = regions_of(lit, labels);
    const std::vector<uint64_t> point_pixels = pixels_inside(points, lit, labels);
    const std::vector<uint64_t> supported = pixels_inside(intersect_runs(points, below_support), lit, labels);
    const std::vector<uint64_t> overhanging = pixels_inside(overhang, lit, labels);
    for (uint32_t c = 0; c < labels.count; ++c) {
      if (regions[c].pixels < kIslandMinArea || point_pixels[c] == 0) continue;
      const double required = std::max(1.0, double(point_pixels[c]) * kSupportMultiplier);
      if (double(supported[c]) >= required) continue;
      // Enhanced detection: well enough held to be an island only where it overhangs.
      if (supported[c] >= kPixelsToSupport && double(supported[c]) >= required / 4 &&
          overhanging[c] < kOverhangMinPixels)
        continue;
      Finding f = finding(FindingKind::Island, layer, layer, regions[c].box);
      f.area_mm2 = double(point_pixels[c]) * pixel_x * pixel_y;
      findings.push_back(f);
    }
  }
};

LayerChecker::LayerChecker(double pixel_x_mm, double pixel_y_mm, double layer_height_mm) : state_(new State) {
  if (!(pixel_x_mm > 0) || !(pixel_y_mm > 0) || !(layer_height_mm > 0))
    throw Error(format("printability check: the pixel size (%g x %g mm) and the layer height (%g mm) must be positive",
                       pixel_x_mm, pixel_y_mm, layer_height_mm));
  state_->pixel_x = pixel_x_mm;
  state_->pixel_y = pixel_y_mm;
  state_->height = layer_height_mm;
}

LayerChecker::~LayerChecker() = default;

void LayerChecker::add_layer(const MaskImage& layer) { add_layer(mask_runs_of(layer)); }

void LayerChecker::add_layer(MaskRuns layer) {
  State& s = *state_;
  const size_t k = s.layers;
  if (k == 0) {
    s.width = layer.width;
    s.rows = layer.height;
  } else if (layer.width != s.width || layer.height != s.rows) {
    throw Error(format("printability check: layer %zu is %d x %d pixels, layer 0 is %d x %d", k, layer.width,
                       layer.height, s.width, s.rows));
  }
  // Every level the checks compare with, ascending, in one pass over the layer's runs.
  std::vector<LevelRuns> at = runs_at_levels(layer, {1, kIslandLit, kIslandPointLevel, kTrapSolid, kTouchLevel, 128,
                                                     kSupportLevel});
  LevelRuns &nonzero = at[0], &lit = at[1], &points = at[2], &solid = at[3], &touching = at[4], &at_least_128 = at[5],
            &support = at[6];
  s.check_touching(touching, k);
  if (k > 0) s.check_islands_and_overhangs(layer, nonzero, lit, points, at_least_128, k);
  s.air.add_layer(complement_runs(solid), k);
  s.add_air_findings(s.air.take_closed());
  s.below_support = std::move(support);
  s.below_nonzero = std::move(nonzero);
  s.below_128 = std::move(at_least_128);
  s.below = std::move(layer);
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
