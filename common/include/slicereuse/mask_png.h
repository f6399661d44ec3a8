#pragma once
// PNG encoding and decoding of mask images in memory, through OpenImageIO.
//
// encode_mask_png: width x height bytes (row-major, one grey channel) -> a PNG file's bytes in
// out (replaced), greyscale with bits = 1 (a pixel is white when its byte is >= 128) or 8.
// 8-bit PNGs are written by OpenImageIO; 1-bit ones directly with zlib, because OpenImageIO
// 2.4's PNG writer ignores "oiio:BitsPerSample" and 8-bit binary masks cost 8x the deflate and
// checksum work (the export's bottleneck). Both use no row filter and zlib's run-length
// strategy at level 1, the fastest and smallest setting measured on mostly black masks.
// decode_mask_png: a PNG file's bytes -> its first channel as 8-bit grey (1-, 2-, 4- and 16-bit
// files are converted); name (a path or archive:entry) only appears in error messages.
// Both are thread-safe and throw Error on failure.
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

void encode_mask_png(const uint8_t* pixels, int width, int height, int bits,
                     std::vector<uint8_t>& out);
void decode_mask_png(const uint8_t* data, size_t size, const std::string& name, MaskImage& out);

}  // namespace slicereuse
