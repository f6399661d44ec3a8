// support_sweep: the supports' property tests over many parts (issue #35, item 5; support_sweep.h),
// one JSON line per part on stdout, for bench/support_sweep.py (which adds PrusaSlicer's resin
// and prints the table).
//   support_sweep --parts N --seed S --out DIR [--thickness MM] [--resin] [--stl] [--keep]
//   support_sweep --part "shape family_seed member tilt critical density height faces" --out DIR ...
// --parts: random_sweep_part(S, 0 .. N-1); --part (repeatable): the parts as a line of the output
// gives them ("part"), to reproduce a failure. --resin: the supports' lit volume too (the part
// printed alone besides). --stl: each part also written as DIR/part_NNNN.stl (binary), for
// PrusaSlicer. Each part's print files and printability report (printability.csv) go to
// DIR/part_NNNN/, removed after its checks unless --keep.
// Exits 1 when an argument is wrong (in words), 0 otherwise, whatever the findings.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "flag_number.h"
#include "mesh_file_writers.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "support_sweep.h"

using namespace slicereuse;

namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (uint8_t(c) < 0x20) out += format("\\u%04x", unsigned(uint8_t(c)));
    else out += c;
  }
  return out + "\"";
}

// A number JSON reads (an infinite distance: no layer below to rest on, as null).
std::string json_number(double v) { return std::isfinite(v) ? format("%.9g", v) : "null"; }

}  // namespace

int main(int argc, char** argv) {
  try {
    size_t parts = 0;
    uint64_t seed = 1;
    double thickness = 0.05;
    bool resin = false, stl = false, keep = false;
    std::string out;
    std::vector<test::SweepPart> given;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--resin" || a == "--stl" || a == "--keep") {
        (a == "--resin" ? resin : a == "--stl" ? stl : keep) = true;
        continue;
      }
      if (i + 1 >= argc) throw Error(a + ": missing value");
      const char* v = argv[++i];
      if (a == "--parts") parts = test::flag_number<size_t>("--parts", v);
      else if (a == "--seed") seed = test::flag_number<uint64_t>("--seed", v);
      else if (a == "--thickness") thickness = test::flag_number<double>("--thickness", v);
      else if (a == "--part") given.push_back(test::sweep_part_from_text(v));
      else if (a == "--out") out = v;
      else throw Error("unknown option " + a);
    }
    if (out.empty()) throw Error("--out DIR is required");
    if (!(thickness > 0)) throw Error("--thickness must be positive");
    if (given.empty())
      for (size_t i = 0; i < parts; ++i) given.push_back(test::random_sweep_part(seed, i));
    for (size_t i = 0; i < given.size(); ++i) {
      const test::SweepPart& p = given[i];
      const std::string folder = out + format("/part_%04zu", i);
      std::filesystem::create_directories(folder);
      std::string stl_path;
      if (stl) {
        stl_path = out + format("/part_%04zu.stl", i);
        test::write_mesh_file(stl_path, test::make_sweep_part(p), test::MeshFileKind::StlBinary);
      }
      const test::SweepFindings f = test::check_sweep_part(p, thickness, folder, resin);
      if (!keep) std::filesystem::remove_all(folder);
      std::string failed;
      for (const std::string& name : test::failed_properties(f))
        failed += (failed.empty() ? "" : ", ") + json_string(name);
      std::printf(
          "{\"index\": %zu, \"part\": %s, \"shape\": %s, \"tilt\": %g, \"critical_angle\": %g, \"density\": %g, "
          "\"thickness\": %g, \"display_px\": %d, \"stl\": %s, \"failed\": [%s], \"error\": %s, \"layers\": %zu, "
          "\"points\": %zu, \"pillars\": %zu, \"on_part\": %zu, \"up_facing\": %zu, \"islands\": %zu, "
          "\"resin_traps\": %zu, \"far_mm\": %s, \"far_layer\": %zu, \"feet\": %zu, \"feet_in_air\": %zu, "
          "\"foot_off_mm\": %s, \"support_islands\": %zu, \"support_island_layer\": %zu, \"outside_zones_mm2\": %s, "
          "\"outside_zones_xyz\": [%s, %s, %s], \"supported_mm3\": %s, \"part_mm3\": %s, \"seconds\": %.3f}\n",
          i, json_string(test::sweep_part_text(p)).c_str(), json_string(p.shape).c_str(), p.tilt_deg,
          p.critical_angle_deg, p.density, thickness, f.display_px, stl ? json_string(stl_path).c_str() : "null",
          failed.c_str(), json_string(f.error).c_str(), f.layers, f.points, f.pillars, f.on_part, f.up_facing,
          f.islands, f.resin_traps, json_number(f.far_mm).c_str(), f.far_layer, f.feet, f.feet_in_air,
          json_number(f.foot_off_mm).c_str(), f.support_islands, f.support_island_layer,
          json_number(f.outside_zones_mm2).c_str(), json_number(f.outside_zones_xyz[0]).c_str(),
          json_number(f.outside_zones_xyz[1]).c_str(), json_number(f.outside_zones_xyz[2]).c_str(),
          json_number(f.supported_mm3).c_str(),
          resin ? json_number(f.part_mm3).c_str() : "null", f.seconds);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "support_sweep: %s\n", e.what());
    return 1;
  }
  return 0;
}
