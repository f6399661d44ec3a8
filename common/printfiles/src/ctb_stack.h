#pragma once
// Reading a Chitubox .ctb file (ctb_format.h) as a stack of masks, for MaskStack (mask_stack.h):
//   index_ctb_file(fd, path)   checks the magic and reads the header and the layer table: the
//                              image size, the encryption key and where each layer's data lies
//                              (its page of 4 GB and address), every count and place checked
//                              against the file's size before anything is allocated for it.
//                              Nothing is decoded.
//   read_ctb_layer(...)        layer k's image data as stored (bytes replaced).
//   decode_ctb_layer(...)      layer k's image data -> width x height 8-bit pixels in out, the
//                              cipher undone first when the key is not 0 (layer k's key stream);
//                              a 7-bit code c is the level 0 for c = 0, else 2c + 1.
// Both throw Error naming the file (and the layer) and the problem in words: a truncated file,
// a wrong magic (the encrypted CTB of newer Chitu boards and the 1-bit .cbddlp named as such),
// a layer table or layer data beyond the end of the file, a run length cut off or of no known
// form, runs that make more or fewer pixels than the image holds. Images of more than
// kGooMaxPixels are refused (goo_stack.h: a forged header cannot make a reader allocate gigabytes).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

struct CtbIndex {
  int width = 0, height = 0;
  uint32_t key = 0;
  std::vector<uint64_t> data_at;  // per layer: its image data's offset in the file
  std::vector<uint32_t> data_size;
};

CtbIndex index_ctb_file(int fd, const std::string& path);

void read_ctb_layer(int fd, const CtbIndex& index, size_t k, const std::string& name, std::vector<uint8_t>& bytes);

void decode_ctb_layer(const uint8_t* data, size_t size, int width, int height, uint32_t key, size_t k,
                      const std::string& name, MaskImage& out);

}  // namespace slicereuse
