#include "slicereuse/png/mask_png.h"

#include <png.h>
#include <zlib.h>

#include <array>
#include <cstring>

#include "slicereuse/png/deflate_runs.h"
#include "slicereuse/png/png_rows.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

// Bit 7 of 8 consecutive bytes, first byte in the most significant bit (PNG bit order): the
// multiplier moves byte i's bit to bit 63 - i without carries.
uint8_t pack8(const uint8_t* p) {
  uint64_t x;
  std::memcpy(&x, p, 8);
  x = (x >> 7) & 0x0101010101010101ULL;
  return uint8_t((x * 0x8040201008040201ULL) >> 56);
}

void pack_row(const uint8_t* src, int width, uint8_t* dst) {
  const size_t full = size_t(width) / 8;
  for (size_t i = 0; i < full; ++i) dst[i] = pack8(src + 8 * i);
  if (full * 8 < size_t(width)) {
    uint8_t tail = 0;
    for (size_t c = 8 * full; c < size_t(width); ++c) tail |= uint8_t((src[c] >> 7) << (7 - (c & 7)));
    dst[full] = tail;
  }
}

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

// Appends a PNG chunk: length, type, data, CRC of type and data.
void chunk(std::vector<uint8_t>& out, const char* type, const uint8_t* data, size_t n) {
  put32(out, uint32_t(n));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  if (n) out.insert(out.end(), data, data + n);
  put32(out, uint32_t(crc32(0, out.data() + start, uInt(n + 4))));
}

}  // namespace

namespace {

void check_size(int width, int height, int bits) {
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535 || (bits != 1 && bits != 8))
    throw Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + ", " +
                std::to_string(bits) + "-bit mask as PNG");
}

// A PNG file is written around its image data in place: png_begin writes the signature, IHDR
// (colour type 0: grey, 6: RGBA) and the IDAT chunk's head into out (replaced) and returns where
// the data goes; the deflater
// appends the zlib stream there; png_end fills in the IDAT length and CRC and adds IEND.
size_t png_begin(int width, int height, int bits, uint8_t colour_type, std::vector<uint8_t>& out) {
  static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  out.assign(signature, signature + 8);
  uint8_t header[13];
  for (int i = 0; i < 4; ++i) {
    header[i] = uint8_t(uint32_t(width) >> (24 - 8 * i));
    header[4 + i] = uint8_t(uint32_t(height) >> (24 - 8 * i));
  }
  // Deflate, filter set 0, no interlace.
  const uint8_t format[5] = {uint8_t(bits), colour_type, 0, 0, 0};
  std::memcpy(header + 8, format, sizeof format);
  chunk(out, "IHDR", header, sizeof header);
  put32(out, 0);  // IDAT length, filled in by png_end
  out.insert(out.end(), {'I', 'D', 'A', 'T'});
  return out.size();
}

void png_end(size_t data_begin, std::vector<uint8_t>& out) {
  const size_t n = out.size() - data_begin;
  for (int i = 0; i < 4; ++i) out[data_begin - 8 + size_t(i)] = uint8_t(uint32_t(n) >> (24 - 8 * i));
  put32(out, uint32_t(crc32(0, out.data() + data_begin - 4, uInt(n + 4))));
  chunk(out, "IEND", nullptr, 0);
}

// The calling thread's deflater, emptied: a deflater kept per thread allocates nothing per image
// once its buffer has grown, and a former call may have thrown half-way.
RunDeflater& thread_deflater() {
  thread_local RunDeflater deflater;
  deflater.reset();
  return deflater;
}

}  // namespace

void encode_mask_png(const uint8_t* pixels, int width, int height, int bits,
                     std::vector<uint8_t>& out) {
  check_size(width, height, bits);
  // Rows without a filter (type 0): on masks, filters cost time and gain nothing.
  thread_local std::vector<uint8_t> row;
  RunDeflater& deflater = thread_deflater();
  row.resize(1 + (size_t(width) + 7) / 8);
  row[0] = 0;
  const size_t data_begin = png_begin(width, height, bits, 0, out);
  for (int r = 0; r < height; ++r) {
    const uint8_t* src = pixels + size_t(r) * size_t(width);
    if (bits == 1) {
      pack_row(src, width, row.data() + 1);
      deflater.add(row.data(), row.size());
    } else {
      deflater.add(row.data(), 1);
      deflater.add(src, size_t(width));
    }
  }
  deflater.finish(out);
  png_end(data_begin, out);
}

