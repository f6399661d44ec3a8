#include "support_sweep.h"

#include <chrono>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>

#include "family.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printfiles/check_print_file.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/member_supports.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "support_checks.h"
#include "support_tree_checks.h"

namespace slicereuse::test {
namespace {

// Uniform in [lo, hi] on a grid of 1 / per: an integer over per, as the printed text reads back.
double draw(std::mt19937_64& rng, double lo, double hi, double per) {
  const double u = double(rng() >> 11) * 0x1.0p-53;
  return (std::round(lo * per) + std::round(u * (hi - lo) * per)) / per;
}

double lit_mm3(const StackSupport& s, const PrinterProfile& p, double thickness) {
  const double lit = double(std::accumulate(s.lit.begin(), s.lit.end(), size_t(0)));
  return lit * p.pixel_size_x_um * p.pixel_size_y_um * 1e-6 * thickness;
}

}  // namespace

SweepPart random_sweep_part(uint64_t seed, size_t index) {
  std::seed_seq seq{uint32_t(seed), uint32_t(seed >> 32), uint32_t(index), uint32_t(index >> 32)};
  std::mt19937_64 rng(seq);
  SweepPart p;
  p.shape = family_shapes()[rng() % family_shapes().size()];
  p.family_seed = 1 + rng() % 1000;
  p.member = 1 + int(rng() % 3);
  p.tilt_deg = draw(rng, 0, 90, 2);
  p.critical_angle_deg = draw(rng, 10, 80, 2);
  p.density = draw(rng, 0.5, 3, 20);
  p.height_mm = draw(rng, 6, 12, 2);
  return p;
}

std::string sweep_part_text(const SweepPart& p) {
  return format("%s %llu %d %g %g %g %g %zu", p.shape.c_str(), (unsigned long long)p.family_seed, p.member,
                p.tilt_deg, p.critical_angle_deg, p.density, p.height_mm, p.faces);
}

SweepPart sweep_part_from_text(const std::string& text) {
  std::istringstream in(text);
  SweepPart p;
  std::string rest;
  if (!(in >> p.shape >> p.family_seed >> p.member >> p.tilt_deg >> p.critical_angle_deg >> p.density >>
        p.height_mm >> p.faces) ||
      (in >> rest))
    throw Error("not a sweep part: '" + text +
                "' (want: shape family_seed member tilt_deg critical_angle_deg density height_mm faces)");
  return p;
}

Mesh make_sweep_part(const SweepPart& p) {
  FamilyOptions o;
  o.shape = p.shape;
  o.faces = p.faces;
  o.height = p.height_mm;
  o.seed = p.family_seed;
  const Mesh base = make_family_base(o);
  Mesh m = make_family_member(base, o, p.member);
  FamilyTilt(base, p.tilt_deg).apply(m);
  // Centred on the display, its lowest vertex on the job's first plane (a member's turn may dip
  // below the base's).
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t v = 0; v < m.vertices(); ++v)
    for (int k = 0; k < 3; ++k) lo[k] = std::fmin(lo[k], m.V[3 * v + k]), hi[k] = std::fmax(hi[k], m.V[3 * v + k]);
  const double shift[3] = {-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]};
  for (size_t v = 0; v < m.vertices(); ++v)
    for (int k = 0; k < 3; ++k) m.V[3 * v + k] += shift[k];
  return m;
}

