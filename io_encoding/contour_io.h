#pragma once
// What the io_encoding plugin does, once for both MeshLab generations: the formats it registers
// and opening / saving a contour layer (contour_layer.h) from / to a file with the core's
// readers and writers. The shims (shim_2020.cpp, shim_2025.cpp) only adapt this to MeshLab's
// IO plugin interfaces. Header-only: it needs the generation's vcg mesh type.
//
// Open: .ctr / .srb (slicereuse contour file, text or binary) and .cli (Common Layer Interface,
// ASCII or binary) become a contour layer. Beside a contour file B.ctr or B.srb, the encoding
// file of its own format (B.enc / B_enc.srb, encoding_file_beside), else of the other, is read
// as its encoding (it must describe the same layers, contours and points) and becomes the
// per-vertex face and area coordinates.
// Save: .ctr / .srb write the contour file (text / binary) and, when the layer carries an
// encoding, B.enc / B_enc.srb beside it, staged together (both appear or neither); .cli writes
// CLI (ASCII, or binary when the save parameter "binary" is set); .slc writes SLC (open contours
// are left out and counted).
// Every function throws Error with a message naming the file and the problem.
#include <sys/stat.h>

#include <cctype>
#include <string>
#include <vector>

#include "contour_layer.h"
#include "slicereuse/formats/cli_file.h"
#include "slicereuse/formats/file_names.h"
#include "slicereuse/formats/slc_file.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/progress.h"

namespace slicereuse::plugin {

struct IoFormat {
  const char* extension;  // upper case, as MeshLab lists them
  const char* description;
  bool opens;
};

inline const std::vector<IoFormat>& io_formats() {
  static const std::vector<IoFormat> formats = {
      {"CTR", "slicereuse contours, text", true},
      {"SRB", "slicereuse contours, binary", true},
      {"CLI", "Common Layer Interface", true},
      {"SLC", "3D Systems SLC contours", false},
  };
  return formats;
}

// The save parameter of .cli files.
inline const char* const kCliBinaryParameter = "binary";

inline std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

inline bool is_file(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The encoding file that belongs to the contour file at path, or "" if there is none: B.enc or
// B_enc.srb (encoding_file_beside), the one that saving in this format writes (B.enc for .ctr,
// B_enc.srb for .srb) first.
inline std::string encoding_beside(const std::string& path, FileFormat format) {
  const FileFormat other = format == FileFormat::Binary ? FileFormat::Text : FileFormat::Binary;
  for (const std::string& candidate : {encoding_file_beside(path, format), encoding_file_beside(path, other)})
    if (candidate != path && is_file(candidate)) return candidate;
  return "";
}

// Puts the encoding of e onto the contours of s; both must describe the same slices.
inline void attach_encoding(Slices& s, Slices&& e, const std::string& encoding_path) {
  if (e.layer_begin != s.layer_begin || e.contour_begin != s.contour_begin || e.contour_open != s.contour_open)
    throw Error("encoding file '" + encoding_path + "' does not match the contours: it has " +
                std::to_string(e.layers()) + " layers, " + std::to_string(e.contours()) + " contours and " +
                std::to_string(e.points()) + " points, the contour file " + std::to_string(s.layers()) + ", " +
                std::to_string(s.contours()) + " and " + std::to_string(s.points()));
  s.fingerprint = e.fingerprint;
  s.face = std::move(e.face);
  s.edge = std::move(e.edge);
  s.t = std::move(e.t);
}

// Fills m from the file; returns a line for the log.
template <class MeshT>
std::string open_contour_file(const std::string& format, const std::string& path, MeshT& m, const Progress& progress) {
  const std::string ext = upper(format);
  Slices s;
  std::string encoding;
  if (ext == "CLI") {
    s = read_cli_file(path, progress);
  } else if (ext == "CTR" || ext == "SRB") {
    s = read_contour_file(path, progress);
    encoding = encoding_beside(path, ext == "SRB" ? FileFormat::Binary : FileFormat::Text);
    if (!encoding.empty()) attach_encoding(s, read_encoding_file(encoding), encoding);
  } else {
    throw Error("io_encoding cannot open ." + format + " files");
  }
  const std::string counts = std::to_string(s.layers()) + " layers, " + std::to_string(s.contours()) +
                             " contours, " + std::to_string(s.points()) + " points";
  fill_contour_layer(m, std::move(s));
  return "Opened " + path + ": " + counts +
         (encoding.empty() ? std::string(", no encoding") : ", encoding from " + encoding);
}

// Writes the contour layer m; returns a line for the log.
template <class MeshT>
std::string save_contour_layer(const std::string& format, const std::string& path, MeshT& m, bool binary_cli,
                               const Progress& progress) {
  const std::string ext = upper(format);
  const Slices s = slices_of_contour_layer(m);
  std::string also;
  if (ext == "CTR" || ext == "SRB") {
    const FileFormat f = ext == "SRB" ? FileFormat::Binary : FileFormat::Text;
    // Staged together (atomic_file.h): the contour file and its encoding appear both or neither.
    // Both names are reserved first, so a target that cannot be written stops the save early.
    StagedOutputs outputs;
    const std::string contours = outputs.file(path);
    const std::string encoding = s.has_encoding() ? encoding_file_beside(path, f) : "";
    const std::string encoding_staged = encoding.empty() ? "" : outputs.file(encoding);
    write_contour_file(contours, s, f, progress);
    if (!encoding.empty()) {
      write_encoding_file(encoding_staged, s, f);
      also = ", encoding to " + encoding;
    }
    outputs.commit();
  } else if (ext == "CLI") {
    write_cli_file(path, s, binary_cli ? CliEncoding::Binary : CliEncoding::Ascii, progress);
    also = binary_cli ? " (binary)" : " (ASCII)";
  } else if (ext == "SLC") {
    const SlcExportStats st = write_slc_file(path, s, progress);
    also = ", " + std::to_string(st.boundaries) + " boundaries, " + std::to_string(st.skipped_open_contours) +
           " open contours left out (SLC has closed boundaries only)";
  } else {
    throw Error("io_encoding cannot save ." + format + " files");
  }
  return "Saved " + path + ": " + std::to_string(s.layers()) + " layers, " + std::to_string(s.contours()) +
         " contours, " + std::to_string(s.points()) + " points" + also;
}

}  // namespace slicereuse::plugin
