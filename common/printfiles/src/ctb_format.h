#pragma once
// The layout of Chitubox's .ctb print file, versions 3 and 4, unencrypted layers (as cbiffle/
// catibo's doc/cbddlp-ctb.adoc documents it and UVtools' ChituboxFile reads it; docs/formats.md
// has every field), shared by its writer (ctb_writer.h) and the mask stack reader (ctb_stack.h).
// All numbers are little-endian; sections point at each other by file offset. As written:
//   header (kCtbHeaderSize), large preview (kCtbPreviewHeaderSize, then its data), small preview,
//   print parameters, slicer info and the machine name, [v4: disclaimer, v4 print parameters],
//   layer table (kCtbLayerDefSize per layer), then per layer [v3+: its extended definition,
//   kCtbLayerDefExSize] and its image data.
// Image data: runs of 7-bit codes c (a pixel's level is 0 for c = 0, 2c + 1 otherwise): a byte
// c alone is one pixel; c | kCtbRunFlag is followed by the run length in 1 to 4 bytes, most
// significant first: 0xxxxxxx (7 bits), 10xxxxxx + 1 byte (14), 110xxxxx + 2 (21), 1110xxxx + 3
// (28). Runs go on across row ends. With a non-zero key in the header, layer k's data is XORed
// with the key stream of ctb_key_stream (its bytes little-endian words).
// Previews: RGB565 with the green's lowest bit (kCtbPreviewRunFlag) marking a run, whose length
// less one follows as 0x3000 | n (12 bits), in little-endian 16-bit words.
#include <cstddef>
#include <cstdint>

namespace slicereuse {

// Versions 2 and 3 begin with kCtbMagic, version 4 with kCtbMagicV4 (as Chitubox writes them; the
// layouts differ only as the version says).
inline constexpr uint32_t kCtbMagic = 0x12FD0086;
inline constexpr uint32_t kCtbMagicV4 = 0x12FD0106;
inline constexpr uint32_t kCtbEncryptedMagic = 0x12FD0107;  // Chitu's closed scheme: not written nor read
inline constexpr uint32_t kCbddlpMagic = 0x12FD0019;        // the 1-bit sibling: not read

inline constexpr size_t kCtbHeaderSize = 112;
// Header fields the reader needs, by offset.
inline constexpr size_t kCtbVersionAt = 4, kCtbResolutionAt = 52, kCtbLayerTableAt = 64, kCtbLayerCountAt = 68,
                        kCtbKeyAt = 100;

inline constexpr size_t kCtbPreviewHeaderSize = 32;
inline constexpr int kCtbLargePreviewWidth = 400, kCtbLargePreviewHeight = 300;
inline constexpr int kCtbSmallPreviewWidth = 200, kCtbSmallPreviewHeight = 125;
inline constexpr uint16_t kCtbPreviewRunFlag = 0x20;
inline constexpr unsigned kCtbPreviewMaxRun = 0xFFF;  // pixels per run word, as Chitubox limits it

inline constexpr size_t kCtbPrintParametersSize = 60;
inline constexpr size_t kCtbSlicerInfoSize = 76;  // without the machine name that follows it
inline constexpr char kCtbDisclaimer[] =
    "Layout and record format for the ctb and cbddlp file types are the copyrighted programs or codes of CBD "
    "Technology (China) Inc..The Customer or User shall not in any manner reproduce, distribute, modify, decompile, "
    "disassemble, decrypt, extract, reverse engineer, lease, assign, or sublicense the said programs or codes.";
inline constexpr size_t kCtbDisclaimerSize = sizeof kCtbDisclaimer - 1;  // 320, stored without a terminator
inline constexpr size_t kCtbPrintParametersV4Size = 464;                 // 84 bytes of fields, 380 reserved

inline constexpr size_t kCtbLayerDefSize = 36;
inline constexpr size_t kCtbLayerDefExSize = 84;  // a copy of the layer's definition, then 48 bytes
// A layer definition's data address is within a page of 4 GB; its page number is the next field.
inline constexpr size_t kCtbDataAddressAt = 12, kCtbDataSizeAt = 16, kCtbPageAt = 20;

inline constexpr uint8_t kCtbRunFlag = 0x80;
inline constexpr uint32_t kCtbMaxRun = 0xFFFFFFF;  // 28 bits

// The 32-bit key stream that a key and layer k (the IV) make; encryption and decryption alike
// XOR the data with it, byte i with byte i % 4 (least significant first) of word i / 4.
struct CtbKeyStream {
  uint32_t step, word;
  CtbKeyStream(uint32_t key, uint32_t layer)
      : step(key * 0x2D83CDACu + 0xD8A83423u), word((layer * 0x1E1530CDu + 0xEC3D47CDu) * step) {}
  // XORs n bytes in place, the stream starting at byte 0 of its first word.
  void apply(uint8_t* data, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      data[i] ^= uint8_t(word >> (8 * (i & 3)));
      if ((i & 3) == 3) word += step;
    }
  }
};

}  // namespace slicereuse
