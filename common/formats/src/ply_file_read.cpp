// PLY reader (mesh_file.h): the header's elements are walked in order; the vertex element's
// x, y, z become V, the face element's vertex_indices (or vertex_index) lists become F, fanned
// as vcg's import_ply.h does; every other property and element is stepped over. Every count is
// checked against the bytes left before anything is allocated for it.
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "mesh_file_read.h"

namespace slicereuse::detail {
namespace {

enum class PlyType : uint8_t { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

bool ply_type(std::string_view name, PlyType& t) {
  static const struct {
    const char* old_name;
    const char* new_name;
    PlyType type;
  } kTypes[] = {{"char", "int8", PlyType::Int8},       {"uchar", "uint8", PlyType::Uint8},
                {"short", "int16", PlyType::Int16},    {"ushort", "uint16", PlyType::Uint16},
                {"int", "int32", PlyType::Int32},      {"uint", "uint32", PlyType::Uint32},
                {"float", "float32", PlyType::Float32}, {"double", "float64", PlyType::Float64}};
  for (const auto& k : kTypes)
    if (name == k.old_name || name == k.new_name) return t = k.type, true;
  return false;
}

size_t type_size(PlyType t) {
  static constexpr size_t kSize[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return kSize[size_t(t)];
}
bool is_integer(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

struct Property {
  std::string name;
  bool list = false;
  PlyType type{};        // of the value, or of a list's items
  PlyType count_type{};  // of a list's count
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> props;
  uint64_t line = 0;
  // The fewest bytes one item takes in binary (its lists empty), and whether all are that size.
  uint64_t min_bytes() const {
    uint64_t n = 0;
    for (const Property& p : props) n += type_size(p.list ? p.count_type : p.type);
    return n;
  }
  bool fixed_size() const {
    for (const Property& p : props)
      if (p.list) return false;
    return true;
  }
  int find(std::string_view name) const {
    for (size_t i = 0; i < props.size(); ++i)
      if (props[i].name == name) return int(i);
    return -1;
  }
};

enum class Encoding { Ascii, Little, Big };

struct Header {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  const char* body = nullptr;
};

std::string_view word(const char*& p, const char* e) {
  while (p < e && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
  const char* q = p;
  while (q < e && *q != ' ' && *q != '\t' && *q != '\r') ++q;
  const std::string_view w(p, size_t(q - p));
  p = q;
  return w;
}

Header parse_header(const MeshBytes& in) {
  Header h;
  const char* p = in.b;
  uint64_t line = 0;
  bool format_seen = false;
  for (;;) {
    if (p == in.e) in.fail("the header has no end_header line (the file is truncated or not a PLY file)");
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', size_t(in.e - p)));
    const char* end = nl ? nl : in.e;
    const char* q = p;
    const char* line_start = p;
    p = nl ? nl + 1 : in.e;
    ++line;
    auto fail = [&](const std::string& what) { in.fail("line " + std::to_string(line) + ": " + what); };
    const std::string_view key = word(q, end);
    if (line == 1) {
      if (end - line_start < 3 || std::memcmp(line_start, "ply", 3) != 0) in.fail("not a PLY file: it does not start with 'ply'");
      continue;
    }
    if (key.empty() || key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (!format_seen) fail("end_header before any format line");
      h.body = p;
      return h;
    }
    if (key == "format") {
      const std::string_view f = word(q, end);
      if (f == "ascii") h.encoding = Encoding::Ascii;
      else if (f == "binary_little_endian") h.encoding = Encoding::Little;
      else if (f == "binary_big_endian") h.encoding = Encoding::Big;
      else fail("unknown format " + quote_token(f.data(), end) + " (ascii, binary_little_endian or binary_big_endian)");
      format_seen = true;
      continue;
    }
    if (!format_seen) fail("expected the format line, found " + quote_token(key.data(), end));
    if (key == "element") {
      Element el;
      el.name = std::string(word(q, end));
      const std::string_view n = word(q, end);
      int64_t count = 0;
      if (el.name.empty() || !parse_integer(n.data(), n.data() + n.size(), count) || count < 0)
        fail("expected 'element <name> <count>'");
      el.count = uint64_t(count);
      el.line = line;
      h.elements.push_back(std::move(el));
    } else if (key == "property") {
      if (h.elements.empty()) fail("a property before any element");
      Property prop;
      std::string_view t = word(q, end);
      if (t == "list") {
        prop.list = true;
        const std::string_view ct = word(q, end);
        if (!ply_type(ct, prop.count_type)) fail("unknown type " + quote_token(ct.data(), end) + " of a list's count");
        if (!is_integer(prop.count_type)) fail("a list's count type must be an integer type");
        t = word(q, end);
      }
      if (!ply_type(t, prop.type)) fail("unknown property type " + quote_token(t.data(), end));
      prop.name = std::string(word(q, end));
      if (prop.name.empty()) fail("a property without a name");
      h.elements.back().props.push_back(std::move(prop));
    } else {
      fail("unexpected " + quote_token(key.data(), end) + " in the header");
    }
  }
}

// What the body walk takes from each element: x, y, z of "vertex", the index list of "face".
struct Roles {
  const Element* vertex = nullptr;
  int xyz[3] = {-1, -1, -1};
  const Element* face = nullptr;
  int indices = -1;
};

Roles find_roles(const MeshBytes& in, const Header& h) {
  Roles r;
  for (const Element& el : h.elements) {
    auto at = [&] { return "line " + std::to_string(el.line) + ": "; };
    if (el.name == "vertex") {
      if (r.vertex) in.fail(at() + "a second vertex element");
      r.vertex = &el;
      const char* names[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        r.xyz[k] = el.find(names[k]);
        if (r.xyz[k] < 0) in.fail(at() + "the vertex element has no property " + names[k]);
        if (el.props[size_t(r.xyz[k])].list) in.fail(at() + "the vertex property " + names[k] + " is a list");
      }
    } else if (el.name == "face") {
      if (r.face) in.fail(at() + "a second face element");
      if (!r.vertex) in.fail(at() + "the face element comes before the vertex element");
      r.face = &el;
      r.indices = el.find("vertex_indices");
      if (r.indices < 0) r.indices = el.find("vertex_index");
      if (r.indices < 0) in.fail(at() + "the face element has no vertex_indices (or vertex_index) property");
      const Property& p = el.props[size_t(r.indices)];
      if (!p.list || !is_integer(p.type)) in.fail(at() + "the face's " + p.name + " is not a list of integers");
    }
  }
  if (!r.vertex) in.fail("the header has no vertex element");
  return r;
}

// Adds the face of `count` vertex indices, fanned, to F; checks every index first.
struct FaceSink {
  const MeshBytes& in;
  std::vector<uint32_t>& F;
  uint64_t vertices;
  template <class Where>
  void check_count(int64_t count, uint64_t face, Where where) const {
    if (count < 3 || count > 255)
      in.fail(where() + "face " + std::to_string(face) + " has " + std::to_string(count) +
              " vertices (a face needs 3 to 255)");
  }
  template <class Where>
  uint32_t index(int64_t i, uint64_t face, Where where) const {
    if (i < 0 || uint64_t(i) >= vertices)
      in.fail(where() + "face " + std::to_string(face) + " uses vertex " + std::to_string(i) + " but the file has " +
              std::to_string(vertices) + " vertices (numbered from 0)");
    return uint32_t(i);
  }
  void add(const uint32_t* v, int64_t count) {
    for (int64_t k = 2; k < count; ++k) F.insert(F.end(), {v[0], v[k - 1], v[k]});
  }
};

// ---- binary ----

template <class U>
U load(const char* p, bool big) {
  U u;
  std::memcpy(&u, p, sizeof u);
  if (big) {
    if constexpr (sizeof(U) == 2) u = U(__builtin_bswap16(u));
    if constexpr (sizeof(U) == 4) u = U(__builtin_bswap32(u));
    if constexpr (sizeof(U) == 8) u = U(__builtin_bswap64(u));
  }
  return u;
}

template <class T>
T bits_as(const char* p, bool big) {
  using U = std::conditional_t<sizeof(T) == 1, uint8_t,
                               std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
  const U u = load<U>(p, big);
  T v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

// A binary value of type t as R: a double (any type), or an int64_t (the integer types; 0 for
// the float ones, which parse_header and find_roles never let a list count or index be).
template <class R>
R binary_value(const char* p, PlyType t, bool big) {
  switch (t) {
    case PlyType::Int8: return R(bits_as<int8_t>(p, big));
    case PlyType::Uint8: return R(bits_as<uint8_t>(p, big));
    case PlyType::Int16: return R(bits_as<int16_t>(p, big));
    case PlyType::Uint16: return R(bits_as<uint16_t>(p, big));
    case PlyType::Int32: return R(bits_as<int32_t>(p, big));
    case PlyType::Uint32: return R(bits_as<uint32_t>(p, big));
    case PlyType::Float32: return std::is_floating_point_v<R> ? R(bits_as<float>(p, big)) : R(0);
    case PlyType::Float64: return std::is_floating_point_v<R> ? R(bits_as<double>(p, big)) : R(0);
  }
  return 0;
}

double binary_real(const char* p, PlyType t, bool big) { return binary_value<double>(p, t, big); }
int64_t binary_integer(const char* p, PlyType t, bool big) { return binary_value<int64_t>(p, t, big); }

class BinaryBody {
 public:
  BinaryBody(const MeshBytes& in, const char* p, bool big) : in_(in), p_(p), big_(big) {}

  void read(const Header& h, const Roles& r, Mesh& mesh) {
    for (const Element& el : h.elements) {
      check_room(el);
      if (&el == r.vertex)
        read_vertices(el, r, mesh.V);
      else if (&el == r.face)
        read_faces(el, r, mesh);
      else
        skip(el);
    }
  }

 private:
  std::string where(const char* p) const { return "byte " + std::to_string(p - in_.b) + ": "; }

  // The element's items need at least count * min_bytes bytes: a lying count fails here.
  void check_room(const Element& el) const {
    const uint64_t left = uint64_t(in_.e - p_), min = el.min_bytes();
    if (min != 0 && el.count > left / min)
      in_.fail("the " + el.name + " element's " + std::to_string(el.count) + " items need at least " +
               std::to_string(el.count) + " x " + std::to_string(min) + " bytes but " + std::to_string(left) +
               " are left after byte " + std::to_string(p_ - in_.b) + " (truncated)");
  }

  // Moves past one property of the item at p_, checking each step against the end; returns
  // where the property starts.
  const char* step(const Property& prop, uint64_t item, const Element& el) {
    const char* at = p_;
    const size_t cs = type_size(prop.list ? prop.count_type : prop.type);
    need(cs, item, el);
    p_ += cs;
    if (!prop.list) return at;
    const int64_t n = binary_integer(at, prop.count_type, big_);
    if (n < 0) in_.fail(where(at) + el.name + " " + std::to_string(item) + " has a list of " + std::to_string(n) + " items");
    // n items fit when n <= left / size: this test cannot overflow, unlike n * size.
    const size_t is = type_size(prop.type);
    if (uint64_t(n) > uint64_t(in_.e - p_) / is) need(uint64_t(in_.e - p_) + 1, item, el);
    p_ += size_t(n) * is;
    return at;
  }
  void need(uint64_t bytes, uint64_t item, const Element& el) const {
    if (bytes > uint64_t(in_.e - p_))
      in_.fail(where(p_) + "the file ends inside " + el.name + " " + std::to_string(item) + " of " +
               std::to_string(el.count) + " (truncated)");
  }

  void skip(const Element& el) {
    if (el.fixed_size()) {
      p_ += el.count * el.min_bytes();  // check_room made sure that it is there
      return;
    }
    for (uint64_t i = 0; i < el.count; ++i)
      for (const Property& prop : el.props) step(prop, i, el);
  }

  void read_vertices(const Element& el, const Roles& r, std::vector<double>& V) {
    V.resize(3 * size_t(el.count));
    const PlyType tx = el.props[size_t(r.xyz[0])].type, ty = el.props[size_t(r.xyz[1])].type,
                  tz = el.props[size_t(r.xyz[2])].type;
    if (el.fixed_size()) {
      size_t off[3];
      for (int k = 0; k < 3; ++k) {
        off[k] = 0;
        for (int j = 0; j < r.xyz[k]; ++j) off[k] += type_size(el.props[size_t(j)].type);
      }
      const size_t stride = size_t(el.min_bytes());
      const char* p = p_;
      double* v = V.data();
      if (!big_ && tx == PlyType::Float32 && ty == PlyType::Float32 && tz == PlyType::Float32) {
        for (uint64_t i = 0; i < el.count; ++i, p += stride, v += 3) {
          float x, y, z;
          std::memcpy(&x, p + off[0], 4), std::memcpy(&y, p + off[1], 4), std::memcpy(&z, p + off[2], 4);
          v[0] = x, v[1] = y, v[2] = z;
        }
      } else {
        for (uint64_t i = 0; i < el.count; ++i, p += stride, v += 3)
          v[0] = binary_real(p + off[0], tx, big_), v[1] = binary_real(p + off[1], ty, big_),
          v[2] = binary_real(p + off[2], tz, big_);
      }
      p_ = p;
    } else {
      for (uint64_t i = 0; i < el.count; ++i)
        for (size_t j = 0; j < el.props.size(); ++j) {
          const char* at = step(el.props[j], i, el);
          for (int k = 0; k < 3; ++k)
            if (int(j) == r.xyz[k]) V[3 * i + size_t(k)] = binary_real(at, el.props[j].type, big_);
        }
    }
    for (size_t i = 0; i < V.size(); ++i)
      if (!std::isfinite(V[i]))
        in_.fail("vertex " + std::to_string(i / 3) + " has a coordinate that is not a finite number (NaN or infinity)");
  }

  void read_faces(const Element& el, const Roles& r, Mesh& mesh) {
    FaceSink sink{in_, mesh.F, mesh.V.size() / 3};
    mesh.F.reserve(3 * size_t(el.count));
    const Property& list = el.props[size_t(r.indices)];
    const size_t cs = type_size(list.count_type), is = type_size(list.type);
    uint32_t v[255];
    for (uint64_t f = 0; f < el.count; ++f)
      for (size_t j = 0; j < el.props.size(); ++j) {
        if (int(j) != r.indices) {
          step(el.props[j], f, el);
          continue;
        }
        need(cs, f, el);
        const char* at = p_;
        auto here = [&] { return where(at); };
        const int64_t n = binary_integer(p_, list.count_type, big_);
        sink.check_count(n, f, here);
        need(cs + size_t(n) * is, f, el);
        p_ += cs;
        if (!big_ && list.type <= PlyType::Uint32 && is == 4) {  // the common int/uint indices
          for (int64_t k = 0; k < n; ++k, p_ += 4)
            v[k] = sink.index(list.type == PlyType::Int32 ? int64_t(bits_as<int32_t>(p_, false))
                                                          : int64_t(bits_as<uint32_t>(p_, false)),
                              f, here);
        } else {
          for (int64_t k = 0; k < n; ++k, p_ += is) v[k] = sink.index(binary_integer(p_, list.type, big_), f, here);
        }
        sink.add(v, n);
      }
  }

  const MeshBytes& in_;
  const char* p_;
  bool big_;
};

// ---- ASCII ----

class AsciiBody {
 public:
  AsciiBody(const MeshBytes& in, const char* p) : in_(in), p_(p) {}

  void read(const Header& h, const Roles& r, Mesh& mesh) {
    for (const Element& el : h.elements) {
      check_room(el);
      if (&el == r.vertex) {
        mesh.V.resize(3 * size_t(el.count));
        double* v = mesh.V.data();
        for (uint64_t i = 0; i < el.count; ++i, v += 3)
          for (size_t j = 0; j < el.props.size(); ++j) {
            const Property& prop = el.props[j];
            int k = 0;
            while (k < 3 && r.xyz[k] != int(j)) ++k;
            if (k == 3) {
              skip(prop, i, el);
              continue;
            }
            const std::string_view t = token(i, el);
            if (!real(t, prop.type, v[k]))
              in_.fail_at_line(t.data(), "vertex " + std::to_string(i) + ": expected a number, found " + quote_token(t.data(), in_.e));
            if (!std::isfinite(v[k]))
              in_.fail_at_line(t.data(), "vertex " + std::to_string(i) + " has a coordinate that is not a finite number (NaN or infinity)");
          }
      } else if (&el == r.face) {
        FaceSink sink{in_, mesh.F, mesh.V.size() / 3};
        mesh.F.reserve(3 * size_t(el.count));
        uint32_t v[255];
        for (uint64_t f = 0; f < el.count; ++f)
          for (size_t j = 0; j < el.props.size(); ++j) {
            if (int(j) != r.indices) {
              skip(el.props[j], f, el);
              continue;
            }
            std::string_view t = token(f, el);
            auto here = [&] { return "line " + std::to_string(in_.line_of(t.data())) + ": "; };
            const int64_t n = integer(t, f, el);
            sink.check_count(n, f, here);
            for (int64_t k = 0; k < n; ++k) {
              t = token(f, el);
              v[k] = sink.index(integer(t, f, el), f, here);
            }
            sink.add(v, n);
          }
      } else if (!el.props.empty()) {  // an element without properties has nothing to step over
        for (uint64_t i = 0; i < el.count; ++i)
          for (const Property& prop : el.props) skip(prop, i, el);
      }
    }
  }

 private:
  // Each value takes at least one character and one blank: a lying count fails here.
  void check_room(const Element& el) const {
    const uint64_t left = uint64_t(in_.e - p_), values = el.props.size();
    if (values != 0 && el.count > (left / 2 + 1) / values)
      in_.fail("the " + el.name + " element's " + std::to_string(el.count) + " items (" + std::to_string(values) +
               " values each) cannot fit in the " + std::to_string(left) + " bytes left after line " +
               std::to_string(in_.line_of(p_)) + " (truncated)");
  }

  std::string_view token(uint64_t item, const Element& el) {
    const std::string_view t = next_token(p_, in_.e, is_space);
    if (t.empty())
      in_.fail("the file ends inside " + el.name + " " + std::to_string(item) + " of " + std::to_string(el.count) + " (truncated)");
    return t;
  }
  int64_t integer(std::string_view t, uint64_t item, const Element& el) const {
    int64_t n;
    if (!parse_integer(t.data(), t.data() + t.size(), n))
      in_.fail_at_line(t.data(), el.name + " " + std::to_string(item) + ": expected an integer, found " + quote_token(t.data(), in_.e));
    return n;
  }
  // As vcg's plylib reads it: a float property as a float (fscanf "%f"), a double as a double.
  static bool real(std::string_view t, PlyType type, double& v) {
    if (type == PlyType::Float32) {
      float f;
      if (!parse_real(t.data(), t.data() + t.size(), f)) return false;
      return v = f, true;
    }
    if (type == PlyType::Float64) return parse_real(t.data(), t.data() + t.size(), v);
    int64_t n;
    if (!parse_integer(t.data(), t.data() + t.size(), n)) return false;
    return v = double(n), true;
  }
  void skip(const Property& prop, uint64_t item, const Element& el) {
    if (!prop.list) return void(token(item, el));
    const std::string_view t = token(item, el);
    const int64_t n = integer(t, item, el);
    if (n < 0) in_.fail_at_line(t.data(), el.name + " " + std::to_string(item) + " has a list of " + std::to_string(n) + " items");
    for (int64_t k = 0; k < n; ++k) token(item, el);
  }

  const MeshBytes& in_;
  const char* p_;
};

}  // namespace

Mesh read_ply_mesh(const MeshBytes& in) {
  const Header h = parse_header(in);
  const Roles r = find_roles(in, h);
  if (r.vertex->count > UINT32_MAX) in.fail("more vertices (" + std::to_string(r.vertex->count) + ") than 32-bit indices reach");
  Mesh mesh;
  if (h.encoding == Encoding::Ascii)
    AsciiBody(in, h.body).read(h, r, mesh);
  else
    BinaryBody(in, h.body, h.encoding == Encoding::Big).read(h, r, mesh);
  return mesh;
}

}  // namespace slicereuse::detail
