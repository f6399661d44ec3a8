// support_traps: the resin traps a supported print's supports close are found over the whole
// stack and lit whole, pixel for pixel, in every layer they span, however their size changes
// from layer to layer; after lighting, the printability check finds no resin trap. Air that
// drains (to the border, the top layer, layer 0) stays, as do a part's own hole no support
// touches and a trap larger than the limit; a hole too small ever to drain is lit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/printability/check_layers.h"
#include "slicereuse/printability/support_traps.h"

using namespace slicereuse;

namespace {

using Rows = std::vector<std::string>;

// A mask drawn from text rows: '.' unlit, '#' and 'S' 255, '-' a grey 60 (air to the resin-trap
// check), '+' a grey 140 (solid to it). The supports' mask: 'S' lit, all else unlit.
MaskRuns mask_of(const Rows& rows, bool supports_only = false) {
  MaskImage m{int(rows[0].size()), int(rows.size()), {}};
  for (const std::string& r : rows)
    for (char c : r)
      m.pixels.push_back(supports_only ? (c == 'S' ? 255 : 0)
                                       : c == '#' || c == 'S' ? 255 : c == '-' ? 60 : c == '+' ? 140 : 0);
  return mask_runs_of(m);
}

Rows rows_of(const MaskRuns& runs) {
  std::vector<uint8_t> pixels(size_t(runs.width) * size_t(runs.height));
  draw_mask_runs(runs, pixels.data());
  Rows out;
  for (int y = 0; y < runs.height; ++y) {
    std::string r;
    for (int x = 0; x < runs.width; ++x) {
      const uint8_t v = pixels[size_t(y) * size_t(runs.width) + size_t(x)];
      r += v == 255 ? '#' : v == 60 ? '-' : v == 140 ? '+' : v == 0 ? '.' : '?';
    }
    out.push_back(r);
  }
  return out;
}

// The stack's layers with their traps lit (as '#', supports too), the traps lit, and the resin
// traps the printability check then finds.
struct Lit {
  std::vector<Rows> layers;
  size_t traps = 0;
  uint64_t pixels = 0;
  size_t found = 0;
};

Lit lit(const std::vector<Rows>& stack, uint64_t max_pixels = 1000) {
  SupportTraps traps(max_pixels);
  for (const Rows& layer : stack) traps.add_layer(prepare_trap_layer(mask_of(layer), mask_of(layer, true)));
  traps.finish();
  Lit out;
  out.traps = traps.traps();
  out.pixels = traps.lit_pixels();
  LayerChecker checker(0.05, 0.05, 0.05);
  for (size_t k = 0; k < stack.size(); ++k) {
    MaskRuns mask = mask_of(stack[k]);
    const Rows before = rows_of(mask);
    traps.light(k, mask);
    out.layers.push_back(rows_of(mask));
    EXPECT_EQ(traps.lit(k), out.layers.back() != before) << "layer " << k;
    checker.add_layer(mask);
  }
  out.found = checker.finish().count(FindingKind::ResinTrap);
  return out;
}

// The text rows with 'S' drawn as '#' (what a lit layer shows).
Rows shown(Rows rows) {
  for (std::string& r : rows)
    for (char& c : r)
      if (c == 'S') c = '#';
  return rows;
}

const Rows kSolid = {
    "..............",  //
    ".############.",  //
    ".############.",  //
    ".############.",  //
    ".############.",  //
    ".############.",  //
    ".############.",  //
    "..............",  //
};

// A pocket of air in a ring, split by a pillar (S) into two of 9 pixels.
const Rows kPocket = {
    "..............",  //
    ".############.",  //
    ".###...S...##.",  //
    ".###...S...##.",  //
    ".###...S...##.",  //
    ".############.",  //
    ".############.",  //
    "..............",  //
};

}  // namespace

