#pragma once
// Labels files: which label each member carries (#36), a CSV of two columns
//   member,label
//   arch_member_001.stl,CASE-0412
//   arch_member_002,CASE-0413
// A member is named by its file name or its stem (the name without its last extension), as the
// jobs name members; an optional first row "member,label" is a header. Fields are not quoted;
// spaces around them are dropped; empty lines are skipped.
//
// read_labels_file: the rows, in file order. Throws Error naming the file (and the line) for a
// missing or unreadable file, a row without exactly two fields, an empty member or label, or a
// member listed twice.
// label_of: the label of the member named `name` (a file name or stem, matched either way), or
// throws Error naming the file and the member when it has none.
#include <string>
#include <utility>
#include <vector>

namespace slicereuse {

struct LabelsFile {
  std::string path;
  std::vector<std::pair<std::string, std::string>> rows;  // member, label
};

LabelsFile read_labels_file(const std::string& path);
std::string label_of(const LabelsFile& file, const std::string& name);

}  // namespace slicereuse
