#pragma once
// PickPoints files (.pp): the landmarks a person picks in MeshLab's "PickPoints" editor, an XML
// document
//   <!DOCTYPE PickedPoints>
//   <PickedPoints>
//    <DocumentData> ... </DocumentData>
//    <point x="1.5" y="-2" z="0.25" active="1" name="tip"/>
//    ...
//   </PickedPoints>
// Attributes come in any order; active="0" marks a point the user unchecked, any other value
// or no active attribute (files from older MeshLab versions) an active one.
//
// read_pickpoints_file: every <point> child of the <PickedPoints> root, in file order. The XML is
// parsed by pugixml (as UTF-8, what MeshLab writes). Throws Error naming the file (and the line)
// for a missing or unreadable file, malformed XML (pugixml's reason in words: an unterminated tag
// or attribute value, a missing end tag, ...), a root element other than <PickedPoints>, a point
// without x, y, z or name, a coordinate that is not a finite number, or two active points with
// the same name.
// landmark_pairs: the active points of two files matched by name, in the source file's order;
// throws Error when fewer than min_pairs names match, listing the counts and the unmatched names.
#include <array>
#include <string>
#include <vector>

namespace slicereuse {

struct PickedPoint {
  std::string name;
  std::array<double, 3> xyz{};
  bool active = true;
};

std::vector<PickedPoint> read_pickpoints_file(const std::string& path);

struct LandmarkPairs {
  std::vector<std::string> names;
  std::vector<std::array<double, 3>> source, target;
};

LandmarkPairs landmark_pairs(const std::string& source_path, const std::string& target_path, size_t min_pairs = 3);

}  // namespace slicereuse