TEST(SupportTraps, APocketSupportsCloseIsLitWholeHoweverItsSizeChanges) {
  // A part's floor, three layers of a pocket beside a pillar (S) of 5, 18 and 7 pixels of air
  // (two of them grey, below the resin-trap level), and a lid: one trap, lit in all three
  // layers; a grey pixel above the resin-trap level (+) stays. Lit a layer at a time under a
  // limit between the sizes, the middle layer's air would be trapped between lit ones.
  const std::vector<Rows> stack = {
      kSolid,
      {
          "..............",  //
          ".############.",  //
          ".###S..######.",  //
          ".###S..######.",  //
          ".###S.#######.",  //
          ".############.",  //
          ".#########+##.",  //
          "..............",  //
      },
      {
          "..............",  //
          ".############.",  //
          ".###S......##.",  //
          ".###S-.....##.",  //
          ".###S.....-##.",  //
          ".############.",  //
          ".#########+##.",  //
          "..............",  //
      },
      {
          "..............",  //
          ".############.",  //
          ".###S..######.",  //
          ".###S....####.",  //
          ".###S.#######.",  //
          ".############.",  //
          ".#########+##.",  //
          "..............",  //
      },
      kSolid,
  };
  const Lit l = lit(stack);
  EXPECT_EQ(l.traps, 1u);
  EXPECT_EQ(l.pixels, 5u + 18 + 7);
  EXPECT_EQ(l.found, 0u);
  const Rows expected = {
      "..............",  //
      ".############.",  //
      ".############.",  //
      ".############.",  //
      ".############.",  //
      ".############.",  //
      ".#########+##.",  //
      "..............",  //
  };
  EXPECT_EQ(l.layers[0], kSolid);
  for (size_t k = 1; k <= 3; ++k) EXPECT_EQ(l.layers[k], expected) << "layer " << k;
  EXPECT_EQ(l.layers[4], kSolid);
  // Left unlit, the same stack holds that trap.
  const Lit none = lit(stack, 0);
  EXPECT_EQ(none.traps, 0u);
  EXPECT_EQ(none.found, 1u);
  for (size_t k = 0; k < stack.size(); ++k) EXPECT_EQ(none.layers[k], shown(stack[k])) << "layer " << k;
}

TEST(SupportTraps, AirThatDrainsStays) {
  const Rows open = {
      "..............",  //
      ".############.",  //
      ".......S......",  //
      ".......S......",  //
      ".###...S...##.",  //
      ".############.",  //
      ".############.",  //
      "..............",  //
  };
  // Open to the top layer's air; reaching layer 0 (the plate closes it); joined, through all
  // of its 9 pixels a side, to air that reaches the image border.
  const std::vector<std::vector<Rows>> stacks = {
      {kSolid, kPocket, kPocket}, {kPocket, kPocket, kSolid}, {kSolid, kPocket, open, kSolid}};
  for (const std::vector<Rows>& stack : stacks) {
    const Lit l = lit(stack);
    EXPECT_EQ(l.traps, 0u);
    for (size_t k = 0; k < stack.size(); ++k) EXPECT_EQ(l.layers[k], shown(stack[k])) << "layer " << k;
  }
}

TEST(SupportTraps, APartsOwnHoleStaysAndHolesTooSmallToDrainAreLit) {
  // No support: a closed hole of 12 pixels a layer stays (the check reports it); one of 6 pixels
  // a layer, which air never drains through, is lit, and so is a speck of air the check takes
  // as solid (1 pixel).
  const Rows holes = {
      "..............",  //
      ".############.",  //
      ".#....####..#.",  //
      ".#....####..#.",  //
      ".#....####..#.",  //
      ".#####.######.",  //
      ".############.",  //
      "..............",  //
  };
  const std::vector<Rows> stack = {kSolid, holes, holes, kSolid};
  const Lit l = lit(stack);
  EXPECT_EQ(l.traps, 1u);
  EXPECT_EQ(l.pixels, 2u * (6 + 1));
  EXPECT_EQ(l.found, 1u);
  const Rows expected = {
      "..............",  //
      ".############.",  //
      ".#....#######.",  //
      ".#....#######.",  //
      ".#....#######.",  //
      ".############.",  //
      ".############.",  //
      "..............",  //
  };
  EXPECT_EQ(l.layers[1], expected);
  EXPECT_EQ(l.layers[2], expected);
}

TEST(SupportTraps, ATrapLargerThanTheLimitStays) {
  // Two traps, one each side of the pillar, of 9 pixels a layer.
  const std::vector<Rows> stack = {kSolid, kPocket, kPocket, kSolid};
  EXPECT_EQ(lit(stack, 18).traps, 2u);
  const Lit l = lit(stack, 17);
  EXPECT_EQ(l.traps, 0u);
  EXPECT_EQ(l.found, 2u);
  EXPECT_EQ(l.layers[1], shown(kPocket));
}

TEST(SupportTraps, MasksOfAnotherSizeAreRefused) {
  SupportTraps traps(100);
  EXPECT_ERROR(prepare_trap_layer(mask_of(kSolid), mask_of({"..", ".."})),
               "internal error: a 14 x 8 mask with supports of 2 x 2 pixels");
  traps.add_layer(prepare_trap_layer(mask_of(kSolid), mask_of(kSolid, true)));
  EXPECT_ERROR(traps.add_layer(prepare_trap_layer(mask_of({"..", ".."}), mask_of({"..", ".."}))),
               "layer 1 is 2 x 2 pixels, layer 0 14 x 8");
}
