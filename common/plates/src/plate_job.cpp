#include "slicereuse/plates/plate_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

// Layers [a, b) of an encoding, as an encoding of their own planes: its thickness is 0, so a
// transfer cuts the target on exactly these planes (transfer_layers.h, target_planes) instead
// of extending them to the target's top. Their edge ends into *ends when edge_ends is given.
Slices encoding_layers(const Slices& enc, const Buffer<uint32_t>* edge_ends, size_t a, size_t b,
                       Buffer<uint32_t>* ends) {
  Slices s;
  s.fingerprint = enc.fingerprint;
  s.layer_z.assign(enc.layer_z.begin() + long(a), enc.layer_z.begin() + long(b));
  const uint64_t c0 = enc.layer_begin[a], c1 = enc.layer_begin[b];
  const uint64_t p0 = enc.contour_begin[c0], p1 = enc.contour_begin[c1];
  for (size_t k = a; k <= b; ++k) s.layer_begin.push_back(enc.layer_begin[k] - c0);
  for (uint64_t c = c0; c <= c1; ++c) s.contour_begin.push_back(enc.contour_begin[c] - p0);
  s.contour_open.assign(enc.contour_open.begin() + long(c0), enc.contour_open.begin() + long(c1));
  s.face.resize(p1 - p0);
  s.edge.resize(p1 - p0);
  s.t.resize(p1 - p0);
  std::memcpy(s.face.data(), enc.face.data() + p0, (p1 - p0) * sizeof(uint32_t));
  std::memcpy(s.edge.data(), enc.edge.data() + p0, p1 - p0);
  std::memcpy(s.t.data(), enc.t.data() + p0, (p1 - p0) * sizeof(double));
  if (edge_ends) {
    ends->resize(2 * (p1 - p0));
    std::memcpy(ends->data(), edge_ends->data() + 2 * p0, 2 * (p1 - p0) * sizeof(uint32_t));
  }
  return s;
}

// A member's layers for plate layers [first, first + s.layers()).
struct Piece {
  Slices s;
  size_t first;
};

