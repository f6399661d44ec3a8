// compare_mask_stacks on grey masks: hand-made 8-bit stacks with one known difference per layer
// give exact S (on the >= 128 threshold), largest grey difference, pixels over one level, the
// stack's worst layers and share, and the same figures in the CSV report; anti-aliased exports
// of the same slices compare as identical.
#include <gtest/gtest.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "mask_layers.h"
#include "mask_stack.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "test_files.h"

using namespace slicereuse;

namespace {

// Odd sizes, so the pixel loop's vector part and its remainder both run.
constexpr int W = 67, H = 33;
constexpr uint64_t N = uint64_t(W) * H;

// Every level from 0 to 255 somewhere, none of them in a pattern of rows or columns.
std::vector<uint8_t> grey_image() {
  std::vector<uint8_t> img(N);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) img[size_t(y) * W + size_t(x)] = uint8_t((x * 37 + y * 11) % 256);
  return img;
}

// 0 or 255, as binary masks are.
std::vector<uint8_t> binary_image() {
  std::vector<uint8_t> img = grey_image();
  for (uint8_t& v : img) v = v >= 128 ? 255 : 0;
  return img;
}

// One image of a hand-made stack, with the PNG bit depth to write it in.
struct Image {
  std::vector<uint8_t> pixels;
  int bits = 8;
};

void write_stack(const std::string& folder, const std::vector<Image>& layers, int width = W, int height = H) {
  std::filesystem::create_directory(folder);
  std::vector<uint8_t> png;
  for (size_t k = 0; k < layers.size(); ++k) {
    encode_mask_png(layers[k].pixels.data(), width, height, layers[k].bits, png);
    test::spit(folder + "/" + mask_layer_file_name("layer", k), std::string(png.begin(), png.end()));
  }
}

// The image with pixel p of level `level`.
std::vector<uint8_t> with(std::vector<uint8_t> img, size_t p, uint8_t level) {
  img[p] = level;
  return img;
}

struct Row {
  size_t layer;
  double similarity;
  uint64_t differing, max_difference, over_one;
};

// The report's rows, each field read back by from_chars (the shortest form reads back exactly).
std::vector<Row> read_report(const std::string& path, std::string& header) {
  std::istringstream in(test::slurp(path));
  std::getline(in, header);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    Row r{};
    const char* p = line.data();
    const char* end = line.data() + line.size();
    auto field = [&](auto& value) {
      const auto [next, ec] = std::from_chars(p, end, value);
      EXPECT_EQ(ec, std::errc()) << line;
      if (next == end) {
        p = next;
      } else {
        EXPECT_EQ(*next, ',') << line;
        p = next + 1;
      }
    };
    field(r.layer);
    field(r.similarity);
    field(r.differing);
    field(r.max_difference);
    field(r.over_one);
    EXPECT_EQ(p, end) << "more columns than five: " << line;
    rows.push_back(r);
  }
  return rows;
}

class CompareGreyMasks : public test::TempFolderTest {};

TEST_F(CompareGreyMasks, IdenticalGreyStacksHaveNoDifference) {
  write_stack(path("a"), {{grey_image()}, {with(grey_image(), 5, 200)}});
  const StackComparison c = compare_mask_stacks(path("a"), path("a"), "");
  ASSERT_EQ(c.layers.size(), 2u);
  for (const LayerSimilarity& l : c.layers) {
    EXPECT_EQ(l.similarity, 1.0);
    EXPECT_EQ(l.differing_pixels, 0u);
    EXPECT_EQ(l.max_grey_difference, 0);
    EXPECT_EQ(l.over_one_level_pixels, 0u);
  }
  EXPECT_EQ(c.min_similarity, 1.0);
  EXPECT_EQ(c.max_grey_difference, 0);
  EXPECT_EQ(c.over_one_level_pixels, 0u);
  EXPECT_EQ(c.over_one_level_share, 0.0);
  EXPECT_EQ((std::vector<size_t>{c.worst_layer, c.max_grey_difference_layer, c.over_one_level_layer}),
            (std::vector<size_t>{0, 0, 0}));
}

