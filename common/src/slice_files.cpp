#include "slicereuse/slice_files.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <memory>

#include "slice_files_binary_layout.h"
#include "slicereuse/error.h"

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

struct FileCloser {
  void operator()(FILE* f) const { std::fclose(f); }
};

Slices read_file(const std::string& path, FileKind kind, const Progress& progress) {
  std::unique_ptr<FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  struct stat st;
  if (::fstat(::fileno(f.get()), &st) != 0 || !S_ISREG(st.st_mode))
    throw Error("cannot read '" + path + "': not a regular file");
  const uint64_t size = uint64_t(st.st_size);

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

}  // namespace slicereuse