// The plate's layers [a, b): every piece's layer at that height, members one after another.
// The contours are laid out first; the points, a layer's of a piece being one block, are then
// copied on all cores: the copy fills fresh pages on a plate's first range, which the kernel
// zeroes on the faulting thread.
Slices merge_layers(const std::vector<Piece>& pieces, const std::vector<double>& planes, size_t a, size_t b,
                    double z_start, double h) {
  Slices out;
  out.z_start = z_start + double(a) * h;
  out.thickness = h;
  out.layer_z.assign(planes.begin() + long(a), planes.begin() + long(b));
  out.layer_begin.push_back(0);
  out.contour_begin.push_back(0);
  struct Block {
    const double* from;
    uint64_t to, n;  // points
  };
  std::vector<Block> blocks;
  uint64_t q = 0;
  for (size_t k = a; k < b; ++k) {
    for (const Piece& p : pieces) {
      if (k < p.first || k >= p.first + p.s.layers()) continue;
      const size_t local = k - p.first;
      const uint64_t c0 = p.s.layer_begin[local], c1 = p.s.layer_begin[local + 1];
      const uint64_t p0 = p.s.contour_begin[c0];
      blocks.push_back({p.s.xyz.data() + 3 * p0, q, p.s.contour_begin[c1] - p0});
      for (uint64_t c = c0; c < c1; ++c) {
        q += p.s.contour_begin[c + 1] - p.s.contour_begin[c];
        out.contour_begin.push_back(q);
        out.contour_open.push_back(p.s.contour_open[c]);
      }
    }
    out.layer_begin.push_back(out.contour_open.size());
  }
  out.xyz.resize(3 * q);
  const long long n = static_cast<long long>(blocks.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (long long i = 0; i < n; ++i) {
    const Block& block = blocks[size_t(i)];
    std::memcpy(out.xyz.data() + 3 * block.to, block.from, 3 * block.n * sizeof(double));
  }
  return out;
}

// The plate's layers [a, b): each member's own layers there (own[m]: how many it has), by
// transfer where the encoding has them, else sliced directly; merged member after member.
Slices plate_range(const std::vector<Mesh>& placed, const PlateJobOptions& o, const std::vector<double>& planes,
                   const std::vector<size_t>& own, size_t a, size_t b, PlateJobStats& st, const Progress& progress) {
  const size_t n = placed.size(), Le = o.encoding ? o.encoding->layers() : 0;
  // The range's encoding, shared by every member that has all its layers; a shorter member gets
  // one cut at its own top (transferred onto planes above a member's top, layers would fail
  // their certificate, and a range failing most would be sliced directly).
  struct Sub {
    size_t end = 0;
    Slices enc;
    Buffer<uint32_t> ends;
  };
  Sub shared, cut;
  auto sub_to = [&](size_t te) -> const Sub& {
    Sub& s = te == std::min(b, Le) ? shared : cut;
    if (s.end != te || s.enc.layer_z.empty()) {
      s.enc = encoding_layers(*o.encoding, o.edge_ends, a, te, &s.ends);
      s.end = te;
    }
    return s;
  };
  std::vector<Piece> pieces;
  for (size_t m = 0; m < n; ++m) {
    const Progress mp = sub_progress(progress, double(m) / double(n), double(m + 1) / double(n));
    const size_t e = std::min(b, own[m]);
    const size_t te = std::min(e, Le);  // the member's layers the encoding has
    if (a < te) {
      TransferStats ts;
      const TransferOptions exact(TransferMode::Exact, false);
      if (a == 0 && te == Le && own[m] == Le) {
        // The whole encoding, and the member has exactly its layers: transferred as it is (a
        // transfer's planes run to the member's top, here the encoding's last), with no copy.
        pieces.push_back({o.edge_ends ? transfer_contours(*o.encoding, *o.edge_ends, placed[m], exact, &ts, mp)
                                      : transfer_contours(*o.encoding, placed[m], exact, &ts, mp),
                          a});
      } else {
        const Sub& sub = sub_to(te);
        pieces.push_back({o.edge_ends ? transfer_contours(sub.enc, sub.ends, placed[m], exact, &ts, mp)
                                      : transfer_contours(sub.enc, placed[m], exact, &ts, mp),
                          a});
      }
      st.transferred_layers += ts.transferred_layers;
      st.resliced_layers += ts.resliced_layers;
    }
    // Layers above the encoding's (a member taller than the source), or all of them when
    // slicing directly.
    const size_t d = std::max(a, te);
    if (d < e) {
      pieces.push_back({slice_planes(placed[m], {planes.begin() + long(d), planes.begin() + long(e)}, mp, false), d});
      st.resliced_layers += e - d;
    }
  }
  if (pieces.size() == 1 && pieces[0].first == a && pieces[0].s.layers() == b - a) {
    // One member fills the range (a plate of one member): its layers are the plate's, uncopied.
    Slices s = std::move(pieces[0].s);
    s.z_start = st.z_start + double(a) * st.thickness;
    s.thickness = st.thickness;
    return s;
  }
  return merge_layers(pieces, planes, a, b, st.z_start, st.thickness);
}

}  // namespace

std::vector<double> plate_planes(const std::vector<Mesh>& placed, const PlateJobOptions& o, double* z_start,
                                 double* thickness) {
  if (placed.empty()) throw Error("a plate needs at least one member");
  double lowest = INFINITY, top = -INFINITY;
  for (const Mesh& m : placed) {
    validate_mesh(m);
    const ZRange z = z_range(m);
    lowest = std::min(lowest, z.min);
    top = std::max(top, z.max);
  }
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
  return layer_planes(*z_start, *thickness, top);
}

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& o, const PrinterProfile& profile,
                           const std::string& output_path, const Progress& progress) {
  PlateJobStats st;
  const std::vector<double> planes = plate_planes(placed, o, &st.z_start, &st.thickness);
  const size_t L = planes.size(), n = placed.size();
  // Each member's own layer count: its direct slicing from the plate's z_start stops at its top.
  std::vector<size_t> own(n, 0);
  for (size_t m = 0; m < n; ++m) {
    const double top = z_range(placed[m]).max;
    if (st.z_start < top) own[m] = layer_planes(st.z_start, st.thickness, top).size();
  }
  std::vector<const Mesh*> meshes;
  for (const Mesh& m : placed) meshes.push_back(&m);
  // A range holds every member's points twice (the members' layers and the plate's merged copy).
  const std::vector<size_t> first = layer_chunks(meshes, planes, o.range_budget_bytes, 2 * 3 * sizeof(double));
  st.ranges = first.size() - 1;
  st.layers = L;

  SliceChunks chunks{first, st.thickness, [&](size_t i, const Progress& range_progress) {
                       const auto t = std::chrono::steady_clock::now();
                       Slices s = plate_range(placed, o, planes, own, first[i], first[i + 1], st, range_progress);
                       st.points += s.points();
                       st.slicing_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
                       return s;
                     }};
  st.masks = export_masks(chunks, profile, output_path, progress);
  return st;
}

}  // namespace slicereuse
