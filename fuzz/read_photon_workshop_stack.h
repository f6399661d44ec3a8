#pragma once
// read_photon_workshop_stack: what the photon_workshop_stack fuzz target calls: indexes the file
// at path as an Anycubic Photon Workshop file (photon_workshop_stack.h), then reads and decodes
// every layer, as MaskStack and compare_mask_stacks do. Called directly rather than through
// MaskStack, so that an input whose "ANYCUBIC" is mutated away still reaches this reader's checks.
// Its seeds are files the writer made for a small display, their previews cut out (preview
// addresses 0, as a file without previews has them) to keep them a few KB.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "photon_workshop_stack.h"
#include "slicereuse/util/error.h"

namespace slicereuse {

inline void read_photon_workshop_stack(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  try {
    const PhotonWorkshopIndex index = index_photon_workshop_file(fd, path);
    std::vector<uint8_t> bytes;
    MaskImage image;
    for (size_t k = 0; k < index.data_at.size(); ++k) {
      read_photon_workshop_layer(fd, index, k, path, bytes);
      decode_pw0_layer(bytes.data(), bytes.size(), index.width, index.height, path, image);
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

}  // namespace slicereuse
