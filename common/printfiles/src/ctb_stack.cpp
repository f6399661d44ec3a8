#include "ctb_stack.h"

#include <algorithm>
#include <cstring>

#include "ctb_format.h"
#include "file_read_at.h"
#include "goo_stack.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

uint32_t little_endian(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

}  // namespace

CtbIndex index_ctb_file(int fd, const std::string& path) {
  const uint64_t size = file_size(fd, path);
  uint8_t head[kCtbHeaderSize];
  read_at(fd, 0, head, size_t(std::min<uint64_t>(size, 4)), path, "the header");
  const uint32_t magic = size < 4 ? 0 : little_endian(head);
  if (magic == kCtbEncryptedMagic)
    throw Error("'" + path +
                "' is an encrypted .ctb (magic 12FD0107, the closed scheme of newer Chitu boards), which is not read");
  if (magic == kCbddlpMagic)
    throw Error("'" + path + "' is a .cbddlp/.photon file (magic 12FD0019, 1-bit layers), which is not read");
  if (magic != kCtbMagic && magic != kCtbMagicV4)
    throw Error("'" + path + "' is not a .ctb file: its first 4 bytes are not the magic 86 00 FD 12 or 06 01 FD 12");
  read_at(fd, 0, head, kCtbHeaderSize, path, format("the header (%zu bytes)", kCtbHeaderSize));
  CtbIndex c;
  const uint32_t width = little_endian(head + kCtbResolutionAt), height = little_endian(head + kCtbResolutionAt + 4);
  if (width == 0 || height == 0 || uint64_t(width) * uint64_t(height) > kGooMaxPixels)
    throw Error(format("'%s' has images of %u x %u pixels, which is not within 1..%llu pixels", path.c_str(), width,
                       height, (unsigned long long)kGooMaxPixels));
  c.width = int(width);
  c.height = int(height);
  c.key = little_endian(head + kCtbKeyAt);
  const uint64_t table_at = little_endian(head + kCtbLayerTableAt), layers = little_endian(head + kCtbLayerCountAt);
  if (table_at < kCtbHeaderSize || table_at + layers * kCtbLayerDefSize > size)
    throw Error(format("'%s' is corrupt: its layer table (%llu layers of %zu bytes at byte %llu) does not lie within "
                       "the file's %llu bytes after the header",
                       path.c_str(), (unsigned long long)layers, kCtbLayerDefSize, (unsigned long long)table_at,
                       (unsigned long long)size));
  std::vector<uint8_t> table(size_t(layers) * kCtbLayerDefSize);
  read_at(fd, table_at, table.data(), table.size(), path, "the layer table");
  c.data_at.resize(size_t(layers));
  c.data_size.resize(size_t(layers));
  for (size_t k = 0; k < layers; ++k) {
    const uint8_t* d = table.data() + k * kCtbLayerDefSize;
    const uint64_t at = uint64_t(little_endian(d + kCtbPageAt)) << 32 | little_endian(d + kCtbDataAddressAt);
    const uint32_t n = little_endian(d + kCtbDataSizeAt);
    if (at > size || n > size - at)
      throw Error(format("'%s' is corrupt: layer %zu's image data (%u bytes at byte %llu) runs past the end of the "
                         "file (%llu bytes)",
                         path.c_str(), k, n, (unsigned long long)at, (unsigned long long)size));
    c.data_at[k] = at;
    c.data_size[k] = n;
  }
  return c;
}

void read_ctb_layer(int fd, const CtbIndex& index, size_t k, const std::string& name, std::vector<uint8_t>& bytes) {
  bytes.resize(index.data_size[k]);
  read_at(fd, index.data_at[k], bytes.data(), bytes.size(), name, "its image data");
}

void decode_ctb_layer(const uint8_t* data, size_t n, int width, int height, uint32_t key, size_t k,
                      const std::string& name, MaskImage& out) {
  const uint8_t* d = data;
  thread_local std::vector<uint8_t> plain;
  if (key != 0) {
    plain.assign(data, data + n);
    CtbKeyStream(key, uint32_t(k)).apply(plain.data(), n);
    d = plain.data();
  }
  const size_t pixels = size_t(width) * size_t(height);
  out.width = width;
  out.height = height;
  out.pixels.resize(pixels);
  uint8_t* px = out.pixels.data();
  size_t filled = 0, i = 0;
  const auto cut = [&] { return Error("'" + name + "' is corrupt: its last run length is cut off by the data's end"); };
  while (i < n) {
    const uint8_t b = d[i++];
    const unsigned code = b & 0x7F;
    uint64_t run = 1;
    if (b & kCtbRunFlag) {
      if (i >= n) throw cut();
      const uint8_t b0 = d[i++];
      // The length's first byte says how many more follow: 0xxxxxxx none, 10 one, 110 two, 1110 three.
      const unsigned more = (b0 & 0x80) == 0      ? 0
                            : (b0 & 0xC0) == 0x80 ? 1
                            : (b0 & 0xE0) == 0xC0 ? 2
                            : (b0 & 0xF0) == 0xE0 ? 3
                                                  : 4;
      if (more == 4)
        throw Error(format("'%s' is corrupt: a run length begins with the byte %02X, of no known form", name.c_str(),
                           unsigned(b0)));
      if (n - i < more) throw cut();
      run = b0 & (0x7Fu >> more);
      for (unsigned m = 0; m < more; ++m) run = run << 8 | d[i++];
    }
    if (run > pixels - filled)
      throw Error(format("'%s' is corrupt: its runs make more than the %d x %d pixels of the image", name.c_str(),
                         width, height));
    std::memset(px + filled, code == 0 ? 0 : int(2 * code + 1), size_t(run));
    filled += size_t(run);
  }
  if (filled != pixels)
    throw Error(
        format("'%s' is corrupt: its runs make %zu of the %zu pixels of the image", name.c_str(), filled, pixels));
}

}  // namespace slicereuse
