// "Make Print Job": the current mesh's layers (transferred from a cached encoding, or sliced
// directly) and its masks in one filter, in memory; a contour file only when asked for.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

struct PrintJobParams {
  std::string mesh_file;
  JobLayers layers;
  JobSupports supports;
  JobChecks checks;
  JobLabels labels;
  JobHollowing hollowing;
  std::string contour_file;
  std::string output_path;
  PrinterSettings printer;
};

ParamList<PrintJobParams> print_job_params() {
  ParamList<PrintJobParams> l;
  add_mesh_file(l, &PrintJobParams::mesh_file)
      .include(&PrintJobParams::layers,
            job_layer_params("Encoding file written by Slice Mesh with Encoding for a member of the family: the "
                             "current mesh's layers are transferred from it (exact). Empty: slice the current mesh "
                             "directly."))
      .include(&PrintJobParams::supports, job_support_params())
      .include(&PrintJobParams::checks, job_check_params())
      .include(&PrintJobParams::labels, job_label_params())
      .include(&PrintJobParams::hollowing, job_hollowing_params())
      .file(&PrintJobParams::contour_file, ParamType::FileSave, "contour_file", "Contour file", "*.ctr *.srb", nullptr,
            "Also write the layers' contour points here (text .ctr unless the name ends in .srb). Empty (the "
            "default): no contour file.");
  add_print_file_output(l, &PrintJobParams::output_path,
                        "The print file, or a folder for PNG images (created if missing; its parent must exist).")
      .include(&PrintJobParams::printer, printer_params());
  return l;
}

// The job is a plate of one member, the current mesh where it stands (plate_job.h): the same
// layers, ranges of layers within memory, and masks as Make Plate Job.
Result run_print_job(const PrintJobParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Make Print Job", p.printer);

  keep_buffers_for_the_next_job();
  JobMesh job = job_mesh(p.mesh_file, host);
  const std::vector<Mesh> member{std::move(job.mesh)};
  const Progress progress = host.progress();
  PlateJobOptions o = plate_job_options(p.layers);
  set_job_checks(p.checks, o);
  set_job_hollowing(p.hollowing, host, member[0], o);
  o.names = {p.mesh_file.empty() ? "the current mesh" : job.name};
  set_job_labels(p.labels, {job.name}, o);
  bool cached = false;
  std::shared_ptr<const CachedEncoding> entry;
  if (!p.layers.encoding_file.empty()) {
    entry = encoding_cache().get(p.layers.encoding_file, {&member[0]}, &cached, sub_progress(progress, 0, 0.2));
    o.encoding = &entry->encoding;
    o.edge_ends = &entry->edge_ends;
  }
  const double from = entry ? 0.2 : 0, supported = p.supports.mode == JobSupportsMode::None ? from : from + 0.2;
  const std::vector<MemberSupports> supports =
      job_member_supports({&member[0]}, p.supports, o, sub_progress(progress, from, supported));
  if (!supports.empty()) o.supports = {&supports[0].tree.mesh};
  // The contour file appears only with the masks: staged until they are written.
  StagedOutputs outputs;
  if (!p.contour_file.empty())
    o.whole_stack = [&](const std::vector<SlicePart>& parts) {
      write_contour_file(outputs.file(p.contour_file), parts.at(0).slices, format_for_name(p.contour_file));
    };
  const PlateJobStats st = export_plate(member, o, profile, p.output_path, sub_progress(progress, supported, 1));
  outputs.commit();

  const double seconds = seconds_since(start);
  const std::string& why = st.direct_reasons.at(0);
  // Made in ranges, the masks' seconds hold the slicing between them; made where drawn, the
  // layers' making is inside the masks' seconds.
  const double masks_seconds = st.masks.seconds - (st.ranges > 0 ? st.slicing_seconds : 0);
  host.log(format("Make Print Job: %zu layers (%zu transferred, %zu sliced%s), %zu points, to %s, %.3f s "
                  "(%s %.3f s%s, masks %.3f s)",
                  st.layers, st.transferred_layers, st.resliced_layers,
                  st.ranges > 1 ? format(" in %zu ranges of layers, to stay within memory", st.ranges).c_str() : "",
                  st.points, p.output_path.c_str(), seconds, entry ? "transfer" : "slicing", st.slicing_seconds,
                  entry ? (cached ? ", encoding in memory" : ", encoding read") : "", masks_seconds));
  if (!why.empty()) host.log("Make Print Job: sliced directly, not by reuse: " + why);
  const MemberSupports none;
  const MemberSupports& sup = supports.empty() ? none : supports[0];
  if (!supports.empty())
    host.log(format("Make Print Job: %zu support points (%s), %zu pillars, %zu layers below the part, %.3f s",
                    sup.points.size(),
                    sup.transferred ? format("%zu kept, %zu moved, %zu added, %zu dropped", sup.transfer.kept,
                                             sup.transfer.moved, sup.transfer.added, sup.transfer.dropped)
                                          .c_str()
                                    : "generated",
                    sup.tree.pillars, sup.layers_below, support_seconds(sup)));
  if (sup.kept_out > 0)
    host.log(format("Make Print Job: %zu support points dropped: their heads would reach into a drain hole",
                    sup.kept_out));
  log_display_warning(host, "Make Print Job", st.masks, profile);
  Result result = {{"layers", int64_t(st.layers)},
                   {"points", int64_t(st.points)},
                   {"transferred_layers", int64_t(st.transferred_layers)},
                   {"resliced_layers", int64_t(st.resliced_layers)},
                   {"encoding_cached", int64_t(cached)},
                   {"layer_ranges", int64_t(st.ranges)},
                   {"reused", int64_t(entry && why.empty())},
                   {"direct_reason", why},
                   {"output_path", p.output_path},
                   {"read_seconds", job.read_seconds},
                   {"slicing_seconds", st.slicing_seconds},
                   {"masks_seconds", masks_seconds},
                   {"support_seconds", support_seconds(sup)},
                   {"seconds", seconds}};
  add_support_figures(sup, "", result);
  add_display_figures(st.masks, result);
  report_printability(host, "Make Print Job", "", st, o.names, false, result);
  report_labels(host, "Make Print Job", o, st, o.names, false, result);
  report_hollowing(host, "Make Print Job", "", st, o.names, false, result);
  return result;
}

}  // namespace