TEST_F(CompareGreyMasks, EachLayersKnownDifferenceGivesExactFigures) {
  const std::vector<uint8_t> grey = grey_image(), binary = binary_image();
  const size_t p = 17 * W + 41, q = 32 * W + 66;  // inside, and the very last pixel
  write_stack(path("a"), {
                             {grey},                             // 0: the same bytes
                             {binary, 1},                        // 1: the same pixels, 1 bit here, 8 in b
                             {with(grey, p, 100)},               // 2: 100 vs 101, both off
                             {with(grey, p, 127)},               // 3: 127 (off) vs 128 (on)
                             {with(grey, q, 0)},                 // 4: 0 vs 255
                             {with(with(grey, p, 10), q, 200)},  // 5: 10 vs 12 and 200 vs 129, neither
                                                                 //    crossing the threshold
                         });
  write_stack(path("b"), {
                             {grey},
                             {binary, 8},
                             {with(grey, p, 101)},
                             {with(grey, p, 128)},
                             {with(grey, q, 255)},
                             {with(with(grey, p, 12), q, 129)},
                         });
  const StackComparison c = compare_mask_stacks(path("a"), path("b"), path("r.csv"));
  ASSERT_EQ(c.layers.size(), 6u);
  const double one_pixel = 1.0 - 1.0 / double(N);
  const std::vector<Row> expected = {
      // layer, S, differing pixels, largest grey difference, pixels over one level
      {0, 1.0, 0, 0, 0},
      {1, 1.0, 0, 0, 0},
      {2, 1.0, 0, 1, 0},
      {3, one_pixel, 1, 1, 0},
      {4, one_pixel, 1, 255, 1},
      {5, 1.0, 0, 71, 2},
  };
  for (const Row& e : expected) {
    const LayerSimilarity& l = c.layers[e.layer];
    EXPECT_EQ(l.layer, e.layer);
    EXPECT_EQ(l.similarity, e.similarity) << "layer " << e.layer;
    EXPECT_EQ(l.differing_pixels, e.differing) << "layer " << e.layer;
    EXPECT_EQ(uint64_t(l.max_grey_difference), e.max_difference) << "layer " << e.layer;
    EXPECT_EQ(l.over_one_level_pixels, e.over_one) << "layer " << e.layer;
  }
  // Layers 3 and 4 tie on S: the first is the worst.
  EXPECT_EQ(c.min_similarity, one_pixel);
  EXPECT_EQ(c.worst_layer, 3u);
  EXPECT_EQ(c.differing_pixels, 2u);
  EXPECT_EQ(c.max_grey_difference, 255);
  EXPECT_EQ(c.max_grey_difference_layer, 4u);
  EXPECT_EQ(c.over_one_level_pixels, 3u);
  EXPECT_EQ(c.over_one_level_share, 3.0 / double(6 * N));
  EXPECT_EQ(c.over_one_level_layer, 5u);
  // Layer 4 alone: its one pixel over one level is the share.
  write_stack(path("a4"), {{with(grey, q, 0)}});
  write_stack(path("b4"), {{with(grey, q, 255)}});
  EXPECT_EQ(compare_mask_stacks(path("a4"), path("b4"), "").over_one_level_share, 1.0 / double(N));

  std::string header;
  const std::vector<Row> rows = read_report(path("r.csv"), header);
  EXPECT_EQ(header, "layer,similarity,differing_pixels,max_grey_difference,over_one_level_pixels");
  ASSERT_EQ(rows.size(), expected.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k].layer, expected[k].layer);
    EXPECT_EQ(rows[k].similarity, expected[k].similarity) << "layer " << k;
    EXPECT_EQ(rows[k].differing, expected[k].differing) << "layer " << k;
    EXPECT_EQ(rows[k].max_difference, expected[k].max_difference) << "layer " << k;
    EXPECT_EQ(rows[k].over_one, expected[k].over_one) << "layer " << k;
  }
}

TEST_F(CompareGreyMasks, TiedLayersGiveTheFirstAsWorst) {
  const std::vector<uint8_t> grey = grey_image();
  write_stack(path("a"), {{grey}, {with(grey, 3, 0)}, {with(grey, 9, 0)}});
  write_stack(path("b"), {{grey}, {with(grey, 3, 255)}, {with(grey, 9, 255)}});
  const StackComparison c = compare_mask_stacks(path("a"), path("b"), "");
  EXPECT_EQ((std::vector<size_t>{c.worst_layer, c.max_grey_difference_layer, c.over_one_level_layer}),
            (std::vector<size_t>{1, 1, 1}));
}

TEST_F(CompareGreyMasks, CountsBeyondSixteenBitsAreExact) {
  // 90,000 pixels, black against white: more than one block of the pixel loop's 16-bit sums.
  constexpr int side = 300;
  constexpr uint64_t n = uint64_t(side) * side;
  std::vector<uint8_t> white(n, 255);
  white[n - 1] = 254;  // the last pixel, past the first block
  write_stack(path("a"), {{std::vector<uint8_t>(n, 0)}}, side, side);
  write_stack(path("b"), {{white}}, side, side);
  const StackComparison c = compare_mask_stacks(path("a"), path("b"), "");
  ASSERT_EQ(c.layers.size(), 1u);
  EXPECT_EQ(c.layers[0].differing_pixels, n);
  EXPECT_EQ(c.layers[0].similarity, 0.0);
  EXPECT_EQ(c.layers[0].over_one_level_pixels, n);
  EXPECT_EQ(c.max_grey_difference, 255);
  EXPECT_EQ(c.over_one_level_share, 1.0);
}

TEST_F(CompareGreyMasks, AntialiasedExportsOfTheSameSlicesAreIdentical) {
  const Slices s = test::make_slices({{test::star(0.3, -0.2, 3, 7.5, 9)},
                                      {test::rect(-4.33, -4.71, 5.12, 4.05), test::rect(-2, -2.37, 2.5, 2, true)}});
  PrinterProfile p = test::small_display();
  p.antialiasing = true;
  p.gamma = 1.8;
  for (const char* ext : {"", ".sl1"}) {
    const std::string a = path(std::string("a") + ext), b = path(std::string("b") + ext);
    export_masks(s, p, a);
    export_masks(s, p, b);
    // The masks do hold grey levels, so the comparison is one of grey images.
    MaskStack stack(a);
    std::vector<uint8_t> bytes;
    stack.read(0, bytes);
    MaskImage img;
    decode_mask_png(bytes.data(), bytes.size(), "layer 0", img);
    size_t grey = 0;
    for (uint8_t v : img.pixels) grey += v != 0 && v != 255;
    EXPECT_GT(grey, 100u);

    const StackComparison c = compare_mask_stacks(a, b, "");
    ASSERT_EQ(c.layers.size(), 2u);
    EXPECT_EQ(c.min_similarity, 1.0);
    EXPECT_EQ(c.differing_pixels, 0u);
    EXPECT_EQ(c.max_grey_difference, 0);
    EXPECT_EQ(c.over_one_level_pixels, 0u);
    EXPECT_EQ(c.over_one_level_share, 0.0);
  }
}

}  // namespace
