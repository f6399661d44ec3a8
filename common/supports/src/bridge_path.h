#pragma once
// bridge_path: whether a bridge (a cylinder of radius between two points, the upper one first)
// is clear of the part, by vertical rays (PartColumns): along the bridge every kBridgeStepMm,
// on its axis and at half and the whole of radius + kRimClearanceMm to either side, none may
// meet the part within the height the cylinder grown by kRimClearanceMm spans there (between
// the bridge's ends' heights), nor run inside it there (PartColumns::inside: the part's walls,
// which vertical rays never meet, may surround it). The surface between two rays may come
// nearer, as between a pillar's rim rays. part must keep all the part's faces. The bridge must
// descend (upper z > lower z) and run sideways.
#include "part_columns.h"
#include "slicereuse/supports/support_structure.h"

namespace slicereuse {

constexpr double kBridgeStepMm = 0.25;

bool bridge_is_clear(const PartColumns& part, const Point3& upper, const Point3& lower, double radius);

}  // namespace slicereuse
