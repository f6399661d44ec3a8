#include "slicereuse/printability/support_traps.h"

#include <algorithm>
#include <vector>

#include "air_regions.h"
#include "level_runs.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "uvtools_settings.h"

namespace slicereuse {
namespace {

// Whether a lit run of row y of lit comes within one pixel of columns [lo, hi).
bool lit_near(const LevelRuns& lit, int y, int lo, int hi) {
  if (y < 0 || y >= lit.height) return false;
  const uint32_t b = lit.row_begin[size_t(y)], e = lit.row_begin[size_t(y) + 1];
  // The first run whose last pixel (hi - 1) is at or after column lo - 1.
  const uint16_t* first =
      std::upper_bound(lit.hi.data() + b, lit.hi.data() + e, lo - 1, [](int v, uint16_t h) { return v < int(h); });
  const uint32_t i = uint32_t(first - lit.hi.data());
  return i < e && int(lit.lo[i]) <= hi;
}

// A run of a pocket of air, columns [lo, hi) of row y, and its piece (air_regions.h) once added
// (kNoPiece: a speck the check takes as solid).
struct PocketRun {
  uint32_t piece;
  uint16_t y, lo, hi;
};

// Row y of mask with the columns [lo, hi) of runs (of that row, increasing) at 255, appended to
// out. A mask run is either air (below the trap level) inside one air run, lit or not, or solid
// and apart from every air run: so it is dropped when a lit run holds it, else kept.
void light_row(const MaskRuns& mask, int y, const PocketRun* runs, size_t count, MaskRuns& out) {
  auto add = [&](int a, int b, uint8_t level) {
    if (a >= b) return;
    const size_t n = out.levels.size();
    if (n > out.row_begin[size_t(y)] && out.levels[n - 1] == level && out.columns[2 * n - 1] == a) {
      out.columns[2 * n - 1] = uint16_t(b);
      return;
    }
    out.columns.push_back(uint16_t(a));
    out.columns.push_back(uint16_t(b));
    out.levels.push_back(level);
  };
  size_t k = 0;
  int lit_to = 0;
  for (uint32_t i = mask.row_begin[size_t(y)]; i < mask.row_begin[size_t(y) + 1]; ++i) {
    const int a = mask.columns[2 * size_t(i)], b = mask.columns[2 * size_t(i) + 1];
    for (; k < count && runs[k].lo <= a; ++k) {
      add(runs[k].lo, runs[k].hi, 255);
      lit_to = runs[k].hi;
    }
    if (b > lit_to) add(a, b, mask.levels[i]);
  }
  for (; k < count; ++k) add(runs[k].lo, runs[k].hi, 255);
}

}  // namespace

struct TrapLayerAir {
  AirLayer air;
};

TrapLayer::TrapLayer() = default;
TrapLayer::~TrapLayer() = default;
TrapLayer::TrapLayer(TrapLayer&&) noexcept = default;
TrapLayer& TrapLayer::operator=(TrapLayer&&) noexcept = default;

TrapLayer prepare_trap_layer(const MaskRuns& mask, const MaskRuns& support_runs) {
  if (support_runs.width != mask.width || support_runs.height != mask.height)
    throw Error(format("internal error: a %d x %d mask with supports of %d x %d pixels", mask.width, mask.height,
                       support_runs.width, support_runs.height));
  TrapLayer out;
  out.air = std::make_unique<TrapLayerAir>();
  AirLayer& a = out.air->air;
  a = air_layer_of(runs_at_levels(mask, {kTrapSolid})[0]);
  bool pockets = false;
  for (uint32_t c = 0; c < a.labels.count; ++c) pockets |= !a.regions[c].border && !a.solid[c];
  if (!pockets || support_runs.levels.empty()) return out;
  const LevelRuns supports = runs_at_levels(support_runs, {1})[0];
  const LevelRuns& runs = a.runs;
  for (int y = 0; y < runs.height; ++y)
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i) {
      AirRegion& r = a.regions[a.labels.of_run[i]];
      if (r.border || r.marked || a.solid[a.labels.of_run[i]]) continue;
      for (int dy = -1; dy <= 1 && !r.marked; ++dy) r.marked = lit_near(supports, y + dy, runs.lo[i], runs.hi[i]);
    }
  return out;
}

struct SupportTraps::State {
  uint64_t max_pixels = 0;
  AirRegions air{true};
  size_t layers = 0;
  int width = 0, height = 0;
  std::vector<std::vector<PocketRun>> pockets;  // per layer; after finish, the runs lit
  std::vector<uint32_t> lit_sets;               // the piece sets (piece_set) lit
  size_t traps = 0;
  uint64_t lit_pixels = 0;
  bool finished = false;