void encode_rgba_png(const uint8_t* rgba, int width, int height, std::vector<uint8_t>& out) {
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " RGBA picture as PNG");
  thread_local std::vector<uint8_t> row;
  RunDeflater& deflater = thread_deflater();
  const size_t bytes = 4 * size_t(width);
  row.resize(1 + bytes);
  row[0] = 1;  // Sub: each byte less the same channel's of the pixel before
  const size_t data_begin = png_begin(width, height, 8, 6, out);
  for (int r = 0; r < height; ++r) {
    const uint8_t* src = rgba + size_t(r) * bytes;
    std::memcpy(row.data() + 1, src, 4);
    for (size_t i = 4; i < bytes; ++i) row[1 + i] = uint8_t(src[i] - src[i - 4]);
    deflater.add(row.data(), row.size());
  }
  deflater.finish(out);
  png_end(data_begin, out);
}

PngRows::PngRows(int width, int height, std::vector<uint8_t>& out)
    : width_(width), deflater_(thread_deflater()), runs_(deflater_.runs()), out_(out) {
  check_size(width, height, 8);
  data_begin_ = png_begin(width, height, 8, 0, out);
}

void PngRows::finish() {
  runs_.end();
  deflater_.finish(out_);
  png_end(data_begin_, out_);
}

void encode_mask_png(const MaskRuns& runs, std::vector<uint8_t>& out) {
  check_size(runs.width, runs.height, 8);
  if (runs.row_begin.size() != size_t(runs.height) + 1 || runs.columns.size() != 2 * size_t(runs.row_begin.back()) ||
      runs.levels.size() != size_t(runs.row_begin.back()))
    throw Error("cannot encode mask runs: their row index does not match the image height or the runs");
  PngRows png(runs.width, runs.height, out);
  for (int r = 0; r < runs.height; ++r)
    png.row([&](auto&& pixels) {
      size_t at = 0;
      for (uint32_t i = runs.row_begin[size_t(r)]; i < runs.row_begin[size_t(r) + 1]; ++i) {
        const size_t a = runs.columns[2 * size_t(i)], b = runs.columns[2 * size_t(i) + 1];
        if (a < at || b < a || b > size_t(runs.width))
          throw Error("cannot encode mask runs: row " + std::to_string(r) + " has runs out of order or outside the image");
        pixels(0, a - at);
        pixels(runs.levels[i], b - a);
        at = b;
      }
      pixels(0, size_t(runs.width) - at);
    });
  png.finish();
}

namespace {

// Any PNG, through libpng's simplified reader.
void decode_any(const uint8_t* data, size_t size, const std::string& name, MaskImage& out) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, data, size))
    throw Error("'" + name + "' is not a readable PNG image: " + image.message);
  if (image.width == 0 || image.height == 0 || image.width > (1u << 16) || image.height > (1u << 16)) {
    png_image_free(&image);
    throw Error("'" + name + "' has an unusable size " + std::to_string(image.width) + "x" +
                std::to_string(image.height));
  }
  // The first channel as 8-bit grey, whatever the file's depth; no gamma or colour conversion.
  image.format = PNG_FORMAT_GRAY;
  out.width = int(image.width);
  out.height = int(image.height);
  out.pixels.resize(size_t(image.width) * size_t(image.height));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr))
    throw Error("'" + name + "' is a corrupt PNG image: " + image.message);
}

struct MemoryReader {
  const uint8_t* data;
  size_t size, at;
};

void read_from_memory(png_structp png, png_bytep to, png_size_t n) {
  auto* r = static_cast<MemoryReader*>(png_get_io_ptr(png));
  if (n > r->size - r->at) png_error(png, "truncated file");
  std::memcpy(to, r->data + r->at, n);
  r->at += n;
}

// libpng reports errors by longjmp; the message is kept for the Error thrown afterwards.
struct ReadError {
  char message[256] = "unknown error";
};

