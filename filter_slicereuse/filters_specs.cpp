// The four filters' names, descriptions, meshes they need, and parameters (see filter_api.h).
#include "filter_api.h"
#include "slicereuse/error.h"

namespace slicereuse::plugin {
namespace {

const char* const kReference =
    "<p>Method: <i>T.-H. Kwok, H. Ye, Y. Chen, C. Zhou, W. Xu</i>, "
    "<b>\"Mass Customization: Reuse of Digital Slicing for Additive Manufacturing\"</b>, "
    "ASME IDETC/CIE 2016; J. Comput. Inf. Sci. Eng. 17(2), 2017.</p>";

ParamSpec param(const char* name, ParamType type, const char* label, const char* tooltip) {
  ParamSpec p;
  p.name = name;
  p.type = type;
  p.label = label;
  p.tooltip = tooltip;
  return p;
}

ParamSpec number_param(const char* name, ParamType type, const char* label, double value,
                       const char* tooltip) {
  ParamSpec p = param(name, type, label, tooltip);
  p.default_number = value;
  return p;
}

ParamSpec file_param(const char* name, ParamType type, const char* label, const char* filter,
                     const char* tooltip) {
  ParamSpec p = param(name, type, label, tooltip);
  p.file_filter = filter;
  return p;
}

ParamSpec enum_param(const char* name, const char* label, std::vector<std::string> values,
                     const char* tooltip) {
  ParamSpec p = param(name, ParamType::Enum, label, tooltip);
  p.enum_values = std::move(values);
  return p;
}

FilterSpec slice_spec() {
  FilterSpec f{FilterId::SliceWithEncoding, "Slice Mesh with Encoding", "slice_mesh_with_encoding",
               std::string(
                   "<p>Slices the current mesh into horizontal layers of closed contours for "
                   "layer-based 3D printing, and records for every contour point its "
                   "<i>encoding</i>: the mesh face it lies on and its area (barycentric) "
                   "coordinates there. The encoding lets <i>Transfer Slicing to Mesh</i> produce "
                   "the contours of any customized member of the same product family (same "
                   "triangles, moved vertices) without slicing it again.</p>"
                   "<p>Layer <i>k</i> spans [z_start + k&middot;h, z_start + (k+1)&middot;h] and "
                   "is cut by its mid-plane z_start + (k+&frac12;)&middot;h, where h is the layer "
                   "thickness; layers are added while their bottom is below the mesh top. "
                   "Lengths are in mm (mesh units). Outer contours run counter-clockwise and holes "
                   "clockwise seen from +z; holes in the mesh give open contours, which are kept "
                   "and counted.</p>"
                   "<p>Writes a contour file and an encoding file (text .ctr / .enc, or binary "
                   ".srb; see docs/formats.md). Both appear together or not at all. Optionally "
                   "adds a few layers' contours as a new edge-mesh layer to look at.</p>") +
                   kReference,
               Arity::CurrentMesh,
               kLayerClass,
               true,
               {}};
  f.params = {
      number_param("layer_thickness", ParamType::Float, "Layer thickness (mm)", 0.1,
                   "Distance between consecutive slicing planes, in mm; must be greater than 0."),
      number_param("z_start", ParamType::Float, "Start height (mm)", -1e30,
                   "Height of the bottom of the first layer, in mm. Any value at or below -1e29 "
                   "(the default, -1e30) means: the lowest vertex of the mesh."),
      file_param("contour_file", ParamType::FileSave, "Contour file", "*.ctr *.srb",
                 "Where to write the contour points (format chosen by File format). "
                 "Empty: no contour file is written."),
      file_param("encoding_file", ParamType::FileSave, "Encoding file", "*.enc *.srb",
                 "Where to write the encoding (face and area coordinates of every point) used "
                 "by Transfer Slicing to Mesh. Empty: no encoding file is written."),
      enum_param("file_format", "File format", {"text", "binary"},
                 "text: readable .ctr/.enc files; binary: compact, faster .srb files with "
                 "checksums. Both keep every coordinate exactly."),
      number_param("preview_layers", ParamType::Int, "Preview layers", 0,
                   "Adds the contours of up to this many evenly spaced layers as a new edge-mesh "
                   "layer, for a visual check. 0: no layer is added."),
  };
  return f;
}

FilterSpec transfer_spec() {
  FilterSpec f{FilterId::TransferSlicing, "Transfer Slicing to Mesh", "transfer_slicing_to_mesh",
               std::string(
                   "<p>Computes the layer contours of a customized family member from the "
                   "encoding of a member that was sliced before (<i>Slice Mesh with "
                   "Encoding</i>), instead of slicing it again. The target mesh must have "
                   "exactly the same triangles as the sliced one (same connectivity, only vertex "
                   "positions differ); this is checked with a fingerprint of the faces.</p>"
                   "<p><b>exact</b> mode moves every point along its mesh edge to where the same "
                   "plane cuts that edge on the target; a layer whose edges no longer straddle "
                   "its plane the same way is re-sliced directly on the target, so the result "
                   "equals slicing the target. <b>barycentric</b> mode applies the encoded area "
                   "coordinates to the target's faces (the method's Eq. 2); points may leave the "
                   "layer plane where the target changed in z, and the largest such deviation "
                   "(mm) is reported.</p>"
                   "<p>Writes the target's contour file and its own encoding, so it can be a "
                   "source later. Both appear together or not at all.</p>") +
                   kReference,
               Arity::MeshParameters,
               kLayerClass,
               true,
               {}};
  f.params = {
      file_param("encoding_file", ParamType::FileOpen, "Source encoding file", "*.enc *.srb",
                 "Encoding file written by Slice Mesh with Encoding for a member of the family."),
      param("target_mesh", ParamType::Mesh, "Target mesh",
                "The family member that receives the slicing; it must have the same faces as "
                "the sliced mesh. In a .mlx script: the 0-based index of the mesh as loaded."),
      enum_param("mode", "Mode", {"exact", "barycentric"},
                 "exact: identical to slicing the target (points stay on the planes); "
                 "barycentric: the paper's area-coordinate mapping, fastest, points may leave "
                 "the planes."),
      param("map_file", ParamType::String, "Cross-parameterization map",
                "Map between meshes of different connectivity; not supported yet, leave empty "
                "(the target must have the source's faces)."),
      file_param("contour_file", ParamType::FileSave, "Contour file", "*.ctr *.srb",
                 "Where to write the target's contour points (text .ctr unless the name ends "
                 "in .srb). Empty: not written."),
      file_param("target_encoding_file", ParamType::FileSave, "Target encoding file",
                 "*.enc *.srb",
                 "Where to write the target's own encoding (text .enc unless the name ends in "
                 ".srb). Empty: not written."),
  };
  return f;
}

// The display and placement of the masks, shared by Export Mask Images and Make Print Job
// (read back by read_printer_profile).
std::vector<ParamSpec> printer_params() {
  return {
      number_param("width_px", ParamType::Int, "Width (pixels)", 1024,
                   "Image width in pixels (the printer's display resolution)."),
      number_param("height_px", ParamType::Int, "Height (pixels)", 768,
                   "Image height in pixels (the printer's display resolution)."),
      number_param("pixel_size_x_um", ParamType::Float, "Pixel size x (um)", 75,
                   "Width of one pixel on the build plane, in micrometres."),
      number_param("pixel_size_y_um", ParamType::Float, "Pixel size y (um)", 75,
                   "Height of one pixel on the build plane, in micrometres."),
      number_param("offset_x_mm", ParamType::Float, "Offset x (mm)", 0,
                   "Shift of the model along x from the image centre, in mm."),
      number_param("offset_y_mm", ParamType::Float, "Offset y (mm)", 0,
                   "Shift of the model along y from the image centre, in mm."),
      number_param("mirror_x", ParamType::Bool, "Mirror x", 0,
                   "Flip the images left-right (for printers whose optics mirror the display)."),
      number_param("mirror_y", ParamType::Bool, "Mirror y", 0, "Flip the images top-bottom."),
      number_param("antialiasing", ParamType::Bool, "Anti-aliasing", 0,
                   "Write 8-bit grey levels from pixel coverage instead of black/white masks."),
  };
}

FilterSpec masks_spec() {
  FilterSpec f{FilterId::ExportMasks, "Export Mask Images", "export_mask_images",
               std::string(
                   "<p>Rasterizes the layers of a contour file into one mask image per layer "
                   "for mask-projection (DLP/LCD) printers: a folder of PNG images "
                   "(NNNNN.png), or a Prusa SL1 archive when the output path ends in .sl1.</p>"
                   "<p>A pixel is lit when its centre lies inside the layer by the nonzero "
                   "winding rule of the closed contours; open contours are ignored and counted. "
                   "The model's XY origin sits at the image centre, shifted by the offsets; row "
                   "0 is the top of the image (largest y). Pixel sizes are in micrometres, "
                   "offsets in mm. With an empty contour file the contours come from the current "
                   "layer, a contour file opened in MeshLab (.ctr, .srb or .cli).</p>") +
                   kReference,
               Arity::None,
               kLayerClass,
               false,
               {}};
  f.params = {
      file_param("contour_file", ParamType::FileOpen, "Contour file", "*.ctr *.srb",
                 "Contour file written by Slice Mesh with Encoding or Transfer Slicing to Mesh. "
                 "Empty: the current layer, a contour file opened with File > Import Mesh "
                 "(.ctr, .srb, .cli)."),
      file_param("output_path", ParamType::FileSave, "Output folder or .sl1", "*.sl1",
                 "A folder for PNG images (created if missing; its parent must exist), or a "
                 "file name ending in .sl1 for a Prusa SL1 archive."),
  };
  const std::vector<ParamSpec> printer = printer_params();
  f.params.insert(f.params.end(), printer.begin(), printer.end());
  return f;
}

FilterSpec print_job_spec() {
  FilterSpec f{FilterId::MakePrintJob, "Make Print Job", "make_print_job",
               std::string(
                   "<p>Makes the current mesh's print job in one step, in memory: its layers, "
                   "either transferred from a family member's encoding (as <i>Transfer Slicing "
                   "to Mesh</i> in exact mode, so the result equals direct slicing) or sliced "
                   "directly when no encoding file is given, then its masks (as <i>Export Mask "
                   "Images</i>), with no contour file in between unless one is asked for.</p>"
                   "<p>The last encoding file read stays in memory (one entry, checked against "
                   "the file's size, modification time and checksum), so a script or a "
                   "pymeshlab loop over a family's members reads it only once. A member whose "
                   "layers fail their certificate (e.g. changed in z) is sliced directly.</p>") +
                   kReference,
               Arity::CurrentMesh,
               kLayerClass,
               true,
               {}};
  f.params = {
      file_param("encoding_file", ParamType::FileOpen, "Source encoding file", "*.enc *.srb",
                 "Encoding file written by Slice Mesh with Encoding for a member of the family; "
                 "the current mesh must have its faces. Empty: slice the current mesh directly."),
      number_param("layer_thickness", ParamType::Float, "Layer thickness (mm)", 0.1,
                   "Used when slicing directly (no encoding file): distance between slicing "
                   "planes, in mm. With an encoding file, the encoding's layers are used."),
      number_param("z_start", ParamType::Float, "Start height (mm)", -1e30,
                   "Used when slicing directly: bottom of the first layer, in mm; at or below "
                   "-1e29 (the default): the lowest vertex of the mesh."),
      file_param("contour_file", ParamType::FileSave, "Contour file", "*.ctr *.srb",
                 "Also write the layers' contour points here (text .ctr unless the name ends in "
                 ".srb). Empty (the default): no contour file."),
      file_param("output_path", ParamType::FileSave, "Output .sl1 or folder", "*.sl1",
                 "A file name ending in .sl1 for a Prusa SL1 archive, or a folder for PNG "
                 "images (created if missing; its parent must exist)."),
  };
  const std::vector<ParamSpec> printer = printer_params();
  f.params.insert(f.params.end(), printer.begin(), printer.end());
  return f;
}

FilterSpec compare_spec() {
  FilterSpec f{FilterId::CompareMasks, "Compare Mask Stacks", "compare_mask_stacks",
               std::string(
                   "<p>Compares two stacks of mask images (folders of PNG images or .sl1 "
                   "archives, e.g. from a transferred and a directly sliced member) layer by "
                   "layer. The similarity of a layer is S = (pixels equal in both images) / "
                   "(all pixels), so S = 1 means identical masks. Logs the lowest S, the layer "
                   "where it occurs and the total number of differing pixels; optionally writes "
                   "one CSV row per layer. The stacks must have the same number of layers and "
                   "image size. The current mesh is not used.</p>") +
                   kReference,
               Arity::None,
               kLayerClass | kMeasureClass,
               false,
               {}};
  f.params = {
      file_param("stack_a", ParamType::FileOpen, "Stack A", "*.sl1",
                 "First mask stack: a folder of PNG images or a .sl1 archive."),
      file_param("stack_b", ParamType::FileOpen, "Stack B", "*.sl1",
                 "Second mask stack: a folder of PNG images or a .sl1 archive."),
      file_param("report_file", ParamType::FileSave, "Report file (CSV)", "*.csv",
                 "Where to write one CSV row per layer (layer, similarity, differing pixels). "
                 "Empty: no report is written."),
  };
  return f;
}

}  // namespace

const std::vector<FilterSpec>& filter_specs() {
  static const std::vector<FilterSpec> specs = {slice_spec(), transfer_spec(), masks_spec(),
                                                compare_spec(), print_job_spec()};
  return specs;
}

const FilterSpec* find_filter_spec(int id) {
  for (const FilterSpec& f : filter_specs())
    if (int(f.id) == id) return &f;
  return nullptr;
}

}  // namespace slicereuse::plugin
