// Layer ranges for stacks too large to hold at once (layer_chunks.h), and mask export a range
// at a time (export_masks of SliceChunks) or a layer at a time (of a LayerMaker), which must
// equal the export of the whole stack.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"
#include "test_files.h"

using namespace slicereuse;
namespace fs = std::filesystem;

namespace {

struct Job {
  Mesh mesh;
  std::vector<double> planes;
  Slices whole;
  PrinterProfile profile;
};

Job arch_job() {
  Job j;
  test::FamilyOptions o;
  o.faces = 20000;
  j.mesh = test::make_family_base(o);
  j.planes = layer_planes(0, 0.05, o.height);
  j.whole = slice_planes(j.mesh, j.planes, {}, false);
  j.whole.thickness = 0.05;
  // The arch centred on the default 1024 x 768 display at 75 um.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (size_t v = 0; v < j.mesh.vertices(); ++v)
    for (int d = 0; d < 2; ++d) {
      lo[d] = std::min(lo[d], j.mesh.V[3 * v + d]);
      hi[d] = std::max(hi[d], j.mesh.V[3 * v + d]);
    }
  j.profile.offset_x_mm = -(lo[0] + hi[0]) / 2;
  j.profile.offset_y_mm = -(lo[1] + hi[1]) / 2;
  return j;
}

size_t points_of_layers(const Slices& s, size_t k0, size_t k1) {
  return s.contour_begin[s.layer_begin[k1]] - s.contour_begin[s.layer_begin[k0]];
}

SliceChunks chunks_of(const Job& j, std::vector<size_t> first) {
  SliceChunks c;
  c.first = std::move(first);
  c.thickness = 0.05;
  c.make = [&j, f = c.first](size_t i, const Progress& progress) {
    Slices s = slice_planes(j.mesh, std::vector<double>(j.planes.begin() + long(f[i]), j.planes.begin() + long(f[i + 1])),
                            progress, false);
    s.thickness = 0.05;
    std::vector<SlicePart> parts;
    parts.push_back({std::move(s), 0});
    return parts;
  };
  return c;
}

// config.ini's usedMaterial line.
std::string used_material(const std::string& sl1) {
  const std::string text = test::zip_entry(sl1, "config.ini");
  const size_t at = text.find("usedMaterial");
  return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

class ChunkedMaskExport : public test::TempFolderTest {};

}  // namespace

TEST(LayerChunks, CountsTheSlicedPointsAndEachRangeFitsTheBudget) {
  const Job j = arch_job();
  const size_t L = j.planes.size(), P = j.whole.points();
  ASSERT_EQ(j.whole.open_contours(), 0u);  // closed: one point per crossed face, exactly
  EXPECT_EQ(layer_chunks(j.mesh, j.planes, 0, 24), (std::vector<size_t>{0, L}));
  EXPECT_EQ(layer_chunks(j.mesh, j.planes, 24 * P, 24), (std::vector<size_t>{0, L}));
  const std::vector<size_t> tight = layer_chunks(j.mesh, j.planes, 24 * P - 1, 24);
  EXPECT_EQ(tight.size(), 3u);

  const uint64_t budget = 24 * P / 5;
  const std::vector<size_t> first = layer_chunks(j.mesh, j.planes, budget, 24);
  ASSERT_GE(first.size(), 7u);  // at least 6 ranges: each at most a fifth of the points
  ASSERT_LE(first.size(), 8u);
  EXPECT_EQ(first.front(), 0u);
  EXPECT_EQ(first.back(), L);
  size_t total = 0;
  for (size_t i = 0; i + 1 < first.size(); ++i) {
    ASSERT_LT(first[i], first[i + 1]);
    const size_t points = points_of_layers(j.whole, first[i], first[i + 1]);
    EXPECT_LE(24 * points, budget) << "range " << i;
    // Full: one more layer would not have fitted.
    if (first[i + 1] < L) EXPECT_GT(24 * points_of_layers(j.whole, first[i], first[i + 1] + 1), budget);
    total += points;
  }
  EXPECT_EQ(total, P);
  // A budget below one layer: every layer is a range of its own.
  EXPECT_EQ(layer_chunks(j.mesh, j.planes, 1, 24).size(), L + 1);
}

TEST_F(ChunkedMaskExport, EqualsTheExportOfTheWholeStack) {
  const Job j = arch_job();
  const std::vector<size_t> first = layer_chunks(j.mesh, j.planes, 24 * j.whole.points() / 4, 24);
  ASSERT_GE(first.size(), 6u);
  const SliceChunks chunks = chunks_of(j, first);
  for (const char* ext : {".sl1", ".goo", ""}) {
    const std::string whole = dir + "/whole" + ext, ranged = dir + "/ranged" + ext;
    size_t made = 0;
    SliceChunks counted = chunks;
    counted.make = [&](size_t i, const Progress& p) {
      EXPECT_EQ(i, made++);  // once per range, in order
      return chunks.make(i, p);
    };
    const MaskExportStats a = export_masks(j.whole, j.profile, whole);
    const MaskExportStats b = export_masks(counted, j.profile, ranged);
    EXPECT_EQ(made, first.size() - 1);
    EXPECT_EQ(b.layers, a.layers);
    EXPECT_EQ(b.ignored_open_contours, a.ignored_open_contours);
    EXPECT_EQ(b.min_x, a.min_x);
    EXPECT_EQ(b.max_x, a.max_x);
    EXPECT_EQ(b.min_y, a.min_y);
    EXPECT_EQ(b.max_y, a.max_y);
    EXPECT_FALSE(b.outside_display);
    const StackComparison c = compare_mask_stacks(whole, ranged, "");
    EXPECT_EQ(c.layers.size(), j.planes.size());
    EXPECT_EQ(c.min_similarity, 1.0);
    EXPECT_EQ(c.differing_pixels, 0u);
    if (std::string(ext) == ".sl1") EXPECT_EQ(used_material(ranged), used_material(whole));
  }
}

// Layers [k0, k1) of s with only the contours whose number within their layer has the given
// parity.
Slices contours_of_parity(const Slices& s, size_t k0, size_t k1, size_t parity) {
  Slices out;
  out.thickness = s.thickness;
  out.z_start = s.z_start + double(k0) * s.thickness;
  out.layer_begin.push_back(0);
  out.contour_begin.push_back(0);
  for (size_t k = k0; k < k1; ++k) {
    out.layer_z.push_back(s.layer_z[k]);
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      if ((c - s.layer_begin[k]) % 2 != parity) continue;
      for (uint64_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p)
        out.xyz.insert(out.xyz.end(), s.xyz.begin() + long(3 * p), s.xyz.begin() + long(3 * p + 3));
      out.contour_begin.push_back(out.xyz.size() / 3);
      out.contour_open.push_back(s.contour_open[c]);
    }
    out.layer_begin.push_back(out.contour_open.size());
  }
  return out;
}

