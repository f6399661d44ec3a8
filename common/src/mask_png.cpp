#include "slicereuse/mask_png.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <zlib.h>

#include <cstring>

#include "slicereuse/error.h"

namespace slicereuse {
namespace {

void put32(uint8_t* p, uint32_t v) {
  p[0] = uint8_t(v >> 24);
  p[1] = uint8_t(v >> 16);
  p[2] = uint8_t(v >> 8);
  p[3] = uint8_t(v);
}

// Bit 7 of 8 consecutive bytes, first byte in the most significant bit (PNG bit order): the
// multiplier moves byte i's bit to bit 63 - i without carries.
uint8_t pack8(const uint8_t* p) {
  uint64_t x;
  std::memcpy(&x, p, 8);
  x = (x >> 7) & 0x0101010101010101ULL;
  return uint8_t((x * 0x8040201008040201ULL) >> 56);
}

// One deflate stream per thread, reset per image instead of reallocated.
struct Deflater {
  z_stream z{};
  bool ready = false;
  ~Deflater() {
    if (ready) deflateEnd(&z);
  }
  void reset() {
    if (!ready) {
      if (deflateInit2(&z, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK)
        throw Error("cannot start zlib compression for a mask PNG");
      ready = true;
    } else {
      deflateReset(&z);
    }
  }
};

void encode_1bit(const uint8_t* pixels, int width, int height, std::vector<uint8_t>& out) {
  const size_t row_bytes = (size_t(width) + 7) / 8, full = size_t(width) / 8;
  thread_local std::vector<uint8_t> raw;
  raw.resize((row_bytes + 1) * size_t(height));
  for (size_t r = 0; r < size_t(height); ++r) {
    const uint8_t* src = pixels + r * size_t(width);
    uint8_t* dst = raw.data() + r * (row_bytes + 1);
    *dst++ = 0;  // filter type None
    for (size_t i = 0; i < full; ++i) dst[i] = pack8(src + 8 * i);
    if (full < row_bytes) {
      uint8_t tail = 0;
      for (size_t c = 8 * full; c < size_t(width); ++c) tail |= uint8_t((src[c] >> 7) << (7 - (c & 7)));
      dst[full] = tail;
    }
  }
  thread_local Deflater deflater;
  deflater.reset();
  z_stream& z = deflater.z;
  static const uint8_t head[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13,
                                 'I', 'H', 'D', 'R'};
  constexpr size_t IDAT = sizeof head + 13 + 4;  // offset of the IDAT chunk
  out.resize(IDAT + 8 + deflateBound(&z, uLong(raw.size())) + 4 + 12);
  std::memcpy(out.data(), head, sizeof head);
  uint8_t* ihdr = out.data() + 12;
  put32(ihdr + 4, uint32_t(width));
  put32(ihdr + 8, uint32_t(height));
  const uint8_t format[] = {1, 0, 0, 0, 0};  // 1 bit, grey, deflate, filter set 0, no interlace
  std::memcpy(ihdr + 12, format, sizeof format);
  put32(ihdr + 17, uint32_t(crc32(0, ihdr, 17)));
  std::memcpy(out.data() + IDAT + 4, "IDAT", 4);
  z.next_in = raw.data();
  z.avail_in = uInt(raw.size());
  z.next_out = out.data() + IDAT + 8;
  z.avail_out = uInt(out.size() - IDAT - 8);
  if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw Error("zlib failed to compress a mask PNG");
  const size_t n = z.total_out;
  put32(out.data() + IDAT, uint32_t(n));
  put32(out.data() + IDAT + 8 + n, uint32_t(crc32(0, out.data() + IDAT + 4, uInt(n + 4))));
  static const uint8_t iend[] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  std::memcpy(out.data() + IDAT + 12 + n, iend, sizeof iend);
  out.resize(IDAT + 12 + n + sizeof iend);
}

}  // namespace

void encode_mask_png(const uint8_t* pixels, int width, int height, int bits,
                     std::vector<uint8_t>& out) {
  if (width <= 0 || height <= 0 || (bits != 1 && bits != 8))
    throw Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + ", " +
                std::to_string(bits) + "-bit mask as PNG");
  if (bits == 1) return encode_1bit(pixels, width, height, out);
  out.clear();
  OIIO::Filesystem::IOVecOutput sink(out);
  OIIO::Filesystem::IOProxy* proxy = &sink;
  OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  // Measured on 1024x768 masks: adaptive filtering costs 4x the time of no filter (PNG_FILTER_NONE
  // = 8) for nothing on black/white images; Z_RLE gives the smallest files at level 1's speed.
  spec.attribute("png:filter", 8);
  spec.attribute("png:compressionLevel", 1);
  spec.attribute("compression", "rle");
  auto png = OIIO::ImageOutput::create("png");
  if (!png) throw Error("OpenImageIO has no PNG writer: " + OIIO::geterror());
  png->threads(1);  // callers already run one image per core
  if (!png->open("mask.png", spec) || !png->write_image(OIIO::TypeDesc::UINT8, pixels) ||
      !png->close())
    throw Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) +
                " mask as PNG: " + png->geterror());
}

void decode_mask_png(const uint8_t* data, size_t size, const std::string& name, MaskImage& out) {
  OIIO::Filesystem::IOMemReader source(data, size);
  OIIO::Filesystem::IOProxy* proxy = &source;
  OIIO::ImageSpec config;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto png = OIIO::ImageInput::create("png");
  if (!png) throw Error("OpenImageIO has no PNG reader: " + OIIO::geterror());
  png->threads(1);
  OIIO::ImageSpec spec;
  if (!png->open("mask.png", spec, config))
    throw Error("'" + name + "' is not a readable PNG image: " + png->geterror());
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1)
    throw Error("'" + name + "' has an unusable size " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height));
  out.width = spec.width;
  out.height = spec.height;
  out.pixels.resize(size_t(spec.width) * size_t(spec.height));
  if (!png->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, out.pixels.data()))
    throw Error("'" + name + "' is a corrupt PNG image: " + png->geterror());
  png->close();
}

}  // namespace slicereuse
