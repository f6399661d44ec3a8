#pragma once
// Reading a .goo file (goo_format.h) as a stack of masks, for MaskStack (mask_stack.h):
//   index_goo_file(fd, path)   walks the file: checks the header's magic and size, then every
//                              layer record's delimiters and that the records end exactly in the
//                              ending string; returns the image size and where each layer's
//                              image data lies. Nothing is decoded.
//   read_goo_layer(...)        layer k's image data as stored (bytes replaced).
//   decode_goo_layer(...)      one layer's image data (0x55, chunks, checksum) -> width x height
//                              8-bit pixels in out, after checking the magic and the checksum.
// Both throw Error naming the file (and the layer) and the problem in words: a truncated file
// or record, a bad magic or delimiter, a checksum mismatch, chunks that make more or fewer
// pixels than the image holds, a diff that leaves 0..255. Images of more than kGooMaxPixels
// are refused (no printer's display comes near; a forged header cannot make a reader allocate
// gigabytes).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

inline constexpr uint64_t kGooMaxPixels = uint64_t(1) << 28;  // 268 M; a 16K display has 94 M

struct GooIndex {
  int width = 0, height = 0;
  std::vector<uint64_t> data_at;  // per layer: its image data's offset in the file
  std::vector<uint32_t> data_size;
};

GooIndex index_goo_file(int fd, const std::string& path);

void read_goo_layer(int fd, const GooIndex& index, size_t k, const std::string& name, std::vector<uint8_t>& bytes);

void decode_goo_layer(const uint8_t* data, size_t size, int width, int height, const std::string& name,
                      MaskImage& out);

}  // namespace slicereuse
