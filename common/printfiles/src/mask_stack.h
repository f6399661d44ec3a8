#pragma once
// MaskStack: read access to a stack of mask images on disk, one per layer, either
//   - a folder of PNG files (export_masks writes layerNNNNN.png; unpacked .sl1 archives hold
//     <jobDir>NNNNN.png), only its top level is listed,
//   - a Prusa .sl1 archive (zip), entries <jobDir>NNNNN.png; thumbnail entries are ignored, or
//   - an Elegoo .goo file (a name ending in .goo, any case, or a file that starts as one does:
//     Phrozen's .prz is the same format): its layers in order (goo_stack.h), or
//   - an Anycubic Photon Workshop file (a name ending in one of photon_workshop_format.h's
//     extensions, any case, or a file that starts with "ANYCUBIC"): its LAYERDEF table's layers
//     (photon_workshop_stack.h), or
//   - a Chitubox .ctb file (a name ending in .ctb, any case, or a file that starts with its
//     magic): its layers in order, encrypted ones decrypted with the header's key (ctb_stack.h).
// read(k) gives layer k's bytes as stored (a PNG, or a print file's layer data), decode(k, ...)
// its pixels; reading is sequential (one file handle), decoding may run on any thread.
// In a folder or archive, layer k is the PNG whose name ends in the decimal number k right before ".png"; PNGs without
// such a number are ignored, and the numbers must run 0..L-1 with no gap and no repeat. Of a
// longer run of digits only the last max(5, digits of L-1) count, so a job name ending in
// digits ("member_001" + "00012.png") keeps its own.
// The constructor throws Error naming the path when it does not exist, is neither a folder nor
// a readable zip archive nor a print file it reads, holds no layer image, or misses or repeats a
// layer number; for a print file, when it is truncated or its records or tables are corrupt
// (goo_stack.h, ctb_stack.h, photon_workshop_stack.h).
// mask_layer_file_name gives the names export_masks writes: prefix, k with at least 5 digits
// (zero-padded, like PrusaSlicer's %.5d), ".png".
// lower_extension: what export and reading tell outputs apart by, the path's extension from its
// last dot, in lower case ("" when the last name has none).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ctb_stack.h"
#include "goo_stack.h"
#include "photon_workshop_stack.h"
#include "slicereuse/png/mask_png.h"

struct zip;

namespace slicereuse {

std::string mask_layer_file_name(const std::string& prefix, size_t k);
std::string lower_extension(const std::string& path);

class MaskStack {
 public:
  explicit MaskStack(const std::string& path);
  ~MaskStack();
  MaskStack(const MaskStack&) = delete;
  MaskStack& operator=(const MaskStack&) = delete;

  size_t layers() const { return names_.size(); }
  // The file path, or archive:entry, of layer k, as shown in messages.
  std::string layer_name(size_t k) const;
  // Reads the stored bytes of layer k into bytes (replaced); throws Error naming layer_name(k)
  // when it cannot be read (a zip entry failing its CRC included). One archive handle: not
  // thread-safe.
  void read(size_t k, std::vector<uint8_t>& bytes);
  // Layer k's pixels from what read(k) gave: PNG decoding (mask_png.h), or the print file's
  // run-length layer (.goo chunks after their checksum, .ctb runs, pw0Img runs); Error naming
  // layer_name(k).
  // Thread-safe.
  void decode(size_t k, const std::vector<uint8_t>& bytes, MaskImage& out) const;

 private:
  std::string path_;
  struct zip* zip_ = nullptr;
  // A print file's descriptor and kind, with the index of that kind.
  enum class PrintFile { None, Goo, Ctb, PhotonWorkshop } kind_ = PrintFile::None;
  int file_ = -1;
  GooIndex goo_index_;
  CtbIndex ctb_index_;
  PhotonWorkshopIndex pws_index_;
  std::vector<std::string> names_;   // file or entry name per layer
  std::vector<uint64_t> entry_;      // zip entry index per layer
};

}  // namespace slicereuse
