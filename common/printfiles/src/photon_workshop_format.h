#pragma once
// The layout of Anycubic's Photon Workshop print files (.pwmx, .pwmb, .pwma, .pm4n, .pm5, .pm5s:
// one format in versions 516, 517 and 518, as UVtools' AnycubicFile reads and writes them;
// docs/formats.md has every field), shared by the writer (photon_workshop_writer.h) and the mask
// stack reader (photon_workshop_stack.h). All numbers are little-endian.
//   file:   the file mark (kPwsMark, version, number of tables, then the tables' addresses),
//           then the tables, each but two beginning with a 12-byte name and a u32 length:
//           HEADER, PREVIEW, the grey colour table (no name), LAYERDEF, EXTRA, MACHINE,
//           SOFTWARE (517+, no name), MODEL (517+), SUBIMGS and PREVIEW2 (518); then the layers'
//           image data, where LAYERDEF's entries point.
//   pw0Img: the image's pixels row after row as one stream of runs; byte 0's high nibble is the
//           code c (the level 17c), its low nibble the run-length (grey codes 1..14), or for codes
//           0x0 and 0xF the high 4 bits of a 12-bit run-length whose low 8 bits are byte 1.
#include <cstddef>
#include <cstdint>
#include <string>

namespace slicereuse {

inline constexpr char kPwsMark[] = "ANYCUBIC";
inline constexpr size_t kPwsNameSize = 12;  // the file mark's and each named table's name field
inline constexpr size_t kPwsTableBase = kPwsNameSize + 4;  // name and length

// File mark fields, by offset (the same in every version): what the reader needs.
inline constexpr size_t kPwsVersionAt = 12, kPwsHeaderAddressAt = 20, kPwsLayerDefAddressAt = 36;
// The HEADER table's resolution, from its start (after the name and length: 11 numbers of 4 bytes).
inline constexpr size_t kPwsHeaderResolutionAt = kPwsTableBase + 44;
inline constexpr size_t kPwsLayerDefSize = 32;     // one LAYERDEF entry: data address and length
inline constexpr size_t kPwsLayerDefLitAt = 24;    // (u32 each), then 4 floats, lit pixels (u32), 0
inline constexpr size_t kPwsSubLayerDefSize = 44;  // one SUBIMGS entry (version 518)

inline constexpr int kPwsPreviewWidth = 224, kPwsPreviewHeight = 168;
inline constexpr int kPwsPreview2Width = 320, kPwsPreview2Height = 190;  // version 518

inline constexpr unsigned kPwsMaxGreyRun = 0xF, kPwsMaxRun = 0xFFF;  // grey codes; codes 0x0 and 0xF

// What an extension's file is: the printer it is for, the versions of the format it holds
// (UVtools' list, of those slicereuse writes: 516, 517, 518), the one written by default (the
// newest), and the machine name written when the profile has none.
struct PwsFileKind {
  const char* extension;
  const char* machine;
  unsigned versions[3];  // ascending, 0 after the last
  unsigned newest() const { return versions[2] ? versions[2] : versions[1] ? versions[1] : versions[0]; }
  bool holds(unsigned version) const {
    return version != 0 && (versions[0] == version || versions[1] == version || versions[2] == version);
  }
};

inline constexpr PwsFileKind kPwsFileKinds[] = {
    {".pwmx", "Photon Mono X", {516, 0, 0}},
    {".pwma", "Photon Mono 4K", {516, 0, 0}},
    {".pwmb", "Photon Mono X 6K / M3 Plus", {516, 517, 0}},
    {".pm5", "Photon Mono M5", {517, 0, 0}},
    {".pm5s", "Photon Mono M5s", {518, 0, 0}},
    {".pm4n", "Photon Mono 4", {516, 517, 518}},
};

// The kind of file an extension (lower case, with its dot) names, or nullptr.
inline const PwsFileKind* photon_workshop_kind(const std::string& extension) {
  for (const PwsFileKind& k : kPwsFileKinds)
    if (extension == k.extension) return &k;
  return nullptr;
}

}  // namespace slicereuse
