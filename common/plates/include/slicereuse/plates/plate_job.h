#pragma once
// plate_job: one build plate's print file, the one pipeline every print job runs through (Make
// Print Job is a plate of one member). Every layer's mask is the union of the members' layers at
// that height.
//
// Input: the members already placed (place_mesh, placement.h: turned and moved in x-y, z
// untouched), and how their contours are made:
//   reuse (options.encoding set): the source's encoding transferred onto each member's placed
//     vertices in exact mode (transfer_contours.h), so each member's layers equal direct slicing
//     of the placed member; the plate's planes are the encoding's (z_start, thickness): every
//     member sits on the source's build plate. A member whose faces are not the encoding's mesh's
//     (another connectivity) is sliced directly on those planes, and stats.direct_reasons says
//     why; with options.strict it fails the job instead;
//   direct (options.encoding null): each placed member sliced directly on the plate's planes,
//     options.slicing's thickness from its z_start (NaN: the lowest vertex of all members).
// The plate has the planes z_start + (k - layers_below + 1/2) h up to its tallest member's (or
// support's) top; each member's layers are those its own direct slicing from the same z_start
// would have (a shorter member simply ends), member layer j being plate layer j + layers_below.
// Layer k's contours are the members' layer k contours one after another: their footprints lie
// apart (arrange_plates.h), so the nonzero rule fills exactly the union of their own masks, and
// no anti-aliased pixel is shared when they are more than a pixel apart.
// Supports (options.supports): a member's support structure (support_tree.h, placed as the
// member is) is sliced directly on the plate's planes from layer 0 up to its top, with no
// encoding, and its layers follow the members' in each layer: the nonzero rule fills the union
// of part and support where they meet.
// Hollowing (options.hollowing.wall_mm > 0): each member's cavity (hollow_layers.h: a 3-D
// erosion of its layers by the wall thickness, then PrusaSlicer's closing) is computed from all
// its layers, made as its masks' are (so a reused member's cavity is its direct slicing's), and
// taken out of its layers before anything else sees them (whole_stack, the elephant-foot
// compensation, which then shrinks the cavity's walls too, as PrusaSlicer's order does, and the
// masks); supports stay solid. Without drain holes (options.drain_hole_mm) the cavity is sealed,
// and the printability check reports it as a resin trap; with them each cavity drains through
// its base. A member too thin for any cavity stays solid, and
// stats.hollowing_notes says so.
// Elephant foot (profile.elephant_foot_mm > 0): each member's faded layers, counted from the
// plate's layer 0 (its pad's bottom) and compensated with its supports together, apart from the
// other members, are replaced by compensate_faded_layers' contours (faded_layers.h: the full
// compensation on layer 0 fading to none over profile.faded_layers, as PrusaSlicer's) in every
// way of making it.
// Labels (options.labels): a member's label is placed once on the region its first layers share
// down to options.label.depth_mm (place_label.h, mirrored to read from below), or on the side
// options.label.side from all its layers (side_label.h), and cut from those layers' contours
// before the elephant-foot compensation, in every way of making it: from its own contours, so a
// reused member's labelled masks are those of direct slicing.
// Memory: reusing, each member's transfer is prepared once (ExactTransfer) and its layer k is
// transferred where layer k's mask is drawn, on that thread (LayerMaker, export_masks.h), so the
// plate holds a few layers of points plus those of the layers made directly beforehand (the
// layers the certificate refuses, and every layer of a member sliced directly). When those would
// hold more than the range budget, when slicing directly, or when the whole stack is asked for,
// the layers are made and exported a range at a time (SliceChunks, export_masks.h), each member's
// as it was made (no merged copy). A range holds at most the budget of points of all members:
// range_budget_bytes, or memory_share of the memory still available (memory_budget.h; slicing
// directly, memory kept for reuse is reclaimed before settling for ranges); reusing, at most
// 256 MB, so that a plate fills little fresh memory. Every way gives the same masks.
// Output: the print file of the profile (export_masks: PNG folder, .sl1, .sl1s, .goo), atomic, and
// the figures. Throws Error for no members, an encoding without a layer thickness, a member of
// another family with strict, supports not one per member, hollowing options that are negative
// or not finite, or whatever transfer, slicing or export refuse.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/hollowing/drain_holes.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/printability/printability_report.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

// Where a label goes: the base, or one of the four sides seen from above, the member's own
// (before its placement turned it): front -y, back +y, left -x, right +x.
enum class LabelSide { Base, Front, Back, Left, Right };

// Labels engraved into members (place_label.h, label_region.h): height_mm high where the label
// fits, down by tenths to min_height_mm, depth_mm deep, margin_mm inside the face's edges; on
// the base mirrored to read from below (base_label.h), on a side upright (side_label.h).
// Defaults after the dental literature (7.5 mm high, 3 mm deep).
struct LabelOptions {
  double height_mm = 7.5;
  double min_height_mm = 2.5;
  double depth_mm = 3;
  double margin_mm = 1;
  LabelSide side = LabelSide::Base;
};

