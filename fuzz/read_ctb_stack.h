#pragma once
// read_ctb_stack: what the ctb_stack fuzz target calls: indexes the file at path as a .ctb
// (ctb_stack.h), whatever its name, then reads and decodes every layer, as MaskStack does for
// compare_mask_stacks. Its seeds are small .ctb files of both versions, one encrypted.
#include <fcntl.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <vector>

#include "ctb_stack.h"
#include "slicereuse/util/error.h"

namespace slicereuse {

inline void read_ctb_stack(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path + "'");
  try {
    const CtbIndex index = index_ctb_file(fd, path);
    std::vector<uint8_t> bytes;
    MaskImage image;
    for (size_t k = 0; k < index.data_at.size(); ++k) {
      read_ctb_layer(fd, index, k, path, bytes);
      decode_ctb_layer(bytes.data(), bytes.size(), index.width, index.height, index.key, k, path, image);
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

}  // namespace slicereuse