void on_read_error(png_structp png, png_const_charp message) {
  auto* e = static_cast<ReadError*>(png_get_error_ptr(png));
  std::strncpy(e->message, message, sizeof e->message - 1);
  png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

// Each byte of a 1-bit row as its 8 pixels, 0 or 255.
const uint64_t* bit_expansion() {
  static const auto table = [] {
    std::array<uint64_t, 256> t{};
    for (unsigned b = 0; b < 256; ++b)
      for (unsigned i = 0; i < 8; ++i)
        if (b & (0x80u >> i)) t[b] |= uint64_t(0xff) << (8 * i);
    return t;
  }();
  return table.data();
}

// Decodes a 1-bit grey, non-interlaced PNG (what export_masks writes into folders) by expanding
// packed rows through a table, several times faster than libpng's own expansion. Returns false,
// with nothing decoded, for any other kind of PNG. Free of C++ objects with destructors between
// setjmp and the libpng calls, which longjmp would skip.
bool decode_one_bit(png_structp png, png_infop info, MemoryReader& reader, MaskImage& out,
                    std::vector<uint8_t>& row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &reader, read_from_memory);
  png_read_info(png, info);
  if (png_get_bit_depth(png, info) != 1 || png_get_color_type(png, info) != PNG_COLOR_TYPE_GRAY ||
      png_get_interlace_type(png, info) != PNG_INTERLACE_NONE)
    return false;
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  if (w == 0 || h == 0 || w > (1u << 16) || h > (1u << 16)) png_error(png, "unusable image size");
  out.width = int(w);
  out.height = int(h);
  out.pixels.resize(size_t(w) * size_t(h) + 8);  // room for the last row's whole 8-pixel word
  row.resize((w + 7) / 8);
  const uint64_t* expand = bit_expansion();
  for (png_uint_32 r = 0; r < h; ++r) {
    png_read_row(png, row.data(), nullptr);
    uint8_t* dst = out.pixels.data() + size_t(r) * w;
    for (size_t i = 0; i < row.size(); ++i) std::memcpy(dst + 8 * i, &expand[row[i]], 8);
  }
  out.pixels.resize(size_t(w) * size_t(h));
  return true;
}

}  // namespace

void decode_mask_png(const uint8_t* data, size_t size, const std::string& name, MaskImage& out) {
  ReadError error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_read_error, ignore_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    throw Error("out of memory reading '" + name + "'");
  }
  MemoryReader reader{data, size, 0};
  thread_local std::vector<uint8_t> row;
  const bool done = decode_one_bit(png, info, reader, out, row);
  png_destroy_read_struct(&png, &info, nullptr);
  // Anything else, and any error (reported with libpng's full checks), takes the general path.
  if (!done) decode_any(data, size, name, out);
}

void draw_mask_runs(const MaskRuns& runs, uint8_t* pixels) {
  const size_t w = size_t(runs.width);
  std::memset(pixels, 0, w * size_t(runs.height));
  for (int r = 0; r < runs.height; ++r)
    for (uint32_t i = runs.row_begin[size_t(r)]; i < runs.row_begin[size_t(r) + 1]; ++i) {
      const uint16_t a = runs.columns[2 * size_t(i)], b = runs.columns[2 * size_t(i) + 1];
      std::memset(pixels + size_t(r) * w + a, runs.levels[i], b - a);
    }
}

MaskRuns mask_runs_of(const MaskImage& image) {
  MaskRuns r;
  r.width = image.width;
  r.height = image.height;
  r.row_begin.reserve(size_t(image.height) + 1);
  r.row_begin.push_back(0);
  const int w = image.width;
  for (int y = 0; y < image.height; ++y) {
    const uint8_t* row = image.pixels.data() + size_t(y) * size_t(w);
    int x = 0;
    while (x < w) {
      // Whole words of unlit pixels are skipped at once.
      uint64_t word;
      if (x + 8 <= w && (std::memcpy(&word, row + x, 8), word == 0)) {
        x += 8;
        continue;
      }
      const uint8_t level = row[x];
      if (level == 0) {
        ++x;
        continue;
      }
      const int lo = x;
      while (x < w && row[x] == level) ++x;
      r.columns.push_back(uint16_t(lo));
      r.columns.push_back(uint16_t(x));
      r.levels.push_back(level);
    }
    r.row_begin.push_back(uint32_t(r.levels.size()));
  }
  return r;
}

}  // namespace slicereuse
