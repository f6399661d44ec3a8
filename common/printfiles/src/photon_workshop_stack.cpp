#include "photon_workshop_stack.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "file_read_at.h"
#include "photon_workshop_format.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

// A named table's start at `at` (name and length), checked to carry `name`; returns its length.
uint32_t table_start(int fd, uint64_t at, const char* name, const std::string& path, uint8_t (&base)[kPwsTableBase]) {
  read_at(fd, at, base, kPwsTableBase, path, format("the %s table (at byte %llu)", name, (unsigned long long)at));
  char expected[kPwsNameSize] = {};
  std::strncpy(expected, name, kPwsNameSize - 1);
  if (std::memcmp(base, expected, kPwsNameSize) != 0)
    throw Error(format("'%s' is corrupt: the file mark says the %s table is at byte %llu, but it is not there",
                       path.c_str(), name, (unsigned long long)at));
  return le32(base + kPwsNameSize);
}

}  // namespace

PhotonWorkshopIndex index_photon_workshop_file(int fd, const std::string& path) {
  const uint64_t file_size = slicereuse::file_size(fd, path);
  uint8_t mark[kPwsLayerDefAddressAt + 4];
  read_at(fd, 0, mark, sizeof mark, path, "the file mark");
  if (std::memcmp(mark, kPwsMark, sizeof kPwsMark) != 0)
    throw Error("'" + path + "' is not an Anycubic Photon Workshop file: it does not begin with \"ANYCUBIC\"");
  const uint32_t version = le32(mark + kPwsVersionAt);
  if (version != 1 && (version < 515 || version > 518))
    throw Error(format("'%s' is an Anycubic file of version %u, which is not one known (1, 515 to 518)", path.c_str(),
                       version));
  PhotonWorkshopIndex x;
  uint8_t base[kPwsTableBase];
  const uint64_t header_at = le32(mark + kPwsHeaderAddressAt);
  table_start(fd, header_at, "HEADER", path, base);
  uint8_t resolution[8];
  read_at(fd, header_at + kPwsHeaderResolutionAt, resolution, sizeof resolution, path, "the HEADER table");
  const uint32_t width = le32(resolution), height = le32(resolution + 4);
  if (width == 0 || height == 0 || uint64_t(width) * uint64_t(height) > kGooMaxPixels)
    throw Error(format("'%s' has images of %u x %u pixels, which is not within 1..%llu pixels", path.c_str(), width,
                       height, (unsigned long long)kGooMaxPixels));
  x.width = int(width);
  x.height = int(height);
  const uint64_t defs_at = le32(mark + kPwsLayerDefAddressAt);
  const uint32_t length = table_start(fd, defs_at, "LAYERDEF", path, base);
  uint8_t count_bytes[4];
  read_at(fd, defs_at + kPwsTableBase, count_bytes, 4, path, "the LAYERDEF table");
  const uint32_t layers = le32(count_bytes);
  if (length != 4 + uint64_t(layers) * kPwsLayerDefSize)
    throw Error(format("'%s' is corrupt: its LAYERDEF table is %u bytes long, but %u layers take %llu", path.c_str(),
                       length, layers, (unsigned long long)(4 + uint64_t(layers) * kPwsLayerDefSize)));
  // Checked against the file's size before the table is read into memory.
  const uint64_t entries_at = defs_at + kPwsTableBase + 4;
  if (entries_at > file_size || (file_size - entries_at) / kPwsLayerDefSize < layers)
    throw Error(format("'%s' is truncated: it ends inside the LAYERDEF table of %u layers (%llu bytes for the file's "
                       "%llu)",
                       path.c_str(), layers, (unsigned long long)(entries_at + uint64_t(layers) * kPwsLayerDefSize),
                       (unsigned long long)file_size));
  std::vector<uint8_t> entries(size_t(layers) * kPwsLayerDefSize);
  read_at(fd, entries_at, entries.data(), entries.size(), path, "the LAYERDEF table");
  x.data_at.resize(layers);
  x.data_size.resize(layers);
  for (uint32_t k = 0; k < layers; ++k) {
    const uint8_t* e = entries.data() + size_t(k) * kPwsLayerDefSize;
    x.data_at[k] = le32(e);
    x.data_size[k] = le32(e + 4);
    if (uint64_t(x.data_at[k]) + x.data_size[k] > file_size)
      throw Error(format("'%s' is truncated: layer %u's data (%u bytes at byte %u) ends beyond the file's %llu bytes",
                         path.c_str(), k, x.data_size[k], x.data_at[k], (unsigned long long)file_size));
  }
  return x;
}

void read_photon_workshop_layer(int fd, const PhotonWorkshopIndex& index, size_t k, const std::string& name,
                                std::vector<uint8_t>& bytes) {
  bytes.resize(index.data_size[k]);
  read_at(fd, index.data_at[k], bytes.data(), bytes.size(), name, "its image data");
}

void decode_pw0_layer(const uint8_t* d, size_t n, int width, int height, const std::string& name, MaskImage& out) {
  const size_t pixels = size_t(width) * size_t(height);
  // A byte makes at most kPwsMaxRun pixels: too little data is refused before the image is made.
  if (n / 2 * uint64_t(kPwsMaxRun) + n % 2 * kPwsMaxGreyRun < pixels)
    throw Error(format("'%s' is corrupt: its %zu bytes cannot make the %d x %d pixels of the image", name.c_str(), n,
                       width, height));
  out.width = width;
  out.height = height;
  out.pixels.resize(pixels);
  uint8_t* px = out.pixels.data();
  size_t filled = 0;
  for (size_t i = 0; i < n;) {
    const unsigned code = d[i] >> 4;
    size_t run = d[i++] & 0xF;
    if (code == 0 || code == 0xF) {
      if (i >= n) throw Error("'" + name + "' is corrupt: its last run is cut off (its second byte is missing)");
      run = run << 8 | d[i++];
    }
    if (run > pixels - filled)
      throw Error(format("'%s' is corrupt: its runs make more than the %d x %d pixels of the image", name.c_str(), width,
                         height));
    std::memset(px + filled, int(code * 17), run);
    filled += run;
  }
  if (filled != pixels)
    throw Error(format("'%s' is corrupt: its runs make %zu of the %zu pixels of the image", name.c_str(), filled, pixels));
}

}  // namespace slicereuse
