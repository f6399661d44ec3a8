#include "slicereuse/plates/plate_job.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>

#include "engrave_labels.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/plates/base_label.h"
#include "slicereuse/plates/faded_layers.h"
#include "slicereuse/plates/side_label.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/slicing/straddling_faces.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/memory_budget.h"
#include "slicereuse/util/parallel_blocks.h"
#include "slicereuse/util/seconds_since.h"

namespace slicereuse {
namespace {

// Reusing, a range holds at most this many bytes of points, whatever the budget: a range costs
// what its points do (ExactTransfer), and a plate then fills at most this much fresh memory,
// which the kernel zeroes before handing it out.
constexpr uint64_t kReusedRangeBytes = uint64_t(256) << 20;
constexpr size_t kPointBytes = 3 * sizeof(double);
constexpr size_t kNotDirect = SIZE_MAX;

// A member's layers sliced directly on a plate made where drawn (MadeWhereDrawn): the planes,
// their slices once made, and for each of the member's layers its layer there (or kNotDirect).
struct DirectLayers {
  std::vector<size_t> at;
  std::vector<double> planes;
  Slices slices;

  void add(size_t k, double z) {
    at[k] = planes.size();
    planes.push_back(z);
  }
};

// The plate's layers: plate layer k is layer k - below of the slicing from z_start.
struct PlateFrame {
  double z_start = 0, thickness = 0;
  size_t below = 0;

  double plane(size_t k) const { return layer_plane(z_start, thickness, double(k) - double(below)); }
  double bottom(size_t k) const { return z_start + (double(k) - double(below)) * thickness; }
};

// A member of the plate and how its layers are made: by its transfer (reusing, same family), or
// sliced directly on its own planes (the plate's, up to its top); a support always directly.
struct PlateMember {
  const Mesh* mesh = nullptr;
  std::unique_ptr<ExactTransfer> transfer;
  std::vector<double> planes;  // without a transfer
  DirectLayers direct;         // made where drawn: its layers sliced beforehand
  size_t offset = 0;           // the plate layer of its layer 0
  std::vector<ClipperLib::Paths> cavity;  // hollowed: each of its layers' cavity; else empty
  // Hollowed, with a label for its side: its layers' contours (as loops, no union: the cavity
  // simplifies them and the label clips them to its strip) and mid-planes, taken for its cavity,
  // kept for member_labels to place the label on (then freed).
  std::vector<ClipperLib::Paths> contours;
  std::vector<double> contour_z;
  bool support = false;
  size_t owner = 0;            // the member it is, or whose support it is

