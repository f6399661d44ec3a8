#include "slicereuse/formats/slice_files.h"

#include <cerrno>
#include <cstring>
#include <memory>

#include <xxhash.h>

#include "slice_files_binary_layout.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"

namespace slicereuse {
namespace {

using detail::FileKind;

void write_file(const std::string& path, const Slices& s, FileFormat format, FileKind kind,
                const Progress& progress) {
  // Validate before creating anything: a bad structure must not cost a half-written temporary.
  try {
    validate_slices(s);
    if (kind == FileKind::Contours && !s.has_points())
      throw Error("the slices carry no contour points (xyz)");
    if (kind == FileKind::Encoding && !s.has_encoding())
      throw Error("the slices carry no encoding (face, edge, t)");
  } catch (const Error& e) {
    throw Error("cannot write " + std::string(detail::kind_noun(kind)) + " '" + path +
                "': " + e.what());
  }
  if (format == FileFormat::Binary)
    detail::write_binary(path, s, kind, progress);
  else
    detail::write_text(path, s, kind, progress);
}

Slices read_file(const std::string& path, FileKind kind, const Progress& progress) {
  const detail::InputFile f = detail::open_input_file(path);
  const uint64_t size = f.size();

  char head[sizeof detail::kBinaryMagic] = {};
  const size_t got = std::fread(head, 1, sizeof head, f.get());
  std::rewind(f.get());
  if (got == sizeof head && std::memcmp(head, detail::kBinaryMagic, sizeof head) == 0)
    return detail::read_binary(path, f.get(), size, kind, progress);

  Buffer<char> data(size);
  if (size && std::fread(data.data(), 1, size, f.get()) != size)
    throw Error("cannot read '" + path + "': " + std::strerror(errno));
  return detail::read_text(path, data, kind, progress);
}

}  // namespace

void write_contour_file(const std::string& path, const Slices& s, FileFormat format,
                        const Progress& progress) {
  write_file(path, s, format, FileKind::Contours, progress);
}

void write_encoding_file(const std::string& path, const Slices& s, FileFormat format,
                         const Progress& progress) {
  write_file(path, s, format, FileKind::Encoding, progress);
}

Slices read_contour_file(const std::string& path, const Progress& progress) {
  return read_file(path, FileKind::Contours, progress);
}

Slices read_encoding_file(const std::string& path, const Progress& progress) {
  return read_file(path, FileKind::Encoding, progress);
}

FileIdentity slice_file_identity(const std::string& path) {
  const detail::InputFile f = detail::open_input_file(path);
  FileIdentity id;
  id.size = f.size();
  unsigned char head[detail::kFixedHeaderBytes];
  const size_t got = std::fread(head, 1, sizeof head, f.get());
  if (got == sizeof head && std::memcmp(head, detail::kBinaryMagic, sizeof detail::kBinaryMagic) == 0) {
    const uint64_t at = detail::table_end(detail::get<uint32_t>(head + detail::kSectionCountAt));
    if (at + 8 <= id.size && fseeko(f.get(), off_t(at), SEEK_SET) == 0 &&
        std::fread(&id.checksum, 1, 8, f.get()) == 8)
      return id;
    throw Error("'" + path + "': truncated binary header");
  }
  // Text: hash everything (the stream was already read up to `got` bytes).
  std::unique_ptr<XXH3_state_t, XXH_errorcode (*)(XXH3_state_t*)> state(XXH3_createState(), XXH3_freeState);
  if (!state || XXH3_64bits_reset(state.get()) != XXH_OK) throw Error("out of memory hashing '" + path + "'");
  XXH3_64bits_update(state.get(), head, got);
  std::vector<unsigned char> piece(size_t(1) << 20);
  for (size_t n; (n = std::fread(piece.data(), 1, piece.size(), f.get())) > 0;)
    XXH3_64bits_update(state.get(), piece.data(), n);
  if (std::ferror(f.get())) throw Error("cannot read '" + path + "': " + std::strerror(errno));
  id.checksum = XXH3_64bits_digest(state.get());
  return id;
}

}  // namespace slicereuse