struct PlateJobOptions {
  const Slices* encoding = nullptr;  // the source's encoding (reuse), or null (direct slicing)
  // Its encoded_edge_ends (transfer_contours.h), or null or empty: then looked up in each
  // member's faces.
  const Buffer<uint32_t>* edge_ends = nullptr;
  // With edge_ends, their vertex_order (transfer_contours.h), or null: then each member's layers
  // are transferred from its own vertex array, in its own order.
  const VertexOrder* vertex_order = nullptr;
  SliceOptions slicing;  // direct slicing's thickness and z_start
  // A range's budget in bytes of points (0: none), or, when memory_share > 0, that share of
  // available_memory() (memory_budget.h).
  uint64_t range_budget_bytes = 0;
  double memory_share = 0;
  bool strict = false;  // reusing: a member of another family fails the job
  // The members' names for messages (a strict refusal); empty: "member 1", "member 2", ...
  std::vector<std::string> names;
  // When set, the plate is made in one range and this sees its parts (one per member with
  // layers, then one per support) before their masks are drawn (hollowed and labelled, before
  // the elephant-foot compensation): a print job's contour file.
  std::function<void(const std::vector<SlicePart>& parts)> whole_stack;
  // Per member (placed like it), its support structure, or null; empty: none.
  std::vector<const Mesh*> supports;
  // Plate layers under z_start (support_layers_below, support_tree.h): only supports are there.
  size_t layers_below = 0;
  // Printability (check_layers.h, UVtools' checks) checked on the masks as they are written:
  // stats.printability and each finding's member. With require_printable, a plate holding an
  // island, a resin trap or a suction cup is refused: Error naming each such finding, its member
  // and place, and nothing is written.
  bool check_printability = false;
  bool require_printable = false;
  // Per member, the text engraved into its base (engrave_labels.h; empty or "": none). A label
  // that fits at no height, or a member less than 1 mm taller than the label is deep, fails the
  // job (Error naming the member and the sizes), or with allow_unlabelled the member is printed
  // without it (stats.label_heights_mm 0).
  std::vector<std::string> labels;
  LabelOptions label;
  bool allow_unlabelled = false;
  // Per member, the turn about z its placement gave it (degrees, placement.h), so that a label
  // on a side goes on the member's own side; empty: none turned.
  std::vector<double> label_turns_deg;
  // Each member hollowed with walls of hollowing.wall_mm (0: solid) and its closing distance;
  // with drain_hole_mm > 0, a drain hole of that diameter under each cavity (drain_holes.h),
  // through the bottom wall to the base, so that none stays sealed.
  HollowingOptions hollowing;
  double drain_hole_mm = 0;
  size_t drain_holes_per_cavity = 1;  // automatic holes: the first under the cavity's middle, the rest spread
  // The user's drain holes (a point layer or a file; support_points.h's encoding: face and area
  // coordinates, so each member, which must have their faces, has them at the same place on its
  // own surface): when not empty, they replace the automatic ones, each drilled along its
  // surface's normal (add_drain_holes_at, drain_holes.h); a hole that reaches no cavity of a
  // member fails the job, naming the member and the hole.
  SupportPoints drain_points;
  // Cavities made before the job (a supported member's, whose support heads keep clear of its
  // drain holes: filters_job_supports.cpp), before any hole: each with the mesh it was made of
  // (which must outlive the job), its layers' planes and the hollowing. A member whose mesh has
  // the same vertices and faces, on the same planes, with the same hollowing, takes it as its
  // cavity (layers_cavity of the same layers: the same) rather than making it again.
  struct MadeCavity {
    const Mesh* mesh = nullptr;
    std::vector<double> planes;
    HollowingOptions hollowing;
    std::vector<ClipperLib::Paths> cavity;
  };
  std::vector<MadeCavity> made_cavities;
};

// Where a finding of the plate's printability lies: the member (an index into placed) whose
// footprint, its supports' included, holds the finding's centre, or lies nearest to it, and that
// centre on the build plate (mm).
struct FindingPlace {
  size_t member = 0;
  double x_mm = 0, y_mm = 0;
};

struct PlateJobStats {
  size_t layers = 0;              // the plate's
  size_t points = 0;              // all members' contour points
  size_t transferred_layers = 0;  // member layers, summed over members
  size_t resliced_layers = 0;     // member layers sliced directly (all of them without an encoding)
  size_t support_layers = 0;      // supports' layers (sliced directly), summed over supports
  size_t ranges = 1;              // of layers made before their masks; 0: made where drawn
  double z_start = 0, thickness = 0;
  // Transfer or slicing, in all ranges; made where drawn, summed over the threads that made the
  // layers (it overlaps the masks then), plus the slicing beforehand.
  double slicing_seconds = 0;
  // Per member: why it was sliced directly although an encoding was given ("" when reused, and
  // for every member of a plate sliced directly by choice).
  std::vector<std::string> direct_reasons;
  // With options.hollowing: per member, its cavity's volume (mm^3), and "" or why it has none;
  // the cavities' computation, members' layers included, in seconds.
  std::vector<double> cavity_mm3;
  std::vector<std::vector<DrainHole>> drain_holes;  // per member, with options.drain_hole_mm
  std::vector<std::string> hollowing_notes;
  double hollowing_seconds = 0;
  MaskExportStats masks;
  // With options.check_printability: the report, and each finding's place (one per finding).
  bool checked = false;
  PrintabilityReport printability;
  std::vector<FindingPlace> finding_places;
  // With options.labels: per member, its label's height in mm (0: none, or it fitted nowhere and
  // allow_unlabelled printed it without), and its place: on the base its centre x, y (mm, plate)
  // and turn (degrees); on a side the centre of its box on the side, x, y, z (mm, plate).
  std::vector<double> label_heights_mm;
  std::vector<std::array<double, 3>> label_places;
};


// The drain holes a hollowed job drills into a member: its mesh (in the frame its layers were
// made in), its layers on the job's planes, its name for messages, and its cavity (layers_cavity
// of those layers), which gains the holes: options.drain_points placed on its own surface (Error
// when its faces are not theirs, or a hole reaches no cavity, naming it), else the automatic ones.
std::vector<DrainHole> drill_member_drain_holes(const Mesh& member, const Slices& layers, const std::string& name,
                                                const PlateJobOptions& options, std::vector<ClipperLib::Paths>& cavity);

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& options,
                           const PrinterProfile& profile, const std::string& output_path,
                           const Progress& progress = {});

}  // namespace slicereuse