  size_t layers() const { return transfer ? transfer->layers() : planes.size(); }
  size_t end() const { return offset + layers(); }
  // Its points on each of its layers: the certificate's counts, or its faces each plane crosses.
  std::vector<uint64_t> layer_points() const {
    return transfer ? transfer->layer_points() : straddling_face_counts(*mesh, planes);
  }
};

// The layers member p must slice directly when made where drawn: every layer without a transfer;
// with one, those the cheap certificate refuses (above the source's top, or failing the counts or
// sample), and, when there are any (the member changed in z, and then some layers that pass the
// sample fail the whole certificate), those the whole certificate refuses too, found now, so that
// all are sliced in one pass (slicing one plane costs about as much as slicing them all: the
// faces are sorted first). When that is more than half of them, every layer is sliced, as
// transfer_contours does (transfer_layers.h): transferring the rest would cost more. That is
// known as soon as more than half fail: a member changed in z everywhere fails the counts on most
// layers, and then no layer's whole certificate is checked.
DirectLayers layers_to_slice(const PlateMember& p) {
  DirectLayers d;
  d.at.assign(p.layers(), kNotDirect);
  if (p.transfer) {
    const ExactTransfer& t = *p.transfer;
    const size_t half = t.layers() / 2;
    size_t refused = 0;
    for (size_t k = 0; k < t.layers(); ++k) refused += !t.transferable(k);
    if (refused > 0 && refused <= half)
      for (size_t k = 0; k < t.layers() && d.planes.size() <= half; ++k)
        if (!t.transferable(k) || !t.certified(k)) d.add(k, t.plane(k));
    if (refused <= half && d.planes.size() <= half) return d;
    d.planes.clear();
    d.at.assign(p.layers(), kNotDirect);
  }
  for (size_t k = 0; k < p.layers(); ++k) d.add(k, p.transfer ? p.transfer->plane(k) : p.planes[k]);
  return d;
}

// The plate's z_start and thickness for o (see plate_job.h), lowest being its members' lowest
// vertex (used only slicing directly from z_start NaN).
void plate_frame(size_t members, const PlateJobOptions& o, double lowest, double* z_start, double* thickness) {
  if (members == 0) throw Error("a plate needs at least one member");
  if (o.encoding) {
    if (!(o.encoding->thickness > 0))
      throw Error("the encoding has no layer thickness (it was not made by slicing at a thickness), so the plate's "
                  "layers are unknown");
    *z_start = o.encoding->z_start;
    *thickness = o.encoding->thickness;
  } else {
    *z_start = std::isnan(o.slicing.z_start) ? lowest : o.slicing.z_start;
    *thickness = o.slicing.thickness;
  }
}

// A mesh's planes on the plate: the plate's up to its own top.
std::vector<double> own_planes(const Mesh& mesh, double z_start, double thickness) {
  const double top = z_range(mesh).max;
  return z_start < top ? layer_planes(z_start, thickness, top) : std::vector<double>{};
}

// A support's planes: the plate's from its layer 0 (below z_start) up to the support's top.
std::vector<double> support_planes(const Mesh& support, const PlateFrame& f) {
  const double top = z_range(support).max;
  std::vector<double> planes;
  for (size_t k = 0; f.bottom(k) < top; ++k) {
    if (k == kMaxLayers)
      throw Error(format("a support reaching z = %g mm gives more than %zu layers of %g mm", top, kMaxLayers,
                         f.thickness));
    planes.push_back(f.plane(k));
  }
  return planes;
}

std::string member_name(const PlateJobOptions& o, size_t m) {
  return m < o.names.size() ? o.names[m] : format("member %zu", m + 1);
}

// Each member prepared, on all cores in one parallel region (OpenMP's threads spin for a while
// after each region, against the masks' threads): reusing, its transfer (which checks the member)
// unless its faces are another family's, then sliced directly (st.direct_reasons says why) or,
// strict, refused; and, made where drawn, the layers it slices beforehand.
std::vector<PlateMember> prepare_members(const std::vector<Mesh>& placed, const PlateJobOptions& o,
                                         PlateJobStats& st) {
  const size_t n = placed.size();
  double lowest = INFINITY;
  if (!o.encoding)
    for (const Mesh& m : placed) {
      validate_mesh(m);
      lowest = std::min(lowest, z_range(m).min);
    }
  plate_frame(n, o, lowest, &st.z_start, &st.thickness);
  if (!o.supports.empty() && o.supports.size() != n)
    throw Error(format("a plate of %zu members was given %zu supports: one (or none) per member", n, o.supports.size()));
  const PlateFrame frame{st.z_start, st.thickness, o.layers_below};
  std::vector<const Mesh*> supports;
  std::vector<size_t> support_owner;
  for (size_t m = 0; m < o.supports.size(); ++m)
    if (o.supports[m]) {
      supports.push_back(o.supports[m]);
      support_owner.push_back(m);
    }
  std::vector<PlateMember> members(n + supports.size());
  st.direct_reasons.assign(n, "");
  const bool with_ends = o.edge_ends && !o.edge_ends->empty();
  parallel_blocks(
      members.size(),
      [&](size_t m) {
        PlateMember& p = members[m];
        if (m >= n) {
          p.mesh = supports[m - n];
          p.support = true;
          p.owner = support_owner[m - n];
          validate_mesh(*p.mesh);
          p.planes = support_planes(*p.mesh, frame);
          if (o.encoding && !o.whole_stack) p.direct = layers_to_slice(p);
          return;
        }
        p.mesh = &placed[m];
        p.owner = m;
        p.offset = o.layers_below;
        if (o.encoding) {
          validate_mesh(placed[m]);
          const std::string difference = family_difference(*o.encoding, placed[m]);
          if (difference.empty()) {
            p.transfer = with_ends ? std::make_unique<ExactTransfer>(*o.encoding, *o.edge_ends, placed[m], o.vertex_order)
                                   : std::make_unique<ExactTransfer>(*o.encoding, placed[m]);
          } else if (o.strict) {
            throw Error(format("%s cannot be made by reuse: its %s (strict is on; off, it would be sliced directly)",
                               member_name(o, m).c_str(), difference.c_str()));
          } else {
            st.direct_reasons[m] = "its " + difference;
          }
        }
        if (!p.transfer) p.planes = own_planes(placed[m], st.z_start, st.thickness);
        if (o.encoding && !o.whole_stack) p.direct = layers_to_slice(p);
      },
      {}, "preparing the members");
  return members;
}

// The cavity made before the job (o.made_cavities) of member p's very layers: of a mesh with its
// vertices and faces, on its planes, with the job's hollowing; else null.
const PlateJobOptions::MadeCavity* made_cavity(const PlateMember& p, const PlateJobOptions& o) {
  for (const PlateJobOptions::MadeCavity& c : o.made_cavities) {
    if (!c.mesh || c.hollowing.wall_mm != o.hollowing.wall_mm || c.hollowing.closing_mm != o.hollowing.closing_mm ||
        c.planes.size() != p.layers() || c.cavity.size() != p.layers() || c.mesh->V != p.mesh->V ||
        c.mesh->F != p.mesh->F)
      continue;
    bool same = true;
    for (size_t k = 0; k < p.layers() && same; ++k)
      same = c.planes[k] == (p.transfer ? p.transfer->plane(k) : p.planes[k]);
    if (same) return &c;
  }
  return nullptr;
}

// With o.hollowing, each member's cavity from all its layers, made as its masks' are (by its
// transfer or sliced directly on its planes), one member at a time on all cores; its volume, or
// why there is none, into st, or the one made before the job of the same layers. Supports stay
// solid. A member to be labelled on a side keeps its layers' contours for the label
// (member_labels), which would slice them again.
void hollow_members(std::vector<PlateMember>& members, const PlateJobOptions& o, PlateJobStats& st,
                    const Progress& progress) {
  const size_t n = st.direct_reasons.size();
  st.cavity_mm3.assign(n, 0);
  st.drain_holes.assign(n, {});
  st.hollowing_notes.assign(n, "");
  if (o.hollowing.wall_mm == 0) return;
  const auto t = std::chrono::steady_clock::now();
  for (size_t m = 0; m < n; ++m) {
    PlateMember& p = members[m];
    const Progress mp = sub_progress(progress, double(m) / double(n), double(m + 1) / double(n));
    Slices layers = p.transfer ? p.transfer->layers(0, p.layers(), nullptr, sub_progress(mp, 0, 0.2))
                               : slice_planes(*p.mesh, p.planes, sub_progress(mp, 0, 0.2), false);
    layers.thickness = st.thickness;
    const bool side_label = m < o.labels.size() && !o.labels[m].empty() && o.label.side != LabelSide::Base;
    const PlateJobOptions::MadeCavity* made = made_cavity(p, o);
    std::vector<ClipperLib::Paths> contours;
    if (!made || side_label) contours = layers_paths(layers);
    p.cavity = made ? made->cavity : cavity_regions(contours, st.thickness, o.hollowing, sub_progress(mp, 0.2, 1));
    if (side_label) {
      p.contours = std::move(contours);
      p.contour_z = layers.layer_z;
    }
    st.cavity_mm3[m] = cavity_volume_mm3(p.cavity, st.thickness);
    if (o.drain_hole_mm > 0 && st.cavity_mm3[m] > 0)
      st.drain_holes[m] = drill_member_drain_holes(*p.mesh, layers, member_name(o, m), o, p.cavity);
    if (st.cavity_mm3[m] == 0) {
      p.cavity.clear();
      st.hollowing_notes[m] =
          format("%s stays solid: no cavity with walls of %g mm%s, since no ball of %g mm radius fits inside it",
                 member_name(o, m).c_str(), o.hollowing.wall_mm,
                 o.hollowing.closing_mm > 0 ? format(" and a closing distance of %g mm", o.hollowing.closing_mm).c_str()
                                            : "",
                 o.hollowing.wall_mm + o.hollowing.closing_mm);
    }
  }
  st.hollowing_seconds = seconds_since(t);
}

// The plate's layers [a, b) as parts (export_masks.h), one per member that has any of them, each
// by its transfer or sliced directly: the masks draw each member's layers where they are.
std::vector<SlicePart> plate_range(const std::vector<PlateMember>& members, const PlateFrame& f, size_t a, size_t b,
                                   PlateJobStats& st, const Progress& progress) {
  const size_t n = members.size();
  std::vector<SlicePart> parts;
  for (size_t m = 0; m < n; ++m) {
    const Progress mp = sub_progress(progress, double(m) / double(n), double(m + 1) / double(n));
    const PlateMember& p = members[m];
    const size_t lo = std::max(a, p.offset), hi = std::min(b, p.end());
    if (lo >= hi) continue;
    const size_t ja = lo - p.offset, je = hi - p.offset;  // its own layers
    if (p.transfer) {
      TransferStats ts;
      parts.push_back({p.transfer->layers(ja, je, &ts, mp), lo - a, p.support});
      st.transferred_layers += ts.transferred_layers;
      st.resliced_layers += ts.resliced_layers;
    } else {
      parts.push_back({slice_planes(*p.mesh, {p.planes.begin() + long(ja), p.planes.begin() + long(je)}, mp, false),
                       lo - a, p.support});
      (p.support ? st.support_layers : st.resliced_layers) += je - ja;
    }
    Slices& made = parts.back().slices;
    if (!p.cavity.empty()) subtract_cavity(made, ja, p.cavity);
    made.z_start = f.bottom(lo);
    made.thickness = f.thickness;
    st.points += made.points();
  }
  return parts;
}

// The owners of the parts plate_range(members, ..., a, b) and MadeWhereDrawn::make (b = a + 1)
// give, in their order: each member's, or its supports', for compensate_faded_layers.
std::vector<size_t> part_owners(const std::vector<PlateMember>& members, size_t a, size_t b) {
  std::vector<size_t> owners;
  for (const PlateMember& p : members)
    if (std::max(a, p.offset) < std::min(b, p.end())) owners.push_back(p.owner);
  return owners;
}

// Those parts with each labelled member's label cut from its own layers (engrave_part).
void engrave_parts(std::vector<SlicePart>& parts, size_t a, size_t b, const std::vector<PlateMember>& members,
                   const std::vector<LabelCut>& labels) {
  if (labels.empty()) return;
  size_t i = 0;
  for (const PlateMember& p : members) {
    if (std::max(a, p.offset) >= std::min(b, p.end())) continue;
    SlicePart& part = parts[i++];
    if (!p.support) engrave_part(part, a + part.first - p.offset, labels[p.owner]);
  }
}

constexpr double kLabelSkinMm = 1;  // of the part between a label's letters and a cavity, at least

// Each labelled member's label placed on its base (base_label.h) from its own first layers, or
// on its side (side_label.h) from all its layers; a label that fits nowhere fails the job, or
// with allow_unlabelled leaves the member unlabelled.
std::vector<LabelCut> member_labels(std::vector<PlateMember>& members, size_t count, const PlateJobOptions& o,
                                    PlateJobStats& st) {
  std::vector<LabelCut> labels;
  if (o.labels.empty()) return labels;
  if (o.labels.size() != count)
    throw Error(format("a plate of %zu members was given %zu labels: one (or \"\") per member", count, o.labels.size()));
  // The cavity lies at least the wall inside the part: letters deeper than the wall less 1 mm
  // would open into it, or leave a skin over it.
  if (o.hollowing.wall_mm > 0 && o.label.depth_mm > o.hollowing.wall_mm - kLabelSkinMm)
    throw Error(format("labels %g mm deep would come within %g mm of the cavity behind walls of %g mm: make them at most "
                       "%g mm deep, or the walls at least %g mm",
                       o.label.depth_mm, kLabelSkinMm, o.hollowing.wall_mm, o.hollowing.wall_mm - kLabelSkinMm,
                       o.label.depth_mm + kLabelSkinMm));
  labels.resize(count);
  st.label_heights_mm.assign(count, 0);
  st.label_places.assign(count, {0, 0, 0});
  for (PlateMember& p : members) {
    const std::string& text = o.labels[p.owner];
    if (p.support || text.empty()) continue;
    const std::string name = p.owner < o.names.size() ? o.names[p.owner] : format("member %zu", p.owner + 1);
    if (o.label.side != LabelSide::Base) {
      // Placed on its solid layers: the letters take only what lies within their depth of the
      // outside (engrave_part), so they keep the wall less their depth from the cavity (above).
      const double turn = p.owner < o.label_turns_deg.size() ? o.label_turns_deg[p.owner] : 0;
      SideLabel s;
      if (!p.contour_z.empty()) {
        s = place_side_label(std::move(p.contours), p.contour_z, st.thickness, turn, text, name, o.label);
        p.contours = {};
        p.contour_z = {};
      } else {
        const Slices all = p.transfer ? p.transfer->layers(0, p.layers()) : slice_planes(*p.mesh, p.planes, {}, false);
        s = place_side_label(all, st.thickness, turn, text, name, o.label);
      }
      if (s.cuts.empty()) {
        if (o.allow_unlabelled) continue;
        throw Error(s.why);
      }
      st.label_heights_mm[p.owner] = s.height_mm;
      st.label_places[p.owner] = {s.x_mm, s.y_mm, s.z_mm};
      labels[p.owner] = {s.first, s.cuts.size(), std::move(s.cuts), o.label.depth_mm};
      continue;
    }
    const size_t layers = engraved_layers(o.label.depth_mm, st.thickness, p.layers());
    Slices first = p.transfer ? p.transfer->layers(0, layers)
                              : slice_planes(*p.mesh, {p.planes.begin(), p.planes.begin() + long(layers)}, {}, false);
    if (!p.cavity.empty()) subtract_cavity(first, 0, p.cavity);  // the label keeps clear of drain holes
    BaseLabel b = place_base_label(first, double(p.layers()) * st.thickness, text, name, o.label);
    if (!b.placement.placed) {
      if (o.allow_unlabelled) continue;
      throw Error(b.why);
    }
    st.label_heights_mm[p.owner] = b.placement.height_mm;
    st.label_places[p.owner] = {b.placement.x_mm, b.placement.y_mm, b.placement.angle_deg};
    labels[p.owner] = {0, b.layers, {std::move(b.placement.region)}, 0};
  }
  return labels;
}

// Per owner (member), its layers from the plate's layer 0 with its supports': what
// compensate_faded_layers fades over, as PrusaSlicer over an object's from its pad's bottom.
std::vector<size_t> object_layers(const std::vector<PlateMember>& members) {
  std::vector<size_t> layers;
  for (const PlateMember& p : members) {
    if (p.owner >= layers.size()) layers.resize(p.owner + 1, 0);
    layers[p.owner] = std::max(layers[p.owner], p.end());
  }
  return layers;
}

// A reused plate made a layer at a time where its masks are drawn (LayerMaker, export_masks.h):
// each member's layer k is transferred on the thread that draws it (ExactTransfer::layer_into),
// into that thread's parts, so its points are drawn while in cache and the plate holds no range
// of them, and fills no fresh memory. The layers a member cannot transfer (layers_to_slice) are
// sliced beforehand, one pass per member, and copied out layer by layer. A member whose every
// layer passed the cheap certificate may still fail the whole one on some (a vertex moved across
// an edge the sample does not read): on the first such layer, the member's layers are all
// checked and those failing sliced, once, in one pass.
class MadeWhereDrawn {
 public:
  MadeWhereDrawn(std::vector<PlateMember>& members, const PlateFrame& frame, const Progress& progress)
      : members_(members),
        frame_(frame),
        late_(members.size()),
        late_once_(new std::once_flag[members.size()]) {
    const auto t = std::chrono::steady_clock::now();
    size_t layers = 0, done = 0;
    for (const PlateMember& p : members_) layers += p.direct.planes.size();
    for (PlateMember& p : members_) {
      const size_t n = p.direct.planes.size();
      if (n == 0) continue;
      const Progress mp = sub_progress(progress, double(done) / double(layers), double(done + n) / double(layers));
      p.direct.slices = slice_planes(*p.mesh, p.direct.planes, mp, false);
      done += n;
    }
    direct_seconds_ = seconds_since(t);
  }