FilterSpec print_job_filter() {
  const std::string description = std::string(
      "<p>Makes the current mesh's print job (or a mesh file's, read without a layer) in one step, in memory: its layers, "
      "either transferred from a family member's encoding (as <i>Transfer Slicing "
      "to Mesh</i> in exact mode, so the result equals direct slicing) or sliced "
      "directly when no encoding file is given, then its masks (as <i>Export Mask "
      "Images</i>), with no contour file in between unless one is asked for. It is "
      "<i>Make Plate Job</i>'s pipeline for a plate of one, the mesh where it stands.</p>"
      "<p>The last encoding file read stays in memory (one entry, checked against "
      "the file's content), so a script or a pymeshlab loop over a family's members "
      "reads it only once; <i>Free Cached Memory</i> releases it, and so does a job "
      "that needs the memory. Layers that fail their certificate (e.g. a member "
      "changed in z) are sliced directly; so is a mesh whose faces are not the "
      "encoding's mesh's (another connectivity), the result saying why, unless "
      "<i>strict</i> is on.</p>"
      "<p>When directly sliced contours would take more than a quarter of the memory "
      "still available (a large part at a very fine layer), the mesh is sliced and "
      "its masks made a range of layers at a time, so memory stays bounded; the log "
      "says how many ranges.</p>"
      "<p>The masks are checked as they are written, as UVtools checks a print file (islands, overhangs, resin "
      "traps, suction cups, parts at the display's edges: see <i>Check Printability</i>); with <i>require "
      "printable</i>, a file holding an island, a resin trap or a suction cup is refused and not written.</p>"
      "<p>With <i>supports</i>, the mesh gets support points (generated on it, or a source's "
      "transferred from a support-points file, certified and completed) and the supports built "
      "from them (as <i>Build Supports</i>); they are sliced with the mesh, on the layers below "
      "it.</p>"
      "<p>With <i>labels</i>, the mesh's name (or its row of a labels file) is cut into its base, mirrored to read "
      "from below (or upright into the <i>label side</i>), as large as fits up to the label height, on the "
      "contours, so a reused member's label is direct slicing's.</p>") +
      kReference;
  return typed_filter({FilterId::MakePrintJob, "Make Print Job", "make_print_job", description, Arity::None,
                       kLayerClass, false},
                      print_job_params(), run_print_job,
                      with_printability_keys(with_display_keys({"layers", "points", "transferred_layers", "resliced_layers", "encoding_cached",
                                         "layer_ranges", "reused", "direct_reason", "output_path", "support_points", "kept",
                                         "moved", "added", "dropped", "read_seconds", "slicing_seconds", "support_seconds",
                                         "masks_seconds", "seconds", "label_height_mm", "cavity_mm3", "drain_holes"}),
                                             false));
}

}  // namespace slicereuse::plugin