  void decide(const std::vector<AirRegion>& closed) {
    for (const AirRegion& r : closed) {
      if (r.border || r.top || r.plate || r.pixels > max_pixels) continue;
      if (!r.marked && r.max_layer_pixels >= kRequiredBlackPixelsToDrain) continue;
      lit_sets.push_back(air.piece_set(r.piece));
      ++traps;
      lit_pixels += r.pixels;
    }
  }
};

SupportTraps::SupportTraps(uint64_t max_pixels) : s_(std::make_unique<State>()) { s_->max_pixels = max_pixels; }
SupportTraps::~SupportTraps() = default;

void SupportTraps::add_layer(TrapLayer layer) {
  State& s = *s_;
  if (s.finished) throw Error("internal error: a layer added to resin traps already found");
  AirLayer& a = layer.air->air;
  if (s.layers == 0) {
    s.width = a.runs.width;
    s.height = a.runs.height;
  } else if (a.runs.width != s.width || a.runs.height != s.height) {
    throw Error(format("layer %zu is %d x %d pixels, layer 0 %d x %d", s.layers, a.runs.width, a.runs.height,
                       s.width, s.height));
  }
  std::vector<PocketRun> pockets;
  for (int y = 0; y < a.runs.height; ++y)
    for (uint32_t i = a.runs.row_begin[size_t(y)]; i < a.runs.row_begin[size_t(y) + 1]; ++i) {
      const uint32_t c = a.labels.of_run[i];
      if (!a.regions[c].border) pockets.push_back({c, uint16_t(y), a.runs.lo[i], a.runs.hi[i]});
    }
  std::vector<uint32_t> piece_of;
  s.air.add_layer(std::move(a), s.layers, &piece_of);
  for (PocketRun& r : pockets) {
    r.piece = piece_of[r.piece];
    if (r.piece == kNoPiece) s.lit_pixels += uint64_t(r.hi - r.lo);  // a speck: lit
  }
  s.pockets.push_back(std::move(pockets));
  ++s.layers;
  s.decide(s.air.take_closed());
}

void SupportTraps::finish() {
  State& s = *s_;
  if (s.finished) return;
  s.air.finish();
  s.decide(s.air.take_closed());
  s.finished = true;
  std::sort(s.lit_sets.begin(), s.lit_sets.end());
  for (std::vector<PocketRun>& layer : s.pockets) {
    layer.erase(std::remove_if(layer.begin(), layer.end(),
                               [&](const PocketRun& r) {
                                 return r.piece != kNoPiece && !std::binary_search(s.lit_sets.begin(), s.lit_sets.end(),
                                                                                   s.air.piece_set(r.piece));
                               }),
                layer.end());
    layer.shrink_to_fit();
  }
}

size_t SupportTraps::traps() const { return s_->traps; }
uint64_t SupportTraps::lit_pixels() const { return s_->lit_pixels; }

bool SupportTraps::lit(size_t k) const { return s_->finished && k < s_->layers && !s_->pockets[k].empty(); }

void SupportTraps::light(size_t k, MaskRuns& mask) const {
  if (!lit(k)) return;
  const State& s = *s_;
  if (mask.width != s.width || mask.height != s.height)
    throw Error(format("internal error: layer %zu's mask is %d x %d pixels, its resin traps' %d x %d", k, mask.width,
                       mask.height, s.width, s.height));
  const std::vector<PocketRun>& runs = s.pockets[k];
  MaskRuns out;
  out.width = mask.width;
  out.height = mask.height;
  out.row_begin.assign(size_t(mask.height) + 1, 0);
  out.columns.reserve(mask.columns.size() + 2 * runs.size());
  out.levels.reserve(mask.levels.size() + runs.size());
  size_t r = 0;
  for (int y = 0; y < mask.height; ++y) {
    out.row_begin[size_t(y)] = uint32_t(out.levels.size());
    size_t e = r;
    while (e < runs.size() && runs[e].y == y) ++e;
    if (e == r) {  // the row as it was
      const uint32_t b = mask.row_begin[size_t(y)], end = mask.row_begin[size_t(y) + 1];
      out.columns.insert(out.columns.end(), mask.columns.begin() + 2 * long(b), mask.columns.begin() + 2 * long(end));
      out.levels.insert(out.levels.end(), mask.levels.begin() + long(b), mask.levels.begin() + long(end));
    } else {
      light_row(mask, y, runs.data() + r, e - r, out);
    }
    r = e;
  }
  out.row_begin[size_t(mask.height)] = uint32_t(out.levels.size());
  mask = std::move(out);
}

}  // namespace slicereuse
