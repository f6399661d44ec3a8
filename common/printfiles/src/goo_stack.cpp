#include "goo_stack.h"

#include <algorithm>
#include <cstring>

#include "file_read_at.h"
#include "goo_format.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

uint32_t big_endian(const uint8_t* p, size_t n) {
  uint32_t v = 0;
  for (size_t i = 0; i < n; ++i) v = v << 8 | p[i];
  return v;
}

}  // namespace

GooIndex index_goo_file(int fd, const std::string& path) {
  const uint64_t file_size = slicereuse::file_size(fd, path);
  std::vector<uint8_t> head(kGooHeaderSize);
  read_at(fd, 0, head.data(), std::min<uint64_t>(file_size, 12), path, "the header");
  if (file_size < 12 || std::memcmp(head.data() + kGooMagicAt, kGooMagic, sizeof kGooMagic) != 0)
    throw Error("'" + path + "' is not a .goo file: bytes 4 to 11 are not its magic 07 00 00 00 44 4C 50 00");
  read_at(fd, 0, head.data(), kGooHeaderSize, path, format("the header (%zu bytes)", kGooHeaderSize));
  GooIndex g;
  const uint32_t layers = big_endian(head.data() + kGooLayerCountAt, 4);
  g.width = int(big_endian(head.data() + kGooResolutionAt, 2));
  g.height = int(big_endian(head.data() + kGooResolutionAt + 2, 2));
  if (g.width == 0 || g.height == 0 || uint64_t(g.width) * uint64_t(g.height) > kGooMaxPixels)
    throw Error(format("'%s' has images of %d x %d pixels, which is not within 1..%llu pixels", path.c_str(), g.width,
                       g.height, (unsigned long long)kGooMaxPixels));
  uint64_t at = big_endian(head.data() + kGooLayerContentAt, 4);
  if (at < kGooHeaderSize)
    throw Error(format("'%s' says its layers begin at byte %llu, inside its header", path.c_str(), (unsigned long long)at));
  // A record takes at least its definition, data size and delimiter: a header claiming more
  // layers than the file could hold is caught at the first missing one, not allocated for.
  const uint64_t record_min = kGooDefinitionSize + 4 + 2;
  g.data_at.reserve(std::min<uint64_t>(layers, file_size / record_min));
  g.data_size.reserve(g.data_at.capacity());
  uint8_t fixed[kGooDefinitionSize + 4];
  for (uint32_t k = 0; k < layers; ++k) {
    const std::string record = format("layer %u's record", k);
    read_at(fd, at, fixed, sizeof fixed, path, record);
    if (std::memcmp(fixed + kGooDefinitionSize - 2, kGooDelimiter, 2) != 0)
      throw Error(format("'%s' is corrupt: layer %u's definition does not end in 0D 0A", path.c_str(), k));
    const uint32_t size = big_endian(fixed + kGooDefinitionSize, 4);
    const uint64_t data = at + sizeof fixed;
    uint8_t delimiter[2];
    read_at(fd, data + size, delimiter, 2, path, record + format(" (%u bytes of image data)", size));
    if (std::memcmp(delimiter, kGooDelimiter, 2) != 0)
      throw Error(format("'%s' is corrupt: layer %u's image data (%u bytes) is not followed by 0D 0A", path.c_str(), k,
                         size));
    g.data_at.push_back(data);
    g.data_size.push_back(size);
    at = data + size + 2;
  }
  uint8_t ending[sizeof kGooEnding];
  read_at(fd, at, ending, sizeof ending, path, "the ending string after the last layer");
  if (std::memcmp(ending, kGooEnding, sizeof ending) != 0)
    throw Error(format("'%s' is corrupt: the %u layers are not followed by the ending string", path.c_str(), layers));
  if (at + sizeof ending != file_size)
    throw Error(format("'%s' is corrupt: %llu bytes follow the ending string", path.c_str(),
                       (unsigned long long)(file_size - at - sizeof ending)));
  return g;
}

void read_goo_layer(int fd, const GooIndex& index, size_t k, const std::string& name, std::vector<uint8_t>& bytes) {
  bytes.resize(index.data_size[k]);
  read_at(fd, index.data_at[k], bytes.data(), bytes.size(), name, "its image data");
}

void decode_goo_layer(const uint8_t* d, size_t n, int width, int height, const std::string& name, MaskImage& out) {
  if (n < 2 || d[0] != kGooLayerMagic)
    throw Error("'" + name + "' is corrupt: its image data does not begin with 0x55");
  const size_t end = n - 1;  // the checksum's place
  uint8_t sum = 0;
  for (size_t i = 1; i < end; ++i) sum = uint8_t(sum + d[i]);
  if (uint8_t(~sum) != d[end])
    throw Error(format("'%s' is corrupt: checksum mismatch (the data sums to checksum %02X, the file says %02X)",
                       name.c_str(), unsigned(uint8_t(~sum)), unsigned(d[end])));
  const size_t pixels = size_t(width) * size_t(height);
  out.width = width;
  out.height = height;
  out.pixels.resize(pixels);
  uint8_t* px = out.pixels.data();
  size_t filled = 0, i = 1;
  int level = -1;  // the previous chunk's level, none before the first
  const auto cut = [&] { return Error("'" + name + "' is corrupt: its last chunk is cut off by the checksum"); };
  while (i < end) {
    const uint8_t b0 = d[i++];
    const unsigned kind = b0 >> 6, bits = b0 >> 4 & 3, low = b0 & 0xF;
    uint64_t run = 0;
    if (kind == kGooDiff) {
      if (level < 0) throw Error("'" + name + "' is corrupt: it begins with a diff chunk, which has no level to change");
      level += (bits & 2) ? -int(low) : int(low);
      if (level < 0 || level > 255) throw Error("'" + name + "' is corrupt: a diff chunk leaves the levels 0..255");
      if (bits & 1) {
        if (i >= end) throw cut();
        run = d[i++];
      } else {
        run = 1;
      }
    } else {
      level = kind == kGooBlack ? 0 : 255;
      if (kind == kGooGrey) {
        if (i >= end) throw cut();
        level = d[i++];
      }
      if (end - i < bits) throw cut();
      for (unsigned b = 0; b < bits; ++b) run = run << 8 | d[i++];
      run = run << 4 | low;
    }
    if (run > pixels - filled)
      throw Error(format("'%s' is corrupt: its chunks make more than the %d x %d pixels of the image", name.c_str(), width,
                         height));
    std::memset(px + filled, level, size_t(run));
    filled += size_t(run);
  }
  if (filled != pixels)
    throw Error(format("'%s' is corrupt: its chunks make %zu of the %zu pixels of the image", name.c_str(), filled, pixels));
}

}  // namespace slicereuse
