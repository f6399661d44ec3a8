#pragma once
// PNG encoding and decoding of mask images in memory.
//
// encode_mask_png: width x height bytes (row-major, one grey channel) -> a PNG file's bytes in
// out (replaced), greyscale with bits = 1 (a pixel is white when its byte is >= 128) or 8.
// encode_mask_png of MaskRuns: the same 8-bit PNG of a mask given as runs of lit pixels, in
// time proportional to the runs, not the pixels (an anti-aliased mask's grey pixels, only
// along the edges, are runs of their own).
// No row filter; the image data is deflated by RunDeflater (deflate_runs.h), which does what
// zlib's run-length strategy does on masks in a fraction of the time: the 8-bit PNGs that
// .sl1 archives need made zlib the bottleneck of mask export; libdeflate, too, is far slower on
// masks (bench_masks --steps deflate compares them; bench/RESULTS.md).
// encode_rgba_png: width x height RGBA pixels (4 bytes each, row-major) -> an 8-bit RGBA PNG in
// out (replaced), for the pictures of a print file (thumbnail_png.h): rows filtered with Sub
// (each byte less the same channel's of the pixel before), so that a picture's runs of equal
// pixels become runs of zeros for the same deflater: faster than libpng, for somewhat larger PNGs.
// decode_mask_png: a PNG file's bytes -> 8-bit grey pixels (other depths and colour types are
// converted by libpng's simplified reader); name (a path or archive:entry) only appears in
// error messages.
// Both are thread-safe and throw Error on failure.
//
// Decoding is libpng's. Why not OpenImageIO: it drags some 270 shared libraries into the host
// process, and inside pymeshlab its libcurl clashes with the older libnghttp2 bundled in the
// wheel, so pymeshlab.load_plugin failed; OpenImageIO 2.4 also cannot write 1-bit PNGs.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace slicereuse {

struct MaskImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // width * height
};

// A mask as runs of lit pixels: row r's runs are the column ranges
// [columns[2i], columns[2i+1]) for i in [row_begin[r], row_begin[r+1]), increasing and disjoint,
// run i's pixels all levels[i] (255 in a binary mask); pixels in no run are 0.
struct MaskRuns {
  int width = 0;
  int height = 0;
  std::vector<uint32_t> row_begin;  // height + 1
  std::vector<uint16_t> columns;    // 2 per run
  std::vector<uint8_t> levels;      // 1 per run
};

// mask_runs_of: an image -> its runs of equal non-zero levels (what the rasterizer gives); it
// skips unlit pixels eight at a time.
MaskRuns mask_runs_of(const MaskImage& image);

// draw_mask_runs: runs -> their image in pixels (runs.width * runs.height bytes, row-major,
// every pixel written: 0 outside the runs).
void draw_mask_runs(const MaskRuns& runs, uint8_t* pixels);

void encode_mask_png(const uint8_t* pixels, int width, int height, int bits,
                     std::vector<uint8_t>& out);
void encode_mask_png(const MaskRuns& runs, std::vector<uint8_t>& out);
void encode_rgba_png(const uint8_t* rgba, int width, int height, std::vector<uint8_t>& out);
void decode_mask_png(const uint8_t* data, size_t size, const std::string& name, MaskImage& out);

}  // namespace slicereuse
