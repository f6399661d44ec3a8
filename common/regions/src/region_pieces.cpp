#include "slicereuse/regions/region_pieces.h"

namespace slicereuse {

std::vector<ClipperLib::Paths> region_pieces(const ClipperLib::Paths& region) {
  ClipperLib::Clipper clipper;
  clipper.StrictlySimple(true);
  clipper.AddPaths(region, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<ClipperLib::Paths> pieces;
  for (const ClipperLib::PolyNode* n = tree.GetFirst(); n; n = n->GetNext()) {
    if (n->IsHole()) continue;
    ClipperLib::Paths piece{n->Contour};
    for (const ClipperLib::PolyNode* hole : n->Childs) piece.push_back(hole->Contour);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

}  // namespace slicereuse
