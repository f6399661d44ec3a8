#include "slicereuse/plates/placements_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>

#include "slicereuse/plates/plate_file_names.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/input_file.h"
#include "slicereuse/util/json_value.h"

namespace slicereuse {
namespace {

constexpr const char* kFormat = "slicereuse placements";
constexpr int kVersion = 1;

double finite(const detail::JsonValue& v, const std::string& where) {
  const double x = v.as_number(where);
  if (!std::isfinite(x)) throw Error(where + " is not a finite number");
  return x;
}

}  // namespace

PlacementsFile placements_of(const Arrangement& a, const std::vector<std::string>& names, double spacing_mm,
                             const Platform& platform, const std::vector<std::string>& outputs) {
  PlacementsFile f;
  f.spacing_mm = spacing_mm;
  f.platform = platform;
  for (size_t k = 0; k < a.members.size(); ++k) {
    PlateRecord r;
    for (size_t m : a.members[k]) {
      r.names.push_back(names.at(m));
      r.placements.push_back(a.placement.at(m));
    }
    r.area_used = a.area_used.at(k);
    if (k < outputs.size()) r.output = outputs[k];
    f.plates.push_back(std::move(r));
  }
  return f;
}

Arrangement arrangement_of(const PlacementsFile& file, const std::vector<std::string>& names, size_t plate) {
  if (plate > file.plates.size())
    throw Error(format("the placements have %zu plate%s: there is no plate %zu", file.plates.size(),
                       file.plates.size() == 1 ? "" : "s", plate));
  std::map<std::string, size_t> index;
  for (size_t m = 0; m < names.size(); ++m)
    if (!index.emplace(names[m], m).second) throw Error("two members are named '" + names[m] + "'");
  Arrangement a;
  a.placement.resize(names.size());
  a.plate.assign(names.size(), SIZE_MAX);
  const size_t first = plate ? plate - 1 : 0, end = plate ? plate : file.plates.size();
  for (size_t k = first; k < end; ++k) {
    a.members.emplace_back();
    for (size_t i = 0; i < file.plates[k].names.size(); ++i) {
      const std::string& name = file.plates[k].names[i];
      const auto it = index.find(name);
      if (it == index.end())
        throw Error(format("the placements place member '%s' (plate %zu), which is not among the members given",
                           name.c_str(), k + 1));
      if (a.plate[it->second] != SIZE_MAX) throw Error("the placements place member '" + name + "' twice");
      a.plate[it->second] = k - first;
      a.placement[it->second] = file.plates[k].placements[i];
      a.members.back().push_back(it->second);
    }
    a.area_used.push_back(file.plates[k].area_used);
  }
  for (size_t m = 0; m < names.size(); ++m)
    if (a.plate[m] == SIZE_MAX)
      throw Error(plate ? format("the placements do not place member '%s' on plate %zu", names[m].c_str(), plate)
                        : "the placements do not place member '" + names[m] + "'");
  return a;
}

void write_placements_file(const std::string& path, const PlacementsFile& f) {
  // Ordered: the keys stay in the order docs/formats.md shows them.
  using Json = nlohmann::ordered_json;
  Json plates = Json::array();
  for (size_t k = 0; k < f.plates.size(); ++k) {
    const PlateRecord& r = f.plates[k];
    Json members = Json::array();
    for (size_t i = 0; i < r.names.size(); ++i) {
      const Placement& p = r.placements[i];
      members.push_back({{"name", r.names[i]}, {"theta_deg", p.theta_deg}, {"tx_mm", p.tx_mm}, {"ty_mm", p.ty_mm}});
    }
    // The layout picture's name beside the print file's, so a reader need not make it up.
    const std::string layout = r.output.empty() ? "" : plate_layout_file_name(r.output);
    plates.push_back({{"plate", k + 1},
                      {"area_used", r.area_used},
                      {"output", r.output},
                      {"layout", layout},
                      {"members", std::move(members)}});
  }
  const Json platform = {{"x0", f.platform.x0}, {"y0", f.platform.y0}, {"x1", f.platform.x1}, {"y1", f.platform.y1}};
  const Json doc = {{"format", kFormat},
                    {"version", kVersion},
                    {"spacing_mm", f.spacing_mm},
                    {"platform_mm", platform},
                    {"plates", std::move(plates)}};
  std::string s;
  try {
    s = doc.dump(2) + "\n";
  } catch (const nlohmann::json::type_error&) {  // dump's one refusal: a string that is not UTF-8
    throw Error("cannot write the placements file '" + path + "': a member's name or a plate's output is not UTF-8 text");
  }
  AtomicFile out(path);
  out.write(s.data(), s.size());
  out.commit();
}

PlacementsFile read_placements_file(const std::string& path) {
  const detail::InputFile in = detail::open_input_file(path, "placements file");
  std::string text(in.size(), '\0');
  if (!text.empty() && std::fread(text.data(), 1, text.size(), in.get()) != text.size())
    throw Error("cannot read the placements file '" + path + "'");
  const detail::JsonValue doc = detail::parse_json(text, path);
  const std::string file = "the placements file '" + path + "'";
  if (doc.at("format", file).as_string(file + "'s format") != kFormat)
    throw Error(file + " is not a slicereuse placements file (its \"format\" is not \"" + kFormat + "\")");
  const double version = doc.at("version", file).as_number(file + "'s version");
  if (version != kVersion) throw Error(format("%s has version %g; this reader knows version %d", file.c_str(), version, kVersion));
  PlacementsFile f;
  f.spacing_mm = finite(doc.at("spacing_mm", file), file + "'s spacing_mm");
  const detail::JsonValue& pf = doc.at("platform_mm", file);
  f.platform = {finite(pf.at("x0", file + "'s platform_mm"), "platform_mm x0"),
                finite(pf.at("y0", file + "'s platform_mm"), "platform_mm y0"),
                finite(pf.at("x1", file + "'s platform_mm"), "platform_mm x1"),
                finite(pf.at("y1", file + "'s platform_mm"), "platform_mm y1")};
  const auto& plates = doc.at("plates", file).as_array(file + "'s plates");
  for (size_t k = 0; k < plates.size(); ++k) {
    const std::string where = format("%s, plate %zu", file.c_str(), k + 1);
    PlateRecord r;
    const detail::JsonValue& plate = plates[k];
    r.area_used = finite(plate.at("area_used", where), where + "'s area_used");
    if (const detail::JsonValue* o = plate.find("output")) r.output = o->as_string(where + "'s output");
    const auto& members = plate.at("members", where).as_array(where + "'s members");
    if (members.empty()) throw Error(where + " has no members");
    for (size_t i = 0; i < members.size(); ++i) {
      const std::string mw = format("%s, member %zu", where.c_str(), i + 1);
      const detail::JsonValue& m = members[i];
      r.names.push_back(m.at("name", mw).as_string(mw + "'s name"));
      r.placements.push_back({finite(m.at("theta_deg", mw), mw + "'s theta_deg"),
                              finite(m.at("tx_mm", mw), mw + "'s tx_mm"), finite(m.at("ty_mm", mw), mw + "'s ty_mm")});
    }
    f.plates.push_back(std::move(r));
  }
  return f;
}

}  // namespace slicereuse
