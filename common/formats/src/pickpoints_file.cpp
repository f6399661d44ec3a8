#include "slicereuse/formats/pickpoints_file.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>

#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"

namespace slicereuse {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// A coordinate: a finite number, blanks around it and a leading '+' allowed (what QString's
// toDouble, MeshLab's own reader, accepts).
bool parse_coordinate(const char* b, const char* e, double& x) {
  while (b < e && is_space(*b)) ++b;
  if (b < e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, x);
  const char* rest = r.ptr;
  while (rest < e && is_space(*rest)) ++rest;
  return r.ec == std::errc() && rest == e && std::isfinite(x);
}

}  // namespace

std::vector<PickedPoint> read_pickpoints_file(const std::string& path) {
  std::string text;
  {
    const detail::InputFile in = detail::open_input_file(path, "the PickPoints file");
    text.resize(size_t(in.size()));
    if (!text.empty() && std::fread(text.data(), 1, text.size(), in.get()) != text.size())
      throw Error("cannot read '" + path + "': " + std::strerror(errno));
  }
  // at: a byte offset into the file (pugixml's offsets are into its copy of text, which is
  // byte for byte the file because it is parsed as UTF-8, as MeshLab writes it).
  auto fail = [&](ptrdiff_t at, const std::string& what) -> void {
    const size_t end = std::min(size_t(std::max<ptrdiff_t>(at, 0)), text.size());
    const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + ptrdiff_t(end), '\n'));
    throw Error("'" + path + "', line " + std::to_string(line) + ": " + what);
  };

  pugi::xml_document doc;
  const pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    std::string why = parsed.description();  // "Error parsing element attribute", ...
    if (!why.empty()) why[0] = char(std::tolower(static_cast<unsigned char>(why[0])));
    fail(parsed.offset, "malformed XML: " + why);
  }
  const pugi::xml_node root = doc.document_element();
  if (std::strcmp(root.name(), "PickedPoints") != 0)
    throw Error("'" + path + "': not a MeshLab PickPoints file (its root element is <" + root.name() +
                ">, not <PickedPoints>)");

  std::vector<PickedPoint> points;
  std::map<std::string, size_t> seen;
  for (const pugi::xml_node node : root.children("point")) {
    const ptrdiff_t at = node.offset_debug();
    PickedPoint p;
    const pugi::xml_attribute name = node.attribute("name");
    if (!name) fail(at, "a <point> without a name attribute");
    p.name = name.value();
    const char* axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      const pugi::xml_attribute c = node.attribute(axis[a]);
      if (!c) fail(at, "point '" + p.name + "' has no " + axis[a] + " attribute");
      const char* v = c.value();
      if (!parse_coordinate(v, v + std::strlen(v), p.xyz[a]))
        fail(at, "point '" + p.name + "': " + axis[a] + " = '" + v + "' is not a finite number");
    }
    p.active = std::strcmp(node.attribute("active").value(), "0") != 0;
    if (p.active && !seen.emplace(p.name, points.size()).second)
      fail(at, "two active points are named '" + p.name + "': landmarks are matched by name");
    points.push_back(p);
  }
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
