#include "slicereuse/supports/member_supports.h"

#include <chrono>

#include "slicereuse/util/seconds_since.h"

namespace slicereuse {

MemberSupports make_member_supports(const Mesh& part, const Slices& part_slicing, double z_start, double thickness,
                                    const MemberSupportOptions& options, const SupportPoints* source,
                                    const SurfaceMap* map, const Progress& progress) {
  MemberSupports s;
  SupportPointOptions point_options = options.points;
  // A part raised off the plate rests on its supports from its first layer on.
  point_options.raised = options.tree.object_elevation_mm > 0;
  point_options.head_front_diameter_mm = options.tree.head_front_diameter_mm;
  auto t = std::chrono::steady_clock::now();
  const Progress points_progress = sub_progress(progress, 0, 0.9);
  if (source) {
    s.points = transfer_support_points(*source, part, part_slicing, point_options, &s.transfer, map, points_progress);
    s.transferred = true;
  } else {
    s.points = generate_support_points(part, part_slicing, point_options, nullptr, points_progress);
  }
  s.kept_out = drop_points_in(s.points, options.keep_out, 0.5 * options.tree.head_front_diameter_mm);
  s.points_seconds = seconds_since(t);
  report_progress(progress, 0.9, "building the support tree");
  t = std::chrono::steady_clock::now();
  s.layers_below = support_layers_below(options.tree, thickness);
  s.tree = build_support_tree(part, s.points, support_ground_z(z_start, thickness, options.tree),
                              options.tree);
  s.tree_seconds = seconds_since(t);
  return s;
}

}  // namespace slicereuse
