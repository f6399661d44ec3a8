// STL reader (mesh_file.h): binary or ASCII by vcg's rule (import_stl.h), the corners read as
// floats in file order, then equal corners unified as MeshLab's "unify duplicated vertices"
// does (vcg Clean::RemoveDuplicateVertex + CompactEveryVector): the first corner of each set of
// equal ones survives, in the order of first occurrence. A hash table makes that linear.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "mesh_file_read.h"

namespace slicereuse::detail {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary STL reading assumes a little-endian host");

constexpr uint64_t kHeaderBytes = 84, kFacetBytes = 50;

// Corners in, indexed vertices out: add() returns the index of the first corner equal to
// (x, y, z) as floats, making a new vertex when there is none. An open-addressing hash table at
// most half full, doubled as vertices come (a closed mesh has about one vertex per 6 corners).
class CornerUnifier {
 public:
  explicit CornerUnifier(size_t expected_vertices) {
    size_t n = 16;
    while (n < 2 * expected_vertices) n *= 2;
    slots_.assign(n, 0);
    keys_.reserve(3 * expected_vertices);
  }
  uint32_t add(float x, float y, float z) {
    // + 0.0f makes -0.0 into +0.0, so that the bits of equal floats are equal.
    uint32_t k[3];
    const float c[3] = {x + 0.0f, y + 0.0f, z + 0.0f};
    std::memcpy(k, c, sizeof k);
    const size_t mask = slots_.size() - 1;
    for (size_t s = hash(k) & mask;; s = (s + 1) & mask) {
      const uint32_t v = slots_[s];
      if (v == 0) {
        const uint32_t index = uint32_t(keys_.size() / 3);
        keys_.insert(keys_.end(), k, k + 3);
        slots_[s] = index + 1;
        if (2 * size_t(index + 1) > slots_.size()) grow();
        return index;
      }
      const uint32_t* q = &keys_[3 * size_t(v - 1)];
      if (q[0] == k[0] && q[1] == k[1] && q[2] == k[2]) return v - 1;
    }
  }

 private:
  static size_t hash(const uint32_t k[3]) {
    uint64_t h = (uint64_t(k[0]) << 32 | k[1]) * 0x9E3779B97F4A7C15ull ^ uint64_t(k[2]) * 0xC2B2AE3D27D4EB4Full;
    return size_t(h ^ (h >> 29));
  }
  void grow() {
    slots_.assign(2 * slots_.size(), 0);
    const size_t mask = slots_.size() - 1;
    for (size_t v = 0; v < keys_.size() / 3; ++v) {
      size_t s = hash(&keys_[3 * v]) & mask;
      while (slots_[s] != 0) s = (s + 1) & mask;
      slots_[s] = uint32_t(v + 1);
    }
  }

