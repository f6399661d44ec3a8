// PLY reading and writing for test meshes (see shapes.h). The whole file is read into memory
// and parsed with a cursor: no iostreams, so a million faces take milliseconds.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "shapes.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::test {

namespace {

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

struct Property {
  std::string name;
  bool list = false;
  Type count_type = Type::U8;  // lists only
  Type type = Type::F32;       // scalar type, or the list's item type
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> props;
};

size_t type_size(Type t) {
  switch (t) {
    case Type::I8: case Type::U8: return 1;
    case Type::I16: case Type::U16: return 2;
    case Type::I32: case Type::U32: case Type::F32: return 4;
    case Type::F64: return 8;
  }
  return 0;
}

bool parse_type(const std::string& s, Type& t) {
  static const struct { const char* name; Type type; } names[] = {
      {"char", Type::I8},    {"int8", Type::I8},     {"uchar", Type::U8},    {"uint8", Type::U8},
      {"short", Type::I16},  {"int16", Type::I16},   {"ushort", Type::U16},  {"uint16", Type::U16},
      {"int", Type::I32},    {"int32", Type::I32},   {"uint", Type::U32},    {"uint32", Type::U32},
      {"float", Type::F32},  {"float32", Type::F32}, {"double", Type::F64},  {"float64", Type::F64}};
  for (const auto& n : names)
    if (s == n.name) { t = n.type; return true; }
  return false;
}

// Reads the data section, either binary little-endian or ascii, one value at a time.
class Cursor {
 public:
  Cursor(const std::string& path, const char* p, const char* end, bool ascii)
      : path_(path), p_(p), end_(end), ascii_(ascii) {}

  double number(Type t) {
    if (ascii_) return ascii_number();
    const size_t n = type_size(t);
    if (size_t(end_ - p_) < n) fail("file is truncated");
    double v = 0;
    switch (t) {
      case Type::I8: { int8_t x; std::memcpy(&x, p_, 1); v = x; break; }
      case Type::U8: { uint8_t x; std::memcpy(&x, p_, 1); v = x; break; }
      case Type::I16: { int16_t x; std::memcpy(&x, p_, 2); v = x; break; }
      case Type::U16: { uint16_t x; std::memcpy(&x, p_, 2); v = x; break; }
      case Type::I32: { int32_t x; std::memcpy(&x, p_, 4); v = x; break; }
      case Type::U32: { uint32_t x; std::memcpy(&x, p_, 4); v = x; break; }
      case Type::F32: { float x; std::memcpy(&x, p_, 4); v = x; break; }
      case Type::F64: { std::memcpy(&v, p_, 8); break; }
    }
    p_ += n;
    return v;
  }

  void set_line(size_t line) { line_ = line; }

  [[noreturn]] void fail(const std::string& what) const {
    std::string where = ascii_ ? " (line " + std::to_string(line_) + ")" : "";
    throw Error(path_ + ": " + what + where);
  }

 private:
  double ascii_number() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
    if (p_ == end_) fail("file is truncated");
    double v = 0;
    const char* start = p_ + (*p_ == '+' ? 1 : 0);
    auto [next, ec] = std::from_chars(start, end_, v);
    if (ec != std::errc()) fail("expected a number");
    p_ = next;
    return v;
  }

  const std::string& path_;
  const char* p_;
  const char* end_;
  bool ascii_;
  size_t line_ = 0;
};

std::vector<char> slurp(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for reading: " + std::strerror(errno));
  std::vector<char> data;
  char chunk[1 << 16];
  size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, f.get())) > 0) data.insert(data.end(), chunk, chunk + n);
  if (std::ferror(f.get())) throw Error(path + ": read error");
  return data;
}

}  // namespace

