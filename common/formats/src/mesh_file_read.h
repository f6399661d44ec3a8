#pragma once
// What the mesh file readers share (mesh_file.h; internal): the file's bytes with its name and
// kind for messages, numbers read as C's strtof / strtod / atoi read them, and the per-format
// readers that mesh_file.cpp dispatches to. Each reader returns the mesh as its format gives it
// (after STL's vertex unification); read_mesh_file then drops faces that use a vertex twice.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/text_tokens.h"

namespace slicereuse::detail {

struct MeshBytes {
  const std::string& path;
  const char* kind;  // "STL", "PLY", "OBJ"
  const char* b;
  const char* e;

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(std::string(kind) + " file '" + path + "': " + what);
  }
  uint64_t line_of(const char* p) const { return 1 + uint64_t(std::count(b, p, '\n')); }
  [[noreturn]] void fail_at_line(const char* p, const std::string& what) const {
    fail("line " + std::to_string(line_of(p)) + ": " + what);
  }
  uint64_t size() const { return uint64_t(e - b); }
};

Mesh read_stl_mesh(const MeshBytes& in);
Mesh read_ply_mesh(const MeshBytes& in);
Mesh read_obj_mesh(const MeshBytes& in);

// Blanks between tokens, as scanf skips them.
inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// The token [p, e) read entirely as a real number the way strtof (float) / strtod (double)
// read it: an optional '+', then what std::from_chars takes; a value beyond the type's range
// (from_chars refuses it) goes through strtof/strtod itself, which give +-inf or a zero.
template <class T>
bool parse_real(const char* p, const char* e, T& v) {
  const char* q = p;
  if (q < e && *q == '+' && q + 1 < e && q[1] != '-' && q[1] != '+') ++q;
  const std::from_chars_result r = std::from_chars(q, e, v);
  if (r.ptr != e || q == e) return false;
  if (r.ec == std::errc::result_out_of_range) {
    const std::string s(p, e);
    char* end = nullptr;
    if constexpr (sizeof(T) == sizeof(float))
      v = std::strtof(s.c_str(), &end);
    else
      v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
  }
  return r.ec == std::errc();
}

// The token [p, e) read entirely as a decimal integer with an optional sign.
inline bool parse_integer(const char* p, const char* e, int64_t& v) {
  if (p < e && *p == '+' && p + 1 < e && p[1] != '-') ++p;
  const std::from_chars_result r = std::from_chars(p, e, v);
  return r.ec == std::errc() && r.ptr == e;
}

// The token at p (up to a blank or e) for a message.
inline std::string quote_token(const char* p, const char* e) { return quoted(p, e, is_space); }

}  // namespace slicereuse::detail