  std::vector<uint32_t> slots_;  // 0: empty, else vertex index + 1
  std::vector<uint32_t> keys_;   // the vertices' floats as bits, -0.0 made +0.0
};

// Adds a corner to the mesh: its vertex index to F and, when it is a new vertex, its own floats
// to V (so a -0.0 that comes first stays -0.0, as in MeshLab). where() says where it is.
struct StlBuilder {
  const MeshBytes& in;
  CornerUnifier unifier;
  Mesh mesh;
  template <class Where>
  void corner(const float xyz[3], Where where) {
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      in.fail(where() + ": a coordinate is not a finite number (NaN or infinity)");
    const size_t before = mesh.V.size() / 3;
    const uint32_t v = unifier.add(xyz[0], xyz[1], xyz[2]);
    if (v == before) mesh.V.insert(mesh.V.end(), {double(xyz[0]), double(xyz[1]), double(xyz[2])});
    mesh.F.push_back(v);
  }
};

Mesh read_binary(const MeshBytes& in, uint32_t facets) {
  const uint64_t need = kHeaderBytes + kFacetBytes * uint64_t(facets);
  if (in.size() < need)
    in.fail("binary STL of " + std::to_string(facets) + " facets needs " + std::to_string(need) +
            " bytes but the file has " + std::to_string(in.size()) + " (truncated)");
  StlBuilder s{in, CornerUnifier(size_t(facets) / 2 + 3), {}};
  s.mesh.V.reserve(3 * (size_t(facets) / 2 + 3));
  s.mesh.F.reserve(3 * size_t(facets));
  const char* p = in.b + kHeaderBytes;
  for (uint32_t f = 0; f < facets; ++f, p += kFacetBytes) {
    float xyz[9];
    std::memcpy(xyz, p + 12, sizeof xyz);
    for (int k = 0; k < 3; ++k)
      s.corner(xyz + 3 * k, [&] {
        return "facet " + std::to_string(f) + " (byte " + std::to_string(p - in.b) + "), vertex " + std::to_string(k);
      });
  }
  return std::move(s.mesh);
}

Mesh read_ascii(const MeshBytes& in) {
  const char* p = static_cast<const char*>(std::memchr(in.b, '\n', in.size()));
  p = p ? p + 1 : in.e;  // the first line ("solid name") is skipped, as vcg does
  // A facet takes about 250 bytes of text and a closed mesh has half as many vertices as facets.
  StlBuilder s{in, CornerUnifier(in.size() / 500 + 3), {}};
  auto expect = [&](std::string_view word) {
    const std::string_view t = next_token(p, in.e, is_space);
    if (t != word)
      in.fail_at_line(t.data(), "expected '" + std::string(word) + "', found " +
                              (t.empty() ? std::string("the end of the file") : quote_token(t.data(), in.e)));
  };
  for (;;) {
    const std::string_view t = next_token(p, in.e, is_space);
    if (t.empty()) break;
    if (t == "endsolid" || t == "solid") {  // a solid's name runs to the end of its line
      const void* nl = std::memchr(p, '\n', size_t(in.e - p));
      p = nl ? static_cast<const char*>(nl) + 1 : in.e;
      continue;
    }
    if (t != "facet") in.fail_at_line(t.data(), "expected 'facet', 'endsolid' or 'solid', found " + quote_token(t.data(), in.e));
    expect("normal");
    for (int k = 0; k < 3; ++k)
      if (next_token(p, in.e, is_space).empty()) in.fail_at_line(t.data(), "the facet's normal is cut short by the end of the file");
    expect("outer");
    expect("loop");
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      float xyz[3];
      for (float& c : xyz) {
        const std::string_view n = next_token(p, in.e, is_space);
        if (n.empty() || !parse_real(n.data(), n.data() + n.size(), c))
          in.fail_at_line(n.empty() ? p : n.data(),
                          "expected a vertex coordinate, found " +
                              (n.empty() ? std::string("the end of the file") : quote_token(n.data(), in.e)));
      }
      s.corner(xyz, [&] { return "line " + std::to_string(in.line_of(p)) + ", facet vertex " + std::to_string(k); });
    }
    expect("endloop");
    expect("endfacet");
  }
  return std::move(s.mesh);
}

}  // namespace

Mesh read_stl_mesh(const MeshBytes& in) {
  if (in.size() < kHeaderBytes)
    in.fail("the file has " + std::to_string(in.size()) + " bytes: MeshLab takes no STL file shorter than 84");
  uint32_t facets;
  std::memcpy(&facets, in.b + 80, 4);
  const uint64_t expected = kHeaderBytes + kFacetBytes * uint64_t(facets);
  if (in.size() == expected) return read_binary(in, facets);
  // vcg's second test: a byte above 127 soon after the header means binary, with a size at most
  // 5% off the one the count gives.
  const unsigned char* q = reinterpret_cast<const unsigned char*>(in.b + kHeaderBytes);
  const size_t look = size_t(std::min<uint64_t>(1000, in.size() - kHeaderBytes));
  if (std::any_of(q, q + look, [](unsigned char c) { return c > 127; })) {
    const uint64_t diff = in.size() > expected ? in.size() - expected : expected - in.size();
    if (diff > in.size() / 20)
      in.fail("looks binary but its size, " + std::to_string(in.size()) + " bytes, is more than 5% off the " +
              std::to_string(expected) + " bytes its facet count (" + std::to_string(facets) + ") gives");
    return read_binary(in, facets);
  }
  return read_ascii(in);
}

}  // namespace slicereuse::detail
