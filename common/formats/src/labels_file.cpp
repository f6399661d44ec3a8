#include "slicereuse/formats/labels_file.h"

#include <filesystem>
#include <fstream>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b + 1 - a);
}

std::string stem(const std::string& name) { return std::filesystem::path(name).stem().string(); }

}  // namespace

LabelsFile read_labels_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(format("cannot read the labels file '%s': it does not exist or cannot be opened", path.c_str()));
  LabelsFile f;
  f.path = path;
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (trimmed(line).empty()) continue;
    const size_t comma = line.find(',');
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos)
      throw Error(format("labels file '%s', line %zu: '%s' is not two fields, a member and its label, parted by one ','",
                         path.c_str(), number, trimmed(line).c_str()));
    const std::string member = trimmed(line.substr(0, comma)), label = trimmed(line.substr(comma + 1));
    if (f.rows.empty() && member == "member" && label == "label") continue;  // the header
    if (member.empty() || label.empty())
      throw Error(format("labels file '%s', line %zu: the %s is empty", path.c_str(), number,
                         member.empty() ? "member" : "label"));
    for (const auto& [other, _] : f.rows)
      if (stem(other) == stem(member))
        throw Error(format("labels file '%s', line %zu: member '%s' is listed twice (also as '%s')", path.c_str(),
                           number, member.c_str(), other.c_str()));
    f.rows.emplace_back(member, label);
  }
  if (in.bad()) throw Error(format("cannot read the labels file '%s': a read failed", path.c_str()));
  return f;
}

std::string label_of(const LabelsFile& file, const std::string& name) {
  for (const auto& [member, label] : file.rows)
    if (member == name || stem(member) == stem(name)) return label;
  throw Error(format("the labels file '%s' has no label for member '%s'", file.path.c_str(), name.c_str()));
}

}  // namespace slicereuse
