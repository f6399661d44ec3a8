#include "air_regions.h"

#include <algorithm>

#include "uvtools_settings.h"

namespace slicereuse {
namespace {

constexpr uint32_t kSolid = UINT32_MAX;

// Marks the rows of a region: it holds runs in every row of its box (it is 4-connected).
void mark_rows(std::vector<uint8_t>& rows, const AirRegion& r) {
  std::fill(rows.begin() + r.y0, rows.begin() + r.y1, uint8_t(1));
}

}  // namespace

void AirRegions::merge(uint32_t a, uint32_t b) {
  a = sets_.find(a);
  b = sets_.find(b);
  if (a == b) return;
  sets_.parent[a] = b;
  AirRegion& to = regions_[b];
  const AirRegion& from = regions_[a];
  to.pixels += from.pixels;
  to.layer_pixels += from.layer_pixels;
  to.max_layer_pixels = std::max(to.max_layer_pixels, from.max_layer_pixels);
  to.x0 = std::min(to.x0, from.x0);
  to.y0 = std::min(to.y0, from.y0);
  to.x1 = std::max(to.x1, from.x1);
  to.y1 = std::max(to.y1, from.y1);
  to.first_layer = std::min(to.first_layer, from.first_layer);
  to.last_layer = std::max(to.last_layer, from.last_layer);
  to.border |= from.border;
  to.top |= from.top;
  to.plate |= from.plate;
  to.marked |= from.marked;
  if (track_pieces_) pieces_.join(from.piece, to.piece);
}

AirLayer air_layer_of(const LevelRuns& solid) {
  // One pass over the rows makes the air's runs (the gaps between solid runs), labels them as
  // they come (ProvisionalLabels, as label_runs labels them) and sums each provisional label's
  // runs; then each set's sums are added up at its root.
  AirLayer a;
  LevelRuns& air = a.runs;
  air.width = solid.width;
  air.height = solid.height;
  air.row_begin.resize(size_t(solid.height) + 1);
  const size_t most = solid.runs() + size_t(solid.height);  // a row has one gap more than solid runs
  air.lo.resize(most);
  air.hi.resize(most);
  uint16_t* const lo_of = air.lo.data();
  uint16_t* const hi_of = air.hi.data();
  ProvisionalLabels labels;
  labels.of_run.reserve(most);
  std::vector<AirRegion> sums;  // per provisional label
  const int width = solid.width, last_row = solid.height - 1;
  uint32_t n = 0;  // air runs so far
  for (int y = 0; y < solid.height; ++y) {
    air.row_begin[size_t(y)] = n;
    uint32_t j = y > 0 ? air.row_begin[size_t(y) - 1] : 0;  // the row above's air runs
    const uint32_t je = n;
    const bool edge_row = y == 0 || y == last_row;
    const uint32_t sb = solid.row_begin[size_t(y)], se = solid.row_begin[size_t(y) + 1];
    if (sb == se && je - j == 1 && lo_of[j] == 0 && hi_of[j] == width) {
      // A row all air under a row all air (most rows of a display): its region, one row more.
      lo_of[n] = 0, hi_of[n] = uint16_t(width);
      labels.of_run.push_back(labels.of_run[j]);
      ++n;
      AirRegion& r = sums[labels.of_run.back()];
      r.pixels += uint64_t(width);
      r.y1 = y + 1;
      continue;
    }
    // Gap g of the row: before solid run g (the last one: after the last solid run).
    for (uint32_t g = sb; g <= se; ++g) {
      const int lo = g == sb ? 0 : solid.hi[g - 1];
      const int hi = g == se ? width : solid.lo[g];
      if (lo >= hi) continue;
      lo_of[n] = uint16_t(lo);
      hi_of[n] = uint16_t(hi);
      ++n;
      if (labels.add(lo_of, hi_of, j, je, lo, hi, 0)) {
        sums.emplace_back();
        sums.back().x0 = lo, sums.back().y0 = y, sums.back().x1 = hi;
      }
      AirRegion& r = sums[labels.of_run.back()];
      r.pixels += uint64_t(hi - lo);
      r.x0 = std::min(r.x0, lo);
      r.x1 = std::max(r.x1, hi);
      r.y1 = y + 1;
      r.border |= edge_row || lo == 0 || hi == width;
    }
  }
  air.row_begin[size_t(solid.height)] = n;
  air.lo.resize(n);
  air.hi.resize(n);
  std::vector<uint32_t> root_of_label;
  a.labels = labels.numbered(&root_of_label);
  a.regions = labels.summed(sums, root_of_label, [](AirRegion& to, const AirRegion& from) {
    to.pixels += from.pixels;
    to.x0 = std::min(to.x0, from.x0);
    to.y0 = std::min(to.y0, from.y0);
    to.x1 = std::max(to.x1, from.x1);
    to.y1 = std::max(to.y1, from.y1);
    to.border |= from.border;
  });
  a.solid.resize(a.labels.count);
  for (uint32_t c = 0; c < a.labels.count; ++c)
    a.solid[c] = a.regions[c].pixels < kRequiredAreaToProcessCheck && !a.regions[c].border;
  return a;
}

void AirRegions::add_layer(AirLayer layer_air, size_t layer, std::vector<uint32_t>* piece_of) {
  const LevelRuns& air = layer_air.runs;
  const RunLabels& labels = layer_air.labels;
  std::vector<AirRegion>& pieces = layer_air.regions;
  // This layer's regions, each a new node after the regions carried from the layer below.
  const uint32_t carried = uint32_t(regions_.size());
  std::vector<uint32_t> node(labels.count, kSolid);
  for (uint32_t c = 0; c < labels.count; ++c) {
    if (layer_air.solid[c]) continue;
    AirRegion& p = pieces[c];
    p.first_layer = p.last_layer = layer;
    p.plate = layer == 0;
    p.layer_pixels = p.pixels;
    if (track_pieces_) p.piece = pieces_.add();
    node[c] = sets_.add();
    regions_.push_back(p);
  }

  if (piece_of) {
    piece_of->assign(labels.count, kNoPiece);
    for (uint32_t c = 0; c < labels.count; ++c)
      if (node[c] != kSolid) (*piece_of)[c] = pieces[c].piece;
  }

  // Pixels shared with each region of the layer below, per (piece, region below) pair: the
  // overlaps of a row come mostly in runs of the same pair, so they are summed as they come,
  // then sorted and summed by pair (the area below is the last overlapping piece's, as it came).
  // Air that reaches the image border drains whatever it joins, so pairs of such air need no
  // counting, and rows with no other air (every row of a layer without holes) no visit.
  struct Shared {
    uint64_t key = 0, pixels = 0, below_area = 0;
  };
  std::vector<Shared> shared;
  std::vector<uint8_t> inner_rows(size_t(air.height), 0);
  for (uint32_t c = 0; c < labels.count; ++c)
    if (node[c] != kSolid && !pieces[c].border) mark_rows(inner_rows, pieces[c]);
  if (previous_air_.height == air.height && previous_air_.width == air.width) {
    for (int y = 0; y < air.height; ++y) {
      if (!inner_rows[size_t(y)] && !previous_inner_rows_[size_t(y)]) continue;
      for_each_overlap(air, previous_air_, y, [&](uint32_t i, uint32_t j, int lo, int hi) {
        const uint32_t c = labels.of_run[i], below = previous_labels_[j];
        const uint32_t below_node = previous_node_[below];
        if (node[c] == kSolid || below_node == kSolid) return;
        if (pieces[c].border && regions_[below_node].border) return;
        const uint64_t key = uint64_t(c) << 32 | below_node;
        if (shared.empty() || shared.back().key != key) shared.push_back({key, 0, 0});
        shared.back().pixels += uint64_t(hi - lo);
        shared.back().below_area = previous_area_[below];
      });
    }
  }
  std::stable_sort(shared.begin(), shared.end(), [](const Shared& a, const Shared& b) { return a.key < b.key; });
  for (size_t k = 0; k < shared.size();) {
    const uint64_t key = shared[k].key;
    uint64_t pixels = 0, below_area = 0;
    for (; k < shared.size() && shared[k].key == key; ++k) {
      pixels += shared[k].pixels;
      below_area = shared[k].below_area;
    }
    const uint32_t c = uint32_t(key >> 32), below = uint32_t(key);
    const uint64_t needed = std::min({kRequiredBlackPixelsToDrain, pieces[c].pixels, below_area});
    if (pixels >= needed) merge(node[c], below);
  }

  // Regions carried from below that no piece continues are closed.
  std::vector<uint32_t> compact(regions_.size(), kSolid);
  std::vector<AirRegion> alive;
  for (uint32_t c = 0; c < labels.count; ++c) {
    if (node[c] == kSolid) continue;
    const uint32_t root = sets_.find(node[c]);
    if (compact[root] == kSolid) {
      compact[root] = uint32_t(alive.size());
      AirRegion r = regions_[root];
      r.max_layer_pixels = std::max(r.max_layer_pixels, r.layer_pixels);
      r.layer_pixels = 0;
      alive.push_back(r);
    }
  }
  for (uint32_t n = 0; n < carried; ++n) {
    const uint32_t root = sets_.find(n);
    if (compact[root] != kSolid) continue;
    compact[root] = kSolid - 1;  // closed once
    closed_.push_back(regions_[root]);
  }

  // Only the open regions are kept, renumbered: memory stays that of one layer.
  previous_node_.assign(labels.count, kSolid);
  previous_area_.assign(labels.count, 0);
  for (uint32_t c = 0; c < labels.count; ++c) {
    if (node[c] == kSolid) continue;
    previous_node_[c] = compact[sets_.find(node[c])];
    previous_area_[c] = pieces[c].pixels;
  }
  regions_ = std::move(alive);
  sets_ = UnionFind(regions_.size());
  previous_inner_rows_.assign(size_t(air.height), 0);
  for (uint32_t c = 0; c < labels.count; ++c)
    if (previous_node_[c] != kSolid && !regions_[previous_node_[c]].border) mark_rows(previous_inner_rows_, pieces[c]);
  previous_air_ = std::move(layer_air.runs);
  previous_labels_ = std::move(layer_air.labels.of_run);
}

void AirRegions::finish() {
  for (AirRegion& r : regions_) {
    r.top = true;
    closed_.push_back(r);
  }
  regions_.clear();
  sets_ = UnionFind();
  previous_air_ = LevelRuns();
  previous_labels_.clear();
  previous_node_.clear();
  previous_area_.clear();
  previous_inner_rows_.clear();
}

std::vector<AirRegion> AirRegions::take_closed() {
  std::vector<AirRegion> out;
  out.swap(closed_);
  return out;
}

}  // namespace slicereuse