SweepFindings check_sweep_part(const SweepPart& part, double thickness, const std::string& folder, bool resin) {
  const auto start = std::chrono::steady_clock::now();
  SweepFindings f;
  try {
    const std::vector<Mesh> placed{make_sweep_part(part)};
    SliceOptions so;
    so.thickness = thickness;
    so.z_start = 0;
    MemberSupportOptions mo;
    mo.points.critical_angle_deg = part.critical_angle_deg;
    mo.points.density_relative = part.density;
    const MemberSupports s = make_member_supports(placed[0], slice_layers(placed[0], so), 0, thickness, mo);
    f.points = s.points.size();
    f.pillars = s.tree.pillars;
    f.on_part = s.tree.on_part;
    f.up_facing = s.tree.up_facing;

    const TreeSections t = check_tree_sections(placed[0], s.tree, thickness);
    f.outside_zones_mm2 = t.outside_zones_mm2;
    f.outside_zones_xyz[0] = t.outside_zones_xy[0], f.outside_zones_xyz[1] = t.outside_zones_xy[1];
    f.outside_zones_xyz[2] = t.outside_zones_z;
    f.support_islands = t.support_islands;
    f.support_island_layer = t.first_support_island_layer;
    const FeetOnPart feet = check_feet_on_part(placed[0], s.tree, mo.tree);
    f.feet = feet.feet;
    f.feet_in_air = feet.in_air;
    f.foot_off_mm = feet.farthest_mm;

    // The SL1S preset (anti-aliased, as PrusaSlicer writes it: binary masks add 1-pixel islands
    // on sloped walls, the part's alone), its display cropped to a square around the part 5 mm
    // wider each way than it (the bases reach 1.5 mm beyond a head), in hundreds of pixels, so
    // that the checks read a fraction of its pixels; a crop too small shows as pixels touching
    // its bounds, an error.
    PrinterProfile profile = printer_preset("prusa_sl1s_speed").profile;
    double reach = 0;
    for (size_t v = 0; v < placed[0].vertices(); ++v)
      reach = std::fmax(reach, std::fmax(std::fabs(placed[0].V[3 * v]), std::fabs(placed[0].V[3 * v + 1])));
    const double pixel_mm = std::fmin(profile.pixel_size_x_um, profile.pixel_size_y_um) / 1000;
    profile.width_px = profile.height_px = f.display_px = 100 * int(std::ceil(2 * (reach + 5) / pixel_mm / 100));
    PlateJobOptions job;
    job.slicing = so;
    job.supports = {&s.tree.mesh};
    job.layers_below = s.layers_below;
    const std::string supported = folder + "/supported.sl1s";
    f.layers = export_plate(placed, job, profile, supported).layers;
    const PrintabilityReport r = check_print_file(supported, profile.pixel_size_x_um / 1000,
                                                  profile.pixel_size_y_um / 1000, thickness,
                                                  folder + "/printability.csv");
    f.islands = r.count(FindingKind::Island);
    f.resin_traps = r.count(FindingKind::ResinTrap);
    if (r.count(FindingKind::TouchingBounds) > 0)
      throw Error(format("the part and its supports reach the edge of the %g x %g mm display",
                         profile.width_px * profile.pixel_size_x_um / 1000,
                         profile.height_px * profile.pixel_size_y_um / 1000));
    const StackSupport stack = check_stack_support(supported, profile);
    f.far_mm = stack.max_distance_mm;
    f.far_layer = stack.max_distance_layer;
    f.supported_mm3 = lit_mm3(stack, profile, thickness);
    if (resin) {
      PlateJobOptions alone;
      alone.slicing = so;
      profile.elephant_foot_mm = 0;  // the supported stack's first layer is the pad's
      export_plate(placed, alone, profile, folder + "/alone.sl1s");
      f.part_mm3 = lit_mm3(check_stack_support(folder + "/alone.sl1s", profile), profile, thickness);
    }
  } catch (const std::exception& e) {
    f.error = e.what();
  }
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return f;
}

const std::vector<std::string>& sweep_properties() {
  static const std::vector<std::string> names{"error", "island", "resin trap", "far reach", "foot in air",
                                              "pillar into part"};
  return names;
}

std::vector<std::string> failed_properties(const SweepFindings& f) {
  const bool failed[] = {!f.error.empty(),
                         f.islands > 0,
                         f.resin_traps > 0,
                         !(f.far_mm <= 1.0),
                         f.feet_in_air > 0 || f.support_islands > 0,
                         f.outside_zones_mm2 >= 1e-9};
  std::vector<std::string> out;
  for (size_t i = 0; i < sweep_properties().size(); ++i)
    if (failed[i] && (i == 0 || f.error.empty())) out.push_back(sweep_properties()[i]);
  return out;
}

}  // namespace slicereuse::test
