// gen_family: writes a mass-customization family (see family/family.h) as PLY files.
//   gen_family --shape {arch,ear,handle,box,sphere,torus} --faces N --members M
//              [--z-change | --z-band] [--shuffle] [--tilt DEG] --height MM --seed S --out DIR
// --z-change: z changes everywhere (ZChange::Everywhere); --z-band: only within one band of
// heights (ZChange::Band).
// --tilt: every member turned by DEG degrees about the x axis through the base's lowest point,
// as a lab orients a shell for printing (its overhangs then need supports); the same rigid turn
// for all, so the family keeps its faces and stands on the base's lowest height.
// writes DIR/member_000.ply (the base) ... and prints "path vertices faces" per file.
// --shuffle renumbers the vertices and reorders and rotates the faces of every member but the
// base (shuffle_mesh.h): the same surfaces with other connectivity in indices.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "family.h"
#include "flag_number.h"
#include "shapes.h"
#include "shuffle_mesh.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  try {
    test::FamilyOptions o;
    int members = 1;
    double tilt = 0;
    bool shuffle = false;
    std::string out;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--shuffle") {
        shuffle = true;
        continue;
      }
      if (a == "--z-change" || a == "--z-band") {
        o.z_change = a == "--z-change" ? test::ZChange::Everywhere : test::ZChange::Band;
        continue;
      }
      if (i + 1 >= argc) throw Error(a + ": missing value");
      const char* v = argv[++i];
      if (a == "--shape") o.shape = v;
      else if (a == "--faces") o.faces = test::flag_number<size_t>("--faces", v);
      else if (a == "--members") members = test::flag_number<int>("--members", v);
      else if (a == "--height") o.height = test::flag_number<double>("--height", v);
      else if (a == "--seed") o.seed = test::flag_number<uint64_t>("--seed", v);
      else if (a == "--tilt") tilt = test::flag_number<double>("--tilt", v);
      else if (a == "--out") out = v;
      else throw Error("unknown option " + a);
    }
    if (out.empty()) throw Error("--out DIR is required");
    if (members < 1 || members > 1000) throw Error("--members must be in 1..1000");
    std::filesystem::create_directories(out);
    const Mesh base = test::make_family_base(o);
    const test::FamilyTilt turn(base, tilt);
    for (int m = 0; m < members; ++m) {
      char name[32];
      std::snprintf(name, sizeof name, "member_%03d.ply", m);
      const std::string path = (std::filesystem::path(out) / name).string();
      Mesh member = test::make_family_member(base, o, m);
      if (tilt != 0) turn.apply(member);
      if (shuffle && m > 0) member = test::shuffle_mesh(member, o.seed * 1000 + uint64_t(m)).mesh;
      test::write_ply(path, member);
      std::printf("%s %zu %zu\n", path.c_str(), base.vertices(), base.faces());
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_family: %s\n", e.what());
    return 1;
  }
  return 0;
}