void write_ply(const std::string& path, const Mesh& mesh) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment slicereuse test mesh\nelement vertex " +
      std::to_string(mesh.vertices()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(mesh.faces()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  std::vector<char> out(header.size() + mesh.V.size() * 8 + mesh.faces() * 13);
  char* p = out.data();
  std::memcpy(p, header.data(), header.size());
  p += header.size();
  std::memcpy(p, mesh.V.data(), mesh.V.size() * 8);
  p += mesh.V.size() * 8;
  for (size_t f = 0; f < mesh.faces(); ++f, p += 13) {
    *p = 3;
    std::memcpy(p + 1, &mesh.F[3 * f], 12);
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

Mesh read_ply(const std::string& path) {
  const std::vector<char> data = slurp(path);
  const char* p = data.data();
  const char* end = p + data.size();

  // Header: one keyword line at a time up to end_header.
  bool ascii = false, have_format = false;
  std::vector<Element> elements;
  size_t line = 0;
  for (;;) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', size_t(end - p)));
    if (!eol) throw Error(path + ": PLY header has no end_header line");
    std::string text(p, eol);
    p = eol + 1;
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::vector<std::string> w;
    for (size_t i = 0; i < text.size();) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      size_t j = i;
      while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
      if (j > i) w.emplace_back(text, i, j - i);
      i = j;
    }
    auto bad = [&](const std::string& what) {
      return Error(path + ": PLY header line " + std::to_string(line) + ": " + what + ": '" + text + "'");
    };
    if (line == 1) {
      if (text != "ply") throw Error(path + ": not a PLY file (first line is not 'ply')");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3) throw bad("malformed format line");
      if (w[1] == "ascii") ascii = true;
      else if (w[1] == "binary_little_endian") ascii = false;
      else throw bad("unsupported format (only ascii and binary_little_endian)");
      have_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) throw bad("malformed element line");
      Element e;
      e.name = w[1];
      auto [q, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (ec != std::errc() || q != w[2].data() + w[2].size()) throw bad("bad element count");
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (elements.empty()) throw bad("property before any element");
      Property prop;
      if (w.size() == 5 && w[1] == "list") {
        prop.list = true;
        if (!parse_type(w[2], prop.count_type) || !parse_type(w[3], prop.type)) throw bad("unknown type");
        if (prop.count_type == Type::F32 || prop.count_type == Type::F64) throw bad("list count must be an integer");
        prop.name = w[4];
      } else if (w.size() == 3) {
        if (!parse_type(w[1], prop.type)) throw bad("unknown type");
        prop.name = w[2];
      } else {
        throw bad("malformed property line");
      }
      elements.back().props.push_back(prop);
    } else {
      throw bad("unknown keyword");
    }
  }
  if (!have_format) throw Error(path + ": PLY header has no format line");

  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
  }
  if (!vertex) throw Error(path + ": PLY has no vertex element");
  if (!face) throw Error(path + ": PLY has no face element");
  int coord_of[64];  // property index -> 0/1/2 for x/y/z, -1 otherwise
  if (vertex->props.size() > 64) throw Error(path + ": too many vertex properties");
  int found = 0;
  for (size_t i = 0; i < vertex->props.size(); ++i) {
    const Property& q = vertex->props[i];
    coord_of[i] = q.name == "x" ? 0 : q.name == "y" ? 1 : q.name == "z" ? 2 : -1;
    if (coord_of[i] >= 0) {
      if (q.list) throw Error(path + ": vertex property " + q.name + " is a list");
      found |= 1 << coord_of[i];
    }
  }
  if (found != 7) throw Error(path + ": vertex element lacks x, y or z");
  int index_prop = -1;
  for (size_t i = 0; i < face->props.size(); ++i) {
    const Property& q = face->props[i];
    if (q.list && (q.name == "vertex_indices" || q.name == "vertex_index")) index_prop = int(i);
  }
  if (index_prop < 0) throw Error(path + ": face element has no vertex_indices list");
  if (face->props[index_prop].type == Type::F32 || face->props[index_prop].type == Type::F64)
    throw Error(path + ": face vertex indices are not integers");

  Mesh mesh;
  mesh.V.resize(3 * vertex->count);
  mesh.F.resize(3 * face->count);
  Cursor in(path, p, end, ascii);
  in.set_line(line + 1);
  for (const Element& e : elements) {
    for (size_t r = 0; r < e.count; ++r) {
      for (size_t i = 0; i < e.props.size(); ++i) {
        const Property& q = e.props[i];
        if (!q.list) {
          const double v = in.number(q.type);
          if (&e == vertex && coord_of[i] >= 0) {
            if (!std::isfinite(v)) in.fail("vertex " + std::to_string(r) + " has a non-finite coordinate");
            mesh.V[3 * r + coord_of[i]] = v;
          }
          continue;
        }
        const double n = in.number(q.count_type);
        if (n < 0) in.fail("negative list length in element " + e.name);
        const bool indices = &e == face && int(i) == index_prop;
        if (indices && n != 3)
          in.fail("face " + std::to_string(r) + " has " + std::to_string(size_t(n)) +
                  " vertices; only triangles are supported");
        for (size_t k = 0; k < size_t(n); ++k) {
          const double v = in.number(q.type);
          if (!indices) continue;
          if (v < 0 || v >= double(vertex->count))
            in.fail("face " + std::to_string(r) + " has vertex index " + std::to_string(int64_t(v)) +
                    " out of range [0, " + std::to_string(vertex->count) + ")");
          mesh.F[3 * r + k] = uint32_t(v);
        }
      }
    }
  }
  if (mesh.F.empty()) throw Error(path + ": PLY has no faces");
  return mesh;
}

}  // namespace slicereuse::test
