// seal_support_pockets: the pockets of air that supports close, and those too small ever to
// drain, are lit, pixel for pixel; a part's own hole, air reaching the border, a pocket too large
// and one no support touches stay.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/printability/seal_support_pockets.h"

using namespace slicereuse;

namespace {

// A mask drawn from text rows: '.' unlit, '#' 255, '-' a grey 60 (air to the resin-trap check),
// '+' a grey 140 (solid to it).
MaskImage image_of(const std::vector<std::string>& rows) {
  MaskImage m{int(rows[0].size()), int(rows.size()), {}};
  for (const std::string& r : rows)
    for (char c : r) m.pixels.push_back(c == '#' ? 255 : c == '-' ? 60 : c == '+' ? 140 : 0);
  return m;
}

// The mask after sealing, as text rows again ('#' for 255), and the pockets sealed.
std::vector<std::string> sealed(const std::vector<std::string>& mask, const std::vector<std::string>& supports,
                                uint64_t max_pixels, size_t* count = nullptr) {
  MaskRuns runs = mask_runs_of(image_of(mask));
  const size_t n = seal_support_pockets(runs, mask_runs_of(image_of(supports)), max_pixels);
  if (count) *count = n;
  std::vector<uint8_t> pixels(size_t(runs.width) * size_t(runs.height));
  draw_mask_runs(runs, pixels.data());
  std::vector<std::string> out;
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

const std::vector<std::string> kNone(9, std::string(20, '.'));

}  // namespace

TEST(SealSupportPockets, APocketSupportsCloseIsLitWithItsGreyPixels) {
  // A pillar (a support, right) against a part closes a pocket of 12 pixels, 4 of them grey below
  // the resin-trap level: lit. The part's own hole of 12 pixels (left) touches no support and
  // stays; its hole of 2 pixels, too small ever to drain, is lit; a grey pixel above the
  // resin-trap level (bottom right) stays as it is.
  const std::vector<std::string> mask = {
      "....................",  //
      "##########..######..",  //
      "#....#####..#---##..",  //
      "#....##..#..#...##..",  //
      "#....#####..#...##..",  //
      "##########..#..-##..",  //
      "............#####+..",  //
      "....................",  //
      "...................."};
  std::vector<std::string> supports = kNone;
  for (int y = 1; y <= 6; ++y) supports[size_t(y)][16] = '#';
  size_t count = 0;
  EXPECT_EQ(sealed(mask, supports, 200, &count), (std::vector<std::string>{
                                                      "....................",  //
                                                      "##########..######..",  //
                                                      "#....#####..######..",  //
                                                      "#....#####..######..",  //
                                                      "#....#####..######..",  //
                                                      "##########..######..",  //
                                                      "............#####+..",  //
                                                      "....................",  //
                                                      "...................."}));
  EXPECT_EQ(count, 2u);
  // A support touching only a corner of the pocket's pixel closes it too.
  std::vector<std::string> corner = kNone;
  corner[6][16] = '#';
  EXPECT_EQ(sealed(mask, corner, 200)[5], "##########..######..");
}

TEST(SealSupportPockets, AirAtTheBorderAPocketTooLargeOrNotTouchedStays) {
  const std::vector<std::string> open = {
      "....................",  //
      "...######...........",  //
      "...#....#...........",  //
      "...#................",  //
      "...#....#...........",  //
      "...######...........",  //
      "....................",  //
      "....................",  //
      "...................."};
  // The air leaks out on the right between two pillars: no pocket.
  std::vector<std::string> supports = kNone;
  supports[2][8] = supports[4][8] = '#';
  size_t count = 9;
  EXPECT_EQ(sealed(open, supports, 200, &count), open);
  EXPECT_EQ(count, 0u);
  // Closed: 12 pixels, not fewer than a limit of 12, or touched by no support, it stays.
  std::vector<std::string> closed = open;
  closed[3][8] = '#';
  EXPECT_EQ(sealed(closed, supports, 12), closed);
  EXPECT_EQ(sealed(closed, kNone, 200), closed);
  std::vector<std::string> lit = closed;
  for (int y = 2; y <= 4; ++y) lit[size_t(y)].replace(4, 4, "####");
  EXPECT_EQ(sealed(closed, supports, 13), lit);
  // Air along the image's edge is never a pocket, even enclosed on three sides and small.
  const std::vector<std::string> edge = {
      "#.#.................",  //
      "#.#.................",  //
      "###.................",  //
      "....................",  //
      "....................",  //
      "....................",  //
      "....................",  //
      "....................",  //
      "...................."};
  EXPECT_EQ(sealed(edge, edge, 200), edge);
}

TEST(SealSupportPockets, MasksOfOtherSizesAreAnInternalError) {
  MaskRuns mask = mask_runs_of(image_of(kNone));
  const MaskRuns other = mask_runs_of(image_of({"#..", "..."}));
  EXPECT_ERROR(seal_support_pockets(mask, other, 10), "a 20 x 9 mask sealed with supports of 3 x 2 pixels");
}
