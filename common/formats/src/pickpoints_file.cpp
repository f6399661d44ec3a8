#include "slicereuse/formats/pickpoints_file.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>

#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"

namespace slicereuse {
namespace {

// The text of an XML attribute value with the predefined and numeric character references
// replaced; false when a reference is malformed.
bool decode_entities(const std::string& raw, std::string& out) {
  out.clear();
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const size_t semi = raw.find(';', i);
    if (semi == std::string::npos) return false;
    const std::string ent = raw.substr(i + 1, semi - i - 1);
    if (ent == "amp") out += '&';
    else if (ent == "lt") out += '<';
    else if (ent == "gt") out += '>';
    else if (ent == "quot") out += '"';
    else if (ent == "apos") out += '\'';
    else if (ent.size() > 1 && ent[0] == '#') {
      unsigned long code = 0;
      const bool hex = ent[1] == 'x' || ent[1] == 'X';
      const char* b = ent.data() + (hex ? 2 : 1);
      const auto r = std::from_chars(b, ent.data() + ent.size(), code, hex ? 16 : 10);
      if (r.ec != std::errc() || r.ptr != ent.data() + ent.size() || code == 0 || code > 0x10ffff) return false;
      if (code < 0x80) {
        out += char(code);
      } else if (code < 0x800) {
        out += char(0xc0 | (code >> 6)), out += char(0x80 | (code & 0x3f));
      } else if (code < 0x10000) {
        out += char(0xe0 | (code >> 12)), out += char(0x80 | ((code >> 6) & 0x3f)), out += char(0x80 | (code & 0x3f));
      } else {
        out += char(0xf0 | (code >> 18)), out += char(0x80 | ((code >> 12) & 0x3f));
        out += char(0x80 | ((code >> 6) & 0x3f)), out += char(0x80 | (code & 0x3f));
      }
    } else {
      return false;
    }
    i = semi;
  }
  return true;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::vector<PickedPoint> read_pickpoints_file(const std::string& path) {
  std::string text;
  {
    const detail::InputFile in = detail::open_input_file(path, "the PickPoints file");
    text.resize(size_t(in.size()));
    if (!text.empty() && std::fread(text.data(), 1, text.size(), in.get()) != text.size())
      throw Error("cannot read '" + path + "': " + std::strerror(errno));
  }
  auto fail = [&](size_t at, const std::string& what) -> void {
    const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + std::min(at, text.size()), '\n'));
    throw Error("'" + path + "', line " + std::to_string(line) + ": " + what);
  };

  std::vector<PickedPoint> points;
  bool root = false;
  std::map<std::string, size_t> seen;
  for (size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i)) {
    if (text.compare(i, 4, "<!--") == 0) {
      const size_t e = text.find("-->", i + 4);
      if (e == std::string::npos) fail(i, "unterminated XML comment");
      i = e + 3;
      continue;
    }
    // The tag's end: the first '>' outside a quoted attribute value.
    size_t e = i + 1;
    char quote = 0;
    for (; e < text.size(); ++e) {
      if (quote) {
        if (text[e] == quote) quote = 0;
      } else if (text[e] == '"' || text[e] == '\'') {
        quote = text[e];
      } else if (text[e] == '>') {
        break;
      } else if (text[e] == '<') {
        fail(e, "malformed XML: '<' inside a tag");
      }
    }
    if (e >= text.size()) fail(i, "malformed XML: unterminated tag or attribute value");
    const std::string tag = text.substr(i + 1, e - i - 1);
    const size_t tag_at = i;
    i = e + 1;
    size_t k = 0;
    while (k < tag.size() && !is_space(tag[k]) && tag[k] != '/') ++k;
    const std::string element = tag.substr(0, k);
    if (element == "PickedPoints") root = true;
    if (element != "point") continue;
    if (!root) fail(tag_at, "a <point> outside the <PickedPoints> root element: not a MeshLab PickPoints file");
    std::map<std::string, std::string> attr;
    while (true) {
      while (k < tag.size() && is_space(tag[k])) ++k;
      if (k >= tag.size() || tag[k] == '/') break;
      const size_t name_at = k;
      while (k < tag.size() && !is_space(tag[k]) && tag[k] != '=') ++k;
      const std::string key = tag.substr(name_at, k - name_at);
      while (k < tag.size() && is_space(tag[k])) ++k;
      if (k >= tag.size() || tag[k] != '=') fail(tag_at, "malformed XML: attribute '" + key + "' has no value");
      ++k;
      while (k < tag.size() && is_space(tag[k])) ++k;
      if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\''))
        fail(tag_at, "malformed XML: the value of attribute '" + key + "' is not quoted");
      const char q = tag[k];
      const size_t close = tag.find(q, k + 1);
      std::string value;
      if (!decode_entities(tag.substr(k + 1, close - k - 1), value))
        fail(tag_at, "malformed XML: bad character reference in attribute '" + key + "'");
      attr[key] = value;
      k = close + 1;
    }
    PickedPoint p;
    if (!attr.count("name")) fail(tag_at, "a <point> without a name attribute");
    p.name = attr["name"];
    const char* axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      if (!attr.count(axis[a])) fail(tag_at, "point '" + p.name + "' has no " + axis[a] + " attribute");
      const std::string& v = attr[axis[a]];
      double x = 0;
      const char* b = v.data();
      while (b < v.data() + v.size() && is_space(*b)) ++b;
      if (b < v.data() + v.size() && *b == '+') ++b;
      const auto r = std::from_chars(b, v.data() + v.size(), x);
      const char* rest = r.ptr;
      while (rest < v.data() + v.size() && is_space(*rest)) ++rest;
      if (r.ec != std::errc() || rest != v.data() + v.size() || !std::isfinite(x))
        fail(tag_at, "point '" + p.name + "': " + axis[a] + " = '" + v + "' is not a finite number");
      p.xyz[a] = x;
    }
    p.active = !(attr.count("active") && attr["active"] == "0");
    if (p.active && !seen.emplace(p.name, points.size()).second)
      fail(tag_at, "two active points are named '" + p.name + "': landmarks are matched by name");
    points.push_back(p);
  }
  if (!root) throw Error("'" + path + "': not a MeshLab PickPoints file (no <PickedPoints> element)");
  return points;
}

LandmarkPairs landmark_pairs(const std::string& source_path, const std::string& target_path, size_t min_pairs) {
  const std::vector<PickedPoint> s = read_pickpoints_file(source_path), t = read_pickpoints_file(target_path);
  std::map<std::string, std::array<double, 3>> by_name;
  for (const PickedPoint& p : t)
    if (p.active) by_name[p.name] = p.xyz;
  LandmarkPairs pairs;
  std::string unmatched;
  size_t active = 0;
  for (const PickedPoint& p : s) {
    if (!p.active) continue;
    ++active;
    const auto it = by_name.find(p.name);
    if (it == by_name.end()) {
      unmatched += (unmatched.empty() ? "'" : ", '") + p.name + "'";
      continue;
    }
    pairs.names.push_back(p.name);
    pairs.source.push_back(p.xyz);
    pairs.target.push_back(it->second);
  }
  if (pairs.names.size() < min_pairs)
    throw Error("landmarks: only " + std::to_string(pairs.names.size()) + " of the " + std::to_string(active) +
                " active points of '" + source_path + "' have a namesake among the " + std::to_string(by_name.size()) +
                " of '" + target_path + "', at least " + std::to_string(min_pairs) + " are needed" +
                (unmatched.empty() ? std::string() : " (unmatched: " + unmatched + ")"));
  return pairs;
}

}  // namespace slicereuse
