#pragma once
// text_tokens: the one tokenizer of the text formats, .ctr / .enc (slice_files_text_read.cpp),
// support points (support_points_file.cpp),
// .map (map_files.cpp) and ASCII CLI (cli_file_read.cpp); internal, not part of the API.
//   LineReader: the lines of a text, ending at '\n' (a '\r' before it is dropped), numbered from 1;
//   fail_at_line: the error naming the file and the line, "'path', line N: what".
//   Blanks separate tokens: space and tab (CLI's parameters run over line ends, so its blanks,
//   AcrossLines, are also '\r' and '\n').
//   from_chars_number: a number at p as std::from_chars reads it (decimal or exponent notation
//   with an optional '-', no '+'; integers in base Base, a constant so that it compiles to the
//   base's own parser); parse_number: one blank-separated number token, which must be entirely a
//   number; next_word, at_end: words and the end of a line; next_token: a token between blanks of
//   the caller's own.
//   quoted: text for an error message, at most 40 bytes, unprintable bytes shown as '?', so that
//   garbage cannot flood the message.
// Inline: the readers parse tens of millions of numbers through these.
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "slicereuse/util/error.h"

namespace slicereuse::detail {

struct Line {
  const char* b;
  const char* e;
  uint64_t number;
};

class LineReader {
 public:
  LineReader(const char* b, const char* e) : p_(b), end_(e) {}
  bool next(Line& line) {
    if (p_ == end_) return false;
    const char* nl = static_cast<const char*>(std::memchr(p_, '\n', size_t(end_ - p_)));
    line.b = p_;
    line.e = nl ? nl : end_;
    if (line.e > line.b && line.e[-1] == '\r') --line.e;
    line.number = ++number_;
    p_ = nl ? nl + 1 : end_;
    return true;
  }

 private:
  const char* p_;
  const char* end_;
  uint64_t number_ = 0;
};

[[noreturn]] inline void fail_at_line(const std::string& path, uint64_t line, const std::string& what) {
  throw Error("'" + path + "', line " + std::to_string(line) + ": " + what);
}

template <bool AcrossLines = false>
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || (AcrossLines && (c == '\r' || c == '\n'));
}
template <bool AcrossLines = false>
inline const char* skip_blanks(const char* p, const char* e) {
  while (p < e && is_blank<AcrossLines>(*p)) ++p;
  return p;
}
inline bool at_end(const char* p, const char* e) { return skip_blanks(p, e) == e; }

// On success p moves past the number.
template <int Base = 10, class T>
inline bool from_chars_number(const char*& p, const char* e, T& v) {
  std::from_chars_result r;
  if constexpr (std::is_floating_point_v<T>)
    r = std::from_chars(p, e, v);
  else
    r = std::from_chars(p, e, v, Base);
  if (r.ec != std::errc()) return false;
  p = r.ptr;
  return true;
}

// Blanks, then a number that ends at a blank or at e; on success p moves past it.
template <int Base = 10, class T>
inline bool parse_number(const char*& p, const char* e, T& v) {
  const char* q = skip_blanks(p, e);
  if (!from_chars_number<Base>(q, e, v) || (q < e && !is_blank(*q))) return false;
  p = q;
  return true;
}

// Bytes for which blank(c) holds, then the token up to the next one (empty at e); p moves past
// it. For formats whose blanks are not is_blank's (the mesh files': scanf's, or OBJ's '\r').
template <class Blank>
inline std::string_view next_token(const char*& p, const char* e, Blank blank) {
  while (p < e && blank(*p)) ++p;
  const char* q = p;
  while (q < e && !blank(*q)) ++q;
  const std::string_view token(p, size_t(q - p));
  p = q;
  return token;
}

// Blanks, then the word up to the next blank; false when there is none.
inline bool next_word(const char*& p, const char* e, std::string_view& word) {
  word = next_token(p, e, [](char c) { return is_blank(c); });
  return !word.empty();
}

// The text from p to the first byte for which ends(c) holds (or 40 bytes, or e), quoted.
template <class Ends>
std::string quoted(const char* p, const char* e, Ends ends) {
  const char* q = p;
  while (q < e && q - p < 40 && !ends(*q)) ++q;
  std::string s(p, q);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return "'" + s + "'";
}
// The token at p (after blanks), quoted.
inline std::string quoted_token(const char* p, const char* e) {
  return quoted(skip_blanks(p, e), e, [](char c) { return is_blank(c); });
}

}  // namespace slicereuse::detail