  // Layer k's parts, one per member that has it.
  void make(size_t k, std::vector<SlicePart>& parts) {
    const auto t = std::chrono::steady_clock::now();
    size_t used = 0, points = 0, transferred = 0, supports = 0;
    for (size_t m = 0; m < members_.size(); ++m) {
      const PlateMember& p = members_[m];
      if (k < p.offset || k >= p.end()) continue;
      const size_t j = k - p.offset;  // its own layer
      if (parts.size() == used) parts.emplace_back();
      parts[used].support = p.support;
      Slices& out = parts[used++].slices;
      supports += p.support;
      const DirectLayers* d = &p.direct;
      if (d->at[j] == kNotDirect && p.transfer->layer_into(j, out)) {
        ++transferred;
      } else {
        if (d->at[j] == kNotDirect) {
          std::call_once(late_once_[m], [&] { late_[m] = late_layers(p); });
          d = &late_[m];
          if (d->at[j] == kNotDirect)
            throw Error(format("internal error: layer %zu of plate member %zu failed its certificate once, not twice",
                               j, m + 1));
        }
        layers_into(d->slices, d->at[j], d->at[j] + 1, out, true);
        // Sliced directly, the part's z_start and thickness are not the plate's.
        out.z_start = frame_.bottom(k);
        out.thickness = frame_.thickness;
      }
      if (!p.cavity.empty()) subtract_cavity(out, j, p.cavity);
      points += out.points();
    }
    parts.resize(used);
    points_ += points;
    transferred_ += transferred;
    resliced_ += used - transferred - supports;
    supports_ += supports;
    nanoseconds_ += uint64_t(1e9 * seconds_since(t));
  }

