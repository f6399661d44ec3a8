#pragma once
// Reading an Anycubic Photon Workshop file (photon_workshop_format.h; versions 1 and 515..518
// with pw0Img layers) as a stack of masks, for MaskStack (mask_stack.h):
//   index_photon_workshop_file(fd, path)   checks the file mark ("ANYCUBIC", a known version),
//                                          the HEADER table's name and resolution, the LAYERDEF
//                                          table's name, length and layer count, and that every
//                                          layer's data lies within the file; returns the image
//                                          size and where each layer's data lies. Nothing is
//                                          decoded.
//   read_photon_workshop_layer(...)        layer k's pw0Img data as stored (bytes replaced).
//   decode_pw0_layer(...)                  one layer's pw0Img data -> width x height 8-bit
//                                          pixels in out (code c read as level 17c).
// They throw Error naming the file (and the layer) and the problem in words: a truncated file, a
// table that is not where the file mark says, a layer count the file cannot hold (checked against
// the file size before anything is allocated), data beyond the end, runs that make more or fewer
// pixels than the image or a run cut off by the end of the data. Images of more than
// kGooMaxPixels are refused, as in .goo (goo_stack.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "goo_stack.h"
#include "slicereuse/png/mask_png.h"

namespace slicereuse {

struct PhotonWorkshopIndex {
  int width = 0, height = 0;
  std::vector<uint32_t> data_at;  // per layer: its data's offset in the file
  std::vector<uint32_t> data_size;
};

PhotonWorkshopIndex index_photon_workshop_file(int fd, const std::string& path);

void read_photon_workshop_layer(int fd, const PhotonWorkshopIndex& index, size_t k, const std::string& name,
                                std::vector<uint8_t>& bytes);

void decode_pw0_layer(const uint8_t* data, size_t size, int width, int height, const std::string& name,
                      MaskImage& out);

}  // namespace slicereuse
