#include "slicereuse/printability/printability_report.h"

#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

const char* finding_kind_name(FindingKind kind) {
  switch (kind) {
    case FindingKind::Island: return "island";
    case FindingKind::Overhang: return "overhang";
    case FindingKind::ResinTrap: return "resin_trap";
    case FindingKind::SuctionCup: return "suction_cup";
    case FindingKind::TouchingBounds: return "touching_bounds";
  }
  return "";
}

bool PrintabilityReport::blocks_printing() const {
  for (size_t kind = 0; kind < kFindingKinds; ++kind)
    if (counts[kind] > 0 && slicereuse::blocks_printing(FindingKind(kind))) return true;
  return false;
}

double PrintabilityReport::trapped_mm3() const {
  double v = 0;
  for (const Finding& f : findings)
    if (f.kind == FindingKind::ResinTrap) v += f.volume_mm3;
  return v;
}

void write_printability_csv(const PrintabilityReport& report, const std::string& path) {
  std::string text =
      "kind,first_layer,last_layer,x0,y0,x1,y1,center_x_mm,center_y_mm,center_z_mm,size_x_mm,size_y_mm,size_z_mm,"
      "area_mm2,volume_mm3\n";
  for (const Finding& f : report.findings)
    text += format("%s,%zu,%zu,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", finding_kind_name(f.kind),
                   f.first_layer, f.last_layer, f.x0, f.y0, f.x1, f.y1, f.center_mm[0], f.center_mm[1],
                   f.center_mm[2], f.size_mm[0], f.size_mm[1], f.size_mm[2], f.area_mm2, f.volume_mm3);
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace slicereuse