// A range may come in parts that each hold some of its layers (as a build plate's members do):
// here the even contours of the range's first half, the odd contours of all its layers and the
// even contours of its second half. Every layer is the union of its parts, so the export equals
// that of the whole stack.
TEST_F(ChunkedMaskExport, RangesInPartsEqualTheExportOfTheWholeStack) {
  Job j = arch_job();
  j.profile.antialiasing = true;
  j.profile.gamma = 1;
  size_t two_contour_layers = 0;
  for (size_t k = 0; k < j.whole.layers(); ++k) two_contour_layers += j.whole.layer_begin[k + 1] - j.whole.layer_begin[k] > 1;
  ASSERT_GT(two_contour_layers, 10u);  // the split takes contours apart
  const std::vector<size_t> first = layer_chunks(j.mesh, j.planes, 24 * j.whole.points() / 4, 24);
  SliceChunks chunks;
  chunks.first = first;
  chunks.thickness = j.whole.thickness;
  chunks.make = [&](size_t i, const Progress&) {
    const size_t a = first[i], b = first[i + 1], mid = (a + b) / 2;
    std::vector<SlicePart> parts;
    parts.push_back({contours_of_parity(j.whole, a, mid, 0), 0});
    parts.push_back({contours_of_parity(j.whole, a, b, 1), 0});
    parts.push_back({contours_of_parity(j.whole, mid, b, 0), mid - a});
    return parts;
  };
  for (const char* ext : {".sl1", ".goo", ""}) {
    const std::string whole = dir + "/whole" + ext, parted = dir + "/parted" + ext;
    const MaskExportStats a = export_masks(j.whole, j.profile, whole);
    const MaskExportStats b = export_masks(chunks, j.profile, parted);
    EXPECT_EQ(b.layers, a.layers);
    EXPECT_EQ(b.min_x, a.min_x);
    EXPECT_EQ(b.max_y, a.max_y);
    const StackComparison c = compare_mask_stacks(whole, parted, "");
    EXPECT_EQ(c.layers.size(), j.planes.size());
    EXPECT_EQ(c.min_similarity, 1.0);
    EXPECT_EQ(c.differing_pixels, 0u);
    EXPECT_EQ(c.max_grey_difference, 0);
    if (std::string(ext) == ".sl1") {  // the areas are summed in another order
      auto ml = [](const std::string& line) { return std::stod(line.substr(line.find('=') + 1)); };
      EXPECT_NEAR(ml(used_material(parted)), ml(used_material(whole)), 1e-9 * ml(used_material(whole)));
    }
  }
}

