#pragma once
// member_supports: one part's supports, everything a print job needs: its support points
// (generated on the part, or a family source's transferred onto it, certified and completed:
// transfer_support_points.h) and the structure built from them (support_tree.h), standing on
// the ground the job's layers give (support_ground_z), in the part's own frame.
//
// Input: the part, its slicing on the job's planes (xyz and encoding: slice_layers, or the
// contours transferred from the source's encoding, which keep its encoding), the job's z_start
// (its planes' bottom) and thickness, and optionally the source's points (and, for a member of
// another connectivity, the map from the source).
// Output: the points (less those options.keep_out drops), how the transfer went (all zero when generated), the tree, the layers
// the job gains below z_start, and the seconds each step took.
#include <cstddef>

#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_keep_out.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/supports/support_tree.h"
#include "slicereuse/supports/transfer_support_points.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct MemberSupportOptions {
  SupportPointOptions points;
  SupportTreeOptions tree;
  // What the heads keep clear of (the part's drain holes): points whose head would reach into
  // one are dropped before the tree is built (support_keep_out.h).
  std::vector<KeepOutCylinder> keep_out;
};

struct MemberSupports {
  SupportPoints points;
  SupportTransferStats transfer;  // zero when generated on the part
  bool transferred = false;
  SupportTree tree;
  size_t layers_below = 0;
  size_t kept_out = 0;  // points dropped for options.keep_out
  double points_seconds = 0, tree_seconds = 0;
};

MemberSupports make_member_supports(const Mesh& part, const Slices& part_slicing, double z_start, double thickness,
                                    const MemberSupportOptions& options, const SupportPoints* source = nullptr,
                                    const SurfaceMap* map = nullptr, const Progress& progress = {});

}  // namespace slicereuse
