#pragma once
// What the filter implementations (filters_*.cpp) share; internal to the plugin. Each filter's
// file declares its parameters (filter_params.h), its spec and its run, and returns them as one
// FilterSpec; filter_specs() lists them.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "filter_api.h"
#include "filter_params.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/member_supports.h"
#include "slicereuse/transfer/encoding_cache.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/seconds_since.h"

namespace slicereuse::plugin {

FilterSpec slice_filter();
FilterSpec transfer_filter();
FilterSpec export_masks_filter();
FilterSpec compare_masks_filter();
FilterSpec print_job_filter();
FilterSpec cross_parameterize_filter();
FilterSpec free_cached_memory_filter();
FilterSpec plate_job_filter();
FilterSpec arrange_plates_filter();
FilterSpec generate_support_points_filter();
FilterSpec transfer_support_points_filter();
FilterSpec build_supports_filter();
FilterSpec check_printability_filter();
FilterSpec add_labels_filter();
FilterSpec hollow_mesh_filter();
FilterSpec add_drain_holes_filter();

// The method's reference, closing every description.
extern const char* const kReference;

// The printer (filters_display.cpp): a preset of printer_presets.h by its index, or custom
// (index = the number of presets, the default) with the given display and exposure; the offsets
// and anti-aliasing given apply to every printer. profile() refuses a preset given with display
// or exposure values other than their defaults (Error naming them).
inline const char* const kCustomPrinter = "custom";
// elephant_foot: the first layer's elephant-foot compensation in mm (fading over the faded
// layers, faded_layers.h), or kPrintersElephantFoot for the printer's own (its preset's, 0 for
// custom).
constexpr double kPrintersElephantFoot = -1;
struct PrinterSettings {
  size_t printer = 0;
  PrinterProfile given;
  double elephant_foot = kPrintersElephantFoot;
  PrinterProfile profile() const;
  std::string name() const;  // the preset's id, or "custom"