TEST_F(ChunkedMaskExport, CancellingWhileARangeIsMadeLeavesNothing) {
  const Job j = arch_job();
  const SliceChunks chunks = chunks_of(j, layer_chunks(j.mesh, j.planes, 24 * j.whole.points() / 3, 24));
  for (const char* name : {"/c.sl1", "/c.goo", "/c"}) {
    bool making = false;
    SliceChunks cancelled = chunks;
    cancelled.make = [&](size_t i, const Progress& p) {
      making = i == 1;
      return chunks.make(i, p);
    };
    EXPECT_THROW(export_masks(cancelled, j.profile, dir + name, [&](double, const char*) { return !making; }),
                 Cancelled);
    EXPECT_FALSE(fs::exists(dir + name));
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(ChunkedMaskExport, RefusesRangesThatDoNotTileTheStack) {
  const Job j = arch_job();
  const size_t L = j.planes.size();
  for (const std::vector<size_t>& first : std::vector<std::vector<size_t>>{{}, {0}, {1, L}, {0, 5, 5, L}, {0, 7, 3, L}})
    EXPECT_NE(test::error_of([&] { export_masks(chunks_of(j, first), j.profile, dir + "/x.sl1"); })
                  .find("layer ranges"),
              std::string::npos);
  // A range whose part reaches beyond its layers: the second range's layers in the first, or its
  // own layers starting one layer late.
  SliceChunks wrong = chunks_of(j, {0, 10, L});
  const auto make = wrong.make;
  wrong.make = [make](size_t i, const Progress& p) { return make(i == 0 ? 1 : i, p); };
  EXPECT_NE(test::error_of([&] { export_masks(wrong, j.profile, dir + "/y.sl1"); })
                .find("range 0 holds a part of " + std::to_string(L - 10) + " layers from its layer 0, beyond its 10 layers"),
            std::string::npos);
  wrong.make = [make](size_t i, const Progress& p) {
    std::vector<SlicePart> parts = make(i, p);
    parts[0].first = i;
    return parts;
  };
  EXPECT_NE(test::error_of([&] { export_masks(wrong, j.profile, dir + "/y.sl1"); })
                .find("range 1 holds a part of " + std::to_string(L - 10) + " layers from its layer 1, beyond"),
            std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir));
}

// A stack made a layer at a time where it is drawn (LayerMaker, as a reused build plate is):
// here each layer as two parts, its even and its odd contours, one contour flagged open. The
// export equals that of the whole stack (with the same contour open), each layer is made once,
// the open contour is counted, and a maker that gives more than one layer is refused in words,
// leaving nothing.
TEST_F(ChunkedMaskExport, LayersMadeWhereDrawnEqualTheExportOfTheWholeStack) {
  Job j = arch_job();
  j.profile.antialiasing = true;
  j.profile.gamma = 1;
  const size_t L = j.whole.layers(), open_layer = L / 2;
  Slices with_open = j.whole;
  with_open.contour_open[with_open.layer_begin[open_layer]] = 1;
  std::vector<std::atomic<int>> made(L);
  LayerMaker maker{L, j.whole.thickness, [&](size_t k, std::vector<SlicePart>& parts) {
                     ++made[k];
                     parts.resize(2);
                     for (size_t parity : {0, 1}) parts[parity] = {contours_of_parity(with_open, k, k + 1, parity), 0};
                   }};
  for (const char* ext : {".sl1", ".goo", ""}) {
    for (std::atomic<int>& m : made) m = 0;
    const std::string whole = dir + "/whole" + ext, drawn = dir + "/drawn" + ext;
    const MaskExportStats a = export_masks(with_open, j.profile, whole);
    const MaskExportStats b = export_masks(maker, j.profile, drawn);
    EXPECT_EQ(std::count(made.begin(), made.end(), 1), long(L));
    EXPECT_EQ(a.ignored_open_contours, 1u);
    EXPECT_EQ(b.ignored_open_contours, 1u);
    EXPECT_EQ(b.layers, L);
    EXPECT_EQ(b.min_x, a.min_x);
    EXPECT_EQ(b.max_y, a.max_y);
    const StackComparison c = compare_mask_stacks(whole, drawn, "");
    EXPECT_EQ(c.layers.size(), L);
    EXPECT_EQ(c.min_similarity, 1.0);
    EXPECT_EQ(c.differing_pixels, 0u);
    EXPECT_EQ(c.max_grey_difference, 0);
  }
  LayerMaker two{L, j.whole.thickness, [&](size_t k, std::vector<SlicePart>& parts) {
                   parts.assign(1, {contours_of_parity(j.whole, k, std::min(k + 2, L), 0), 0});
                 }};
  for (const std::string& name : {dir + "/bad.sl1", dir + "/bad"})
    EXPECT_NE(test::error_of([&] { export_masks(two, j.profile, name); })
                  .find("was made as a part of 2 layers from its layer 0, not as one layer"),
              std::string::npos);
  for (const std::string& name : {dir + "/bad.sl1", dir + "/bad"}) EXPECT_FALSE(fs::exists(name));
}