  void stats(PlateJobStats& st) const {
    st.points = points_;
    st.transferred_layers = transferred_;
    st.resliced_layers = resliced_;
    st.support_layers = supports_;
    st.slicing_seconds = direct_seconds_ + 1e-9 * double(nanoseconds_);
  }

 private:
  // Member p's layers that pass the cheap certificate but not the whole one, sliced (on the
  // drawing thread that found the first: its OpenMP team is its own, a rare cost).
  static DirectLayers late_layers(const PlateMember& p) {
    DirectLayers d;
    const ExactTransfer& t = *p.transfer;
    d.at.assign(t.layers(), kNotDirect);
    for (size_t k = 0; k < t.layers(); ++k)
      if (p.direct.at[k] == kNotDirect && !t.certified(k)) d.add(k, t.plane(k));
    d.slices = slice_planes(*p.mesh, d.planes, {}, false);
    return d;
  }

  std::vector<PlateMember>& members_;
  const PlateFrame frame_;
  std::vector<DirectLayers> late_;
  std::unique_ptr<std::once_flag[]> late_once_;
  double direct_seconds_ = 0;
  std::atomic<size_t> points_{0}, transferred_{0}, resliced_{0}, supports_{0};
  std::atomic<uint64_t> nanoseconds_{0};
};

// A range's budget of point bytes (see plate_job.h); 0: no limit.
uint64_t range_budget(const PlateJobOptions& o) {
  const uint64_t given =
      o.memory_share > 0 ? uint64_t(o.memory_share * double(available_memory())) : o.range_budget_bytes;
  if (!o.encoding) return given;
  return given == 0 ? kReusedRangeBytes : std::min(given, kReusedRangeBytes);
}

// The range starts of the plate's L layers within the budget (layer_chunks.h).
std::vector<size_t> plate_ranges(const std::vector<PlateMember>& members, size_t L, uint64_t budget) {
  if (budget == 0) return {0, L};
  std::vector<uint64_t> points(L, 0);
  for (const PlateMember& p : members) {
    const std::vector<uint64_t> own = p.layer_points();
    for (size_t j = 0; j < own.size(); ++j) points[p.offset + j] += own[j];
  }
  return layer_chunks(points, budget, kPointBytes);
}

// The checks of a plate's masks (export_masks.h): the report into st, each finding placed on
// the plate by its member's footprint, and, when required, the plate refused before it is written.
struct PlateChecks {
  PlateChecks(const std::vector<PlateMember>& members, size_t count, const PlateJobOptions& o,
              const PrinterProfile& profile, PlateJobStats& st) {
    if (!o.check_printability && !o.require_printable) return;
    // Each member's footprint: a box in x-y of its mesh and its supports'.
    std::vector<std::array<double, 4>> boxes(count, {INFINITY, INFINITY, -INFINITY, -INFINITY});
    for (const PlateMember& p : members) {
      std::array<double, 4>& b = boxes[p.owner];
      const std::vector<double>& V = p.mesh->V;
      for (size_t v = 0; v < V.size(); v += 3)
        b = {std::min(b[0], V[v]), std::min(b[1], V[v + 1]), std::max(b[2], V[v]), std::max(b[3], V[v + 1])};
    }
    const MaskImageLayout layout = mask_image_layout(profile);
    std::vector<std::string> names = o.names;
    for (size_t i = names.size(); i < count; ++i) names.push_back(format("member %zu", i + 1));
    checks.done = [&st, &o, boxes, layout, names](PrintabilityReport report) {
      st.checked = true;
      st.finding_places.clear();
      std::string refused;
      for (const Finding& f : report.findings) {
        FindingPlace place;
        double xy[2];
        plate_point_at_pixel(layout, 0.5 * (f.x0 + f.x1), 0.5 * (f.y0 + f.y1), xy);
        place.x_mm = xy[0];
        place.y_mm = xy[1];
        double nearest = INFINITY;
        for (size_t i = 0; i < boxes.size(); ++i) {
          const auto& b = boxes[i];
          const double dx = std::max({b[0] - xy[0], xy[0] - b[2], 0.0});
          const double dy = std::max({b[1] - xy[1], xy[1] - b[3], 0.0});
          if (dx * dx + dy * dy < nearest) {
            nearest = dx * dx + dy * dy;
            place.member = i;
          }
        }
        st.finding_places.push_back(place);
        if (o.require_printable && blocks_printing(f.kind)) {
          std::string kind = finding_kind_name(f.kind);
          std::replace(kind.begin(), kind.end(), '_', ' ');
          refused += format("%s%s in %s, layers %zu-%zu, at x %.2f y %.2f mm (%.3g %s)", refused.empty() ? "" : "; ",
                            kind.c_str(), names[place.member].c_str(), f.first_layer, f.last_layer, xy[0] + 0.0,
                            xy[1] + 0.0, f.kind == FindingKind::Island ? f.area_mm2 : f.volume_mm3,
                            f.kind == FindingKind::Island ? "mm2" : "mm3");
        }
      }
      st.printability = std::move(report);
      if (!refused.empty()) throw Error("not printable, so not written: " + refused);
    };
  }
  const MaskChecks* get() const { return checks.done ? &checks : nullptr; }
  MaskChecks checks;
};

}  // namespace

std::vector<DrainHole> drill_member_drain_holes(const Mesh& member, const Slices& layers, const std::string& name,
                                                const PlateJobOptions& o, std::vector<ClipperLib::Paths>& cavity) {
  if (o.drain_points.size() == 0) {
    std::vector<DrainHole> holes = add_drain_holes(cavity, o.drain_hole_mm, o.drain_holes_per_cavity);
    try {
      check_drain_holes_fit(holes, o.drain_hole_mm, layers);
    } catch (const Error& e) {
      throw Error(name + ": " + e.what());
    }
    return holes;
  }
  const Fingerprint own = mesh_fingerprint(member);
  if (own != o.drain_points.fingerprint)
    throw Error(format("the drain holes are for a mesh of %s; %s has %s: holes are carried only to members with the "
                       "same faces",
                       describe_fingerprint(o.drain_points.fingerprint).c_str(), name.c_str(),
                       describe_fingerprint(own).c_str()));
  SupportPoints placed = o.drain_points;
  place_support_points(placed, member);
  try {
    return add_drain_holes_at(cavity, layers.layer_z, placed.xyz, placed.normal, o.drain_hole_mm,
                              drain_hole_depth_mm(o.hollowing));
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& o, const PrinterProfile& profile,
                           const std::string& output_path, const Progress& progress) {
  PlateJobStats st;
  check_hollowing(o.hollowing);
  if (!(std::isfinite(o.drain_hole_mm) && o.drain_hole_mm >= 0))
    throw Error(format("a drain hole's diameter is %g mm; it must be a finite number, 0 for no holes", o.drain_hole_mm));
  if (o.drain_points.size() > 0) validate_support_points(o.drain_points);
  std::vector<PlateMember> members = prepare_members(placed, o, st);
  const PlateFrame frame{st.z_start, st.thickness, o.layers_below};
  size_t L = 0;
  for (const PlateMember& p : members) L = std::max(L, p.end());
  if (L == 0) {
    double top = -INFINITY;
    for (const Mesh& m : placed) top = std::max(top, z_range(m).max);
    throw Error(format("no layers: z_start %g mm is not below the top of %s at z = %g mm", st.z_start,
                       placed.size() == 1 ? "the mesh" : "any member", top));
  }
  st.layers = L;
  const bool hollowing = o.hollowing.wall_mm > 0;
  hollow_members(members, o, st, sub_progress(progress, 0, hollowing ? 0.3 : 0));
  const Progress rest = sub_progress(progress, hollowing ? 0.3 : 0, 1);
  const uint64_t budget = o.whole_stack ? 0 : range_budget(o);
  const PlateChecks checks(members, placed.size(), o, profile, st);
  const std::vector<LabelCut> labels = member_labels(members, placed.size(), o, st);
  const bool supports =
      std::any_of(members.begin(), members.end(), [](const PlateMember& p) { return p.support; });

  if (o.encoding && !o.whole_stack) {
    // Made where drawn when the layers to slice directly fit in the budget (else in ranges).
    uint64_t direct_points = 0;
    for (const PlateMember& p : members) {
      const std::vector<uint64_t> points = p.layer_points();
      for (size_t k = 0; k < p.layers(); ++k)
        if (p.direct.at[k] != kNotDirect) direct_points += points[k];
    }
    if (direct_points * kPointBytes <= budget) {
      const double share = direct_points > 0 ? 0.1 : 0;  // of the progress, for the direct slicing
      MadeWhereDrawn made(members, frame, sub_progress(rest, 0, share));
      st.ranges = 0;
      const std::vector<size_t> objects = object_layers(members);
      st.masks = export_masks(LayerMaker{L, st.thickness, [&](size_t k, std::vector<SlicePart>& parts) {
                                           made.make(k, parts);
                                           engrave_parts(parts, k, k + 1, members, labels);
                                           compensate_faded_layers(parts, k, part_owners(members, k, k + 1), objects,
                                                                   profile, false);
                                         },
                                         supports},
                              profile, output_path, sub_progress(rest, share, 1), checks.get());
      made.stats(st);
      return st;
    }
  }
  std::vector<size_t> first = plate_ranges(members, L, budget);
  // Slicing directly, memory kept for reuse (buffers, a cached encoding) is given back before
  // settling for ranges; reusing, the encoding in use would only leave the cache.
  if (!o.encoding && o.memory_share > 0 && first.size() > 2 && reclaim_memory() > 0)
    first = plate_ranges(members, L, range_budget(o));
  st.ranges = first.size() - 1;

  const std::vector<size_t> objects = object_layers(members);
  SliceChunks chunks{first, st.thickness, [&](size_t i, const Progress& range_progress) {
                       const auto t = std::chrono::steady_clock::now();
                       std::vector<SlicePart> parts =
                           plate_range(members, frame, first[i], first[i + 1], st, range_progress);
                       st.slicing_seconds += seconds_since(t);
                       engrave_parts(parts, first[i], first[i + 1], members, labels);
                       if (o.whole_stack) o.whole_stack(parts);
                       compensate_faded_layers(parts, first[i], part_owners(members, first[i], first[i + 1]),
                                               objects, profile, true);
                       return parts;
                     },
                     supports};
  st.masks = export_masks(chunks, profile, output_path, rest, checks.get());
  return st;
}

}  // namespace slicereuse