 private:
  PrinterProfile profile_before_elephant_foot() const;
};
// Its parameters ("printer", then the custom values bound to PrinterProfile, whose defaults they
// are), a log line saying which printer and image the masks are made for, the warning for a part
// that does not fit the display, and the display figures in a result (open contours ignored,
// outside_display, the part's extent in mm).
ParamList<PrinterSettings> printer_params();
void log_printer(Host& host, const char* filter, const PrinterSettings& settings);
void log_display_warning(Host& host, const char* filter, const MaskExportStats& stats,
                         const PrinterProfile& profile);
void add_display_figures(const MaskExportStats& stats, Result& result);
// keys and the keys add_display_figures adds, for a spec's results.
std::vector<std::string> with_display_keys(std::vector<std::string> keys);
// The output_path parameter of the filters that write print files (a folder of PNG images, or a
// file of one of print_formats()), bound to field; tooltip says what is written there, and the
// formats and their extensions follow it.
std::string print_file_patterns();                   // "*.sl1 *.sl1s *.goo ..."
std::string print_file_tooltip(const char* tooltip);  // tooltip, then "Print files: .sl1 (...), ..."
template <class P>
ParamList<P>& add_print_file_output(ParamList<P>& l, std::string P::*field, const char* tooltip) {
  return l.file(field, ParamType::FileSave, "output_path", "Output print file or folder",
                print_file_patterns().c_str(), "choose a folder, or a print file (.sl1, .ctb, ...)",
                print_file_tooltip(tooltip).c_str());
}

// How a print or plate job makes its members' layers (filters_job_layers.cpp): transferred
// from a source's encoding, or sliced directly at a layer thickness from z_start; a member of
// another family is sliced directly unless strict. The same parameters, names and tooltips in
// both filters; encoding_tooltip says what the encoding is transferred to.
struct JobLayers {
  std::string encoding_file;
  double layer_thickness;
  double z_start;
  bool strict;
};
ParamList<JobLayers> job_layer_params(const char* encoding_tooltip);
// The plate job's options for p (no members' names, budget or encoding yet): slicing options,
// strict, and a quarter of the available memory per range of layers.
PlateJobOptions plate_job_options(const JobLayers& p);

// Whether a print or plate job checks its masks as it writes them (UVtools' checks,
// check_layers.h; filters_job_checks.cpp), and whether it refuses a file holding an island, a
// resin trap or a suction cup (nothing written). The same parameters in both filters.
struct JobChecks {
  bool check;
  bool require_printable;
};
ParamList<JobChecks> job_check_params();
void set_job_checks(const JobChecks& c, PlateJobOptions& o);
// A checked plate's findings: logged (those that make a print fail, and a line of counts;
// plate_label names the plate, or is empty for a print job), and counted into result under
// islands, overhangs, resin_traps, suction_cups, touching_bounds and trapped_mm3 (summed with
// what is there), and, with per_member, the same counts per member as <key>_<member name>.
// Not checked: those totals are -1.
void report_printability(Host& host, const char* filter, const std::string& plate_label, const PlateJobStats& st,
                         const std::vector<std::string>& names, bool per_member, Result& result);
// keys and the result keys report_printability adds (with "_*" for the members' when per_member).
std::vector<std::string> with_printability_keys(std::vector<std::string> keys, bool per_member);

// Labels a print or plate job engraves into its members (filters_job_labels.cpp; #36): each
// member's name without its extension, or its label in a labels file (labels_file.h); the
// height, depth, the side (the base or one of four), and whether a member whose label fits nowhere is printed without it. The same
// parameters in both filters.
struct JobLabels {
  bool labels;
  std::string labels_file;
  double height_mm;
  double depth_mm;
  LabelSide side;
  bool allow_unlabelled;
};
ParamList<JobLabels> job_label_params();
// label_side's choices, in LabelSide's order, and its tooltip (the jobs' and Add Labels').
std::vector<std::string> label_side_names();
extern const char* const kLabelSideTooltip;
// The job's labels for its members (named `names`: file or layer names) into o; throws Error for
// a labels file that cannot be read or lacks a member, or a label the font cannot print.
void set_job_labels(const JobLabels& l, const std::vector<std::string>& names, PlateJobOptions& o);
// A labelled plate's labels logged (each member's text and height, or left off) and put into
// result as label_height_mm (0: unlabelled; -1 without labels), or per member as
// label_height_mm_<member name> (none without labels).
void report_labels(Host& host, const char* filter, const PlateJobOptions& o, const PlateJobStats& st,
                   const std::vector<std::string>& names, bool per_member, Result& result);
// Whether a print or plate job hollows its members (PrusaSlicer's hollowing, computed on the
// contours: cavity.h, plate_job.h; filters_job_hollowing.cpp): walls of wall_mm (0: solid) and
// PrusaSlicer's closing distance. The same parameters in both filters.
// hollowing_params: the cavity's (hollow_wall_mm, default default_wall_mm, and hollow_closing_mm),
// for the jobs (0: solid) and Hollow Mesh and Add Drain Holes (PrusaSlicer's 3 mm).
ParamList<HollowingOptions> hollowing_params(double default_wall_mm);
// The automatic drain holes' (drain_hole_mm, 0: none; drain_holes, how many per cavity).
struct DrainHoleParams {
  double diameter_mm;
  int per_cavity;
};
ParamList<DrainHoleParams> drain_hole_params();
// The jobs': the cavity, the holes, and the user's holes, a point layer (drain_points_layer, the
// host's reference of a layer of the first member's points; -1: none) or a file of them
// (drain_holes_file, a support-points file), which replace the automatic ones.
struct JobHollowing {
  HollowingOptions cavity;
  DrainHoleParams holes;
  int points_layer;
  std::string holes_file;
};
ParamList<JobHollowing> job_hollowing_params();
// Into o; the user's holes located on first (the job's first member): each point within
// kUserPointReachMm of its surface, or read from the file and checked (a point farther, or a file
// for other faces, or holes without hollowing, refused in words).
void set_job_hollowing(const JobHollowing& h, Host& host, const Mesh& first, PlateJobOptions& o);
// A hollowed plate's cavities: each member's logged (its volume and drain holes, or why it stays
// solid; plate_label names the plate, or is empty for a print job), and counted into result as
// cavity_mm3 and drain_holes (summed with what is there; 0 when solid) and, with per_member,
// cavity_mm3_<member name> and drain_holes_<member name>.
void report_hollowing(Host& host, const char* filter, const std::string& plate_label, const PlateJobStats& st,
                      const std::vector<std::string>& names, bool per_member, Result& result);

// The supports' parameters (filters_job_supports.cpp), declared once for the support filters and
// the jobs. How support points are placed: PrusaSlicer's critical angle, density (%) and minimal
// distance; the options for a part raised (elevation > 0) or not.
struct SupportPointParams {
  double critical_angle_deg;
  double density_percent;
  double minimal_distance_mm;
};
ParamList<SupportPointParams> support_point_params();
SupportPointOptions support_point_options(const SupportPointParams& p, double elevation_mm);
// The support tree's (SupportTreeOptions' fields and defaults, PrusaSlicer's SL1S profile).
ParamList<SupportTreeOptions> support_tree_params();

// Whether and how a print or plate job supports its members: none, points generated on each
// member, or a source's points (support_points_file) transferred onto each member; then each
// member's tree (make_member_supports).
enum class JobSupportsMode { None, Generate, Transfer };
struct JobSupports {
  JobSupportsMode mode;
  std::string support_points_file;
  SupportPointParams points;
  SupportTreeOptions tree;
};
ParamList<JobSupports> job_support_params();
// Each member's supports for a job whose options are o (members in their own frame, before
// placement, in o's order; empty when mode is None), on the job's planes: the encoding's, or
// o.slicing's thickness from its z_start. A NaN z_start (the lowest vertex) is set in o to the
// lowest vertex of all members, so that every plate stands on the ground the supports were built
// for; o.layers_below is set. The source's points are read once; a member of another mesh than
// the file's is refused with the transfer's words, naming the member.
std::vector<MemberSupports> job_member_supports(const std::vector<const Mesh*>& members, const JobSupports& s,
                                                PlateJobOptions& o, const Progress& progress);
// A member's support figures (support_points, kept, moved, added, dropped), each key followed by
// suffix ("" or "_<member>").
void add_support_figures(const MemberSupports& s, const std::string& suffix, Result& result);
inline double support_seconds(const MemberSupports& s) { return s.points_seconds + s.tree_seconds; }

// The layer_thickness and z_start parameters of the filters that slice the current mesh to show
// what a print job would do with it (supports, hollowing): the planes a print job slices it on.
template <class P>
void add_planes(ParamList<P>& l) {
  l.number(&P::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
           "Distance between slicing planes, in mm: the layers a print job slices the mesh into.")
      .number(&P::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "Bottom of the first layer, in mm; at or below -1e29 (the default): the lowest vertex of the mesh.");
}

// The mesh_file parameter of the filters that work on one mesh: the mesh read straight from a
// file instead of the current mesh (a batch's way, without a layer).
template <class P>
ParamList<P>& add_mesh_file(ParamList<P>& l, std::string P::*field) {
  return l.file(field, ParamType::FileOpen, "mesh_file", "Mesh file", "*.stl *.ply *.obj", nullptr,
                "Instead of the current mesh: a mesh file (STL, PLY or OBJ), read straight into the filter "
                "without a layer (a batch's way). Empty (the default): the current mesh.");
}

// The mesh such a filter works on, its name (the layer's, or the file's) and the seconds reading
// the file took (0 for the current mesh). Throws Error when there is no current mesh or the file
// cannot be read.
struct JobMesh {
  Mesh mesh;
  std::string name;
  double read_seconds = 0;
};
JobMesh job_mesh(const std::string& mesh_file, Host& host);

// The slicing options of the layer_thickness and z_start parameters (z_start_option: at or
// below kLowestVertexZStartAtOrBelow, the mesh's lowest vertex).
SliceOptions slice_options(double layer_thickness, double z_start);

// The plugin's one cached encoding (Make Print Job; Free Cached Memory frees it).
EncodingCache& encoding_cache();

// From the first print or plate job on, large buffers one job frees are kept for the next
// (ReuseBuffers) instead of going back to the kernel; reclaim_memory() (Free Cached Memory, or
// a job short of memory) releases them.
void keep_buffers_for_the_next_job();

// Binary when the name ends in .srb, text otherwise.
FileFormat format_for_name(const std::string& path);

// Checks that every non-empty output path can be written and that no two are the same file,
// naming the parameter in the error; called before any work is done.
void check_outputs(const std::vector<std::pair<std::string, std::string>>& named_paths);

// Checks that a filter's result has exactly the keys its spec declares (a declared key ending in
// "_*" stands for any number of keys with that prefix, one per plate or member); Error if not.
void check_result_keys(const FilterSpec& spec, const Result& result);

// The FilterSpec of a filter whose parameters are `params` and whose result has the keys
// `results`: its ParamSpecs, and a run that reads the values into a P, checks every file its
// FileSave parameters will write (check_outputs) before any work, calls run_typed, and checks
// the result's keys against the spec.
template <class P>
FilterSpec typed_filter(FilterSpec spec, const ParamList<P>& params, Result (*run_typed)(const P&, Host&),
                        std::vector<std::string> results) {
  spec.params = params.specs();
  spec.results = std::move(results);
  spec.run = [params, run_typed, spec](const ParamValues& values, Host& host) {
    const P p = params.read(values);
    check_outputs(params.outputs(p));
    Result result = run_typed(p, host);
    check_result_keys(spec, result);
    return result;
  };
  return spec;
}

}  // namespace slicereuse::plugin
