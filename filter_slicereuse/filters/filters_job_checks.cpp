// The printability checks Make Print Job and Make Plate Job run on their masks as they write
// them, and what they report of them.
#include <array>

#include "filters_common.h"
#include "slicereuse/printability/printability_report.h"

namespace slicereuse::plugin {
namespace {

constexpr size_t kLoggedFindings = 20;  // per plate; the counts have them all

// The result's keys, by FindingKind.
constexpr std::array<const char*, kFindingKinds> kCountKeys = {"islands", "overhangs", "resin_traps", "suction_cups",
                                                               "touching_bounds"};

void add_count(Result& result, const std::string& key, size_t n) {
  const auto it = result.find(key);
  result[key] = int64_t(n) + (it == result.end() ? 0 : std::get<int64_t>(it->second));
}

}  // namespace

ParamList<JobChecks> job_check_params() {
  ParamList<JobChecks> l;
  l.flag(&JobChecks::check, "check_printability", "Check printability", true,
         "Check every layer's mask as it is written, as UVtools does with its default settings (islands, overhangs, "
         "resin traps, suction cups, parts touching the display's bounds), and report the findings per member. It "
         "costs a little time; see Check Printability for the definitions.")
      .flag(&JobChecks::require_printable, "require_printable", "Require printable", false,
            "Refuse a print file holding an island, a resin trap or a suction cup: the job fails naming each "
            "finding, its member and place, and nothing is written. Implies the check.");
  return l;
}

void set_job_checks(const JobChecks& c, PlateJobOptions& o) {
  o.check_printability = c.check || c.require_printable;
  o.require_printable = c.require_printable;
}

void report_printability(Host& host, const char* filter, const std::string& plate_label, const PlateJobStats& st,
                         const std::vector<std::string>& names, bool per_member, Result& result) {
  if (!st.checked) {  // counts of -1: not checked
    for (const char* key : kCountKeys) result.emplace(key, int64_t(-1));
    result.emplace("trapped_mm3", -1.0);
    return;
  }
  const PrintabilityReport& r = st.printability;
  const std::string where = plate_label.empty() ? "" : plate_label + ": ";
  std::vector<std::array<size_t, kFindingKinds>> member_counts(names.size(), std::array<size_t, kFindingKinds>{});
  size_t logged = 0;
  for (size_t i = 0; i < r.findings.size(); ++i) {
    const Finding& f = r.findings[i];
    const FindingPlace& at = st.finding_places[i];
    ++member_counts[at.member][size_t(f.kind)];
    if (!blocks_printing(f.kind) || logged++ >= kLoggedFindings) continue;
    const bool volume = f.kind != FindingKind::Island;
    host.log(format("%s: %s%s in %s, layers %zu-%zu, at (%.2f, %.2f) mm, %.2f x %.2f x %.2f mm, %.4g %s", filter,
                    where.c_str(), finding_kind_name(f.kind), names[at.member].c_str(), f.first_layer, f.last_layer,
                    at.x_mm + 0.0, at.y_mm + 0.0, f.size_mm[0], f.size_mm[1], f.size_mm[2],
                    volume ? f.volume_mm3 : f.area_mm2, volume ? "mm3" : "mm2"));
  }
  host.log(format("%s: %sprintability: %zu islands, %zu overhangs, %zu resin traps (%.4g mm3), %zu suction cups, "
                  "%zu touching the display's bounds",
                  filter, where.c_str(), r.count(FindingKind::Island), r.count(FindingKind::Overhang),
                  r.count(FindingKind::ResinTrap), r.trapped_mm3(), r.count(FindingKind::SuctionCup),
                  r.count(FindingKind::TouchingBounds)));
  for (size_t kind = 0; kind < kFindingKinds; ++kind) {
    add_count(result, kCountKeys[kind], r.counts[kind]);
    if (!per_member) continue;
    for (size_t m = 0; m < names.size(); ++m) add_count(result, std::string(kCountKeys[kind]) + "_" + names[m], member_counts[m][kind]);
  }
  const auto it = result.find("trapped_mm3");
  result["trapped_mm3"] = r.trapped_mm3() + (it == result.end() ? 0.0 : std::get<double>(it->second));
}

std::vector<std::string> with_printability_keys(std::vector<std::string> keys, bool per_member) {
  keys.insert(keys.end(), kCountKeys.begin(), kCountKeys.end());
  keys.push_back("trapped_mm3");
  if (per_member)
    for (const char* k : kCountKeys) keys.push_back(std::string(k) + "_*");
  return keys;
}

}  // namespace slicereuse::plugin
