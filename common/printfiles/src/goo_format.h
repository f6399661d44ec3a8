#pragma once
// The layout of Elegoo's .goo print file (Elegoo's "Goo Format Spec V1.2", github.com/
// elegooofficial/GOO; docs/formats.md has every field), shared by its writer (goo_writer.h) and
// the mask stack reader (goo_stack.h). All numbers are big-endian.
//   file:   header (kGooHeaderSize bytes), then per layer a record, then kGooEnding
//   record: definition (kGooDefinitionSize bytes, ending in kGooDelimiter), data size (u32),
//           image data (that many bytes: kGooLayerMagic, run-length chunks, checksum),
//           kGooDelimiter
// Chunk byte 0: bits 7-6 the kind (kGooBlack, kGooGrey with its level in the next byte,
// kGooDiff, kGooWhite); for the three run kinds bits 5-4 say how many more bytes hold the
// run-length above its low 4 bits (bits 3-0): 0, 1, 2 or 3, most significant first. A diff
// chunk sets the level to the previous chunk's plus (bit 5 clear) or minus (bit 5 set) bits 3-0,
// for one pixel (bit 4 clear) or for the number of pixels in the next byte (bit 4 set).
// The checksum is the complement of the byte sum of the chunks (magic and checksum excluded).
#include <cstddef>
#include <cstdint>

namespace slicereuse {

inline constexpr uint8_t kGooMagic[8] = {0x07, 0x00, 0x00, 0x00, 0x44, 0x4C, 0x50, 0x00};
inline constexpr uint8_t kGooEnding[11] = {0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00, 0x44, 0x4C, 0x50, 0x00};
inline constexpr uint8_t kGooDelimiter[2] = {0x0D, 0x0A};
inline constexpr uint8_t kGooLayerMagic = 0x55;

inline constexpr int kGooSmallPreview = 116, kGooBigPreview = 290;  // square, RGB565
inline constexpr size_t kGooHeaderSize = 195477;
// Header fields the reader needs, by offset.
inline constexpr size_t kGooMagicAt = 4, kGooLayerCountAt = 195310, kGooResolutionAt = 195314,
                        kGooLayerContentAt = 195470;
inline constexpr size_t kGooDefinitionSize = 66;  // 16 numbers and the delimiter

enum GooChunk : uint8_t { kGooBlack = 0, kGooGrey = 1, kGooDiff = 2, kGooWhite = 3 };
inline constexpr uint32_t kGooMaxRun = 0xFFFFFFF;  // 28 bits: 4 in byte 0, 3 more bytes

}  // namespace slicereuse
