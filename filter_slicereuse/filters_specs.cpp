// The filters' names, descriptions, meshes they need, and parameters (see filter_api.h).
#include "filter_api.h"
#include "slicereuse/util/error.h"

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
                   "Encoding</i>), instead of slicing it again. Without a map, the target mesh "
                   "must have exactly the same triangles as the sliced one (same connectivity, "
                   "only vertex positions differ); this is checked with a fingerprint of the "
                   "faces. A target with other triangles (remeshed, renumbered, another scan) "
                   "needs a <i>map file</i> from <i>Cross-Parameterize Meshes</i>.</p>"
                   "<p><b>exact</b> mode moves every point along its mesh edge to where the same "
                   "plane cuts that edge on the target; through a map, it traces the target's "
                   "own contour from the faces the mapped points land on. A layer it cannot "
                   "certify is re-sliced directly on the target, so the result equals slicing "
                   "the target. <b>barycentric</b> mode applies the encoded area coordinates to "
                   "the target's faces (the method's Eq. 2), or carries each point through the "
                   "map and places it on the target's section at its layer's height (the nearest "
                   "point of it); the largest distance of a carried point from its plane before "
                   "that (mm) is reported, and so are contours dropped because the target has no "
                   "surface at their height near them.</p>"
                   "<p>Writes the target's contour file and, in exact mode, its own encoding, so "
                   "it can be a source later. Both appear together or not at all.</p>") +
                   kReference,
               Arity::MeshParameters,
               kLayerClass,
               true,
               {}};
  f.params = {
      file_param("encoding_file", ParamType::FileOpen, "Source encoding file", "*.enc *.srb",
                 "Encoding file written by Slice Mesh with Encoding for a member of the family."),
      param("target_mesh", ParamType::Mesh, "Target mesh",
                "The family member that receives the slicing: with the sliced mesh's faces, or "
                "the target of map_file. In a .mlx script: the 0-based index of the mesh as "
                "loaded."),
      enum_param("mode", "Mode", {"exact", "barycentric"},
                 "exact: identical to slicing the target (points stay on the planes); "
                 "barycentric: the paper's area-coordinate mapping, fastest, points may leave "
                 "the planes."),
      file_param("map_file", ParamType::FileOpen, "Cross-parameterization map", "*.map *.srb",
                 "Map from the sliced mesh onto a target with other faces, written by "
                 "Cross-Parameterize Meshes (.map text or .srb binary). Empty: the target must "
                 "have the sliced mesh's faces."),
      file_param("contour_file", ParamType::FileSave, "Contour file", "*.ctr *.srb",
                 "Where to write the target's contour points (text .ctr unless the name ends "
                 "in .srb). Empty: not written."),
      file_param("target_encoding_file", ParamType::FileSave, "Target encoding file",
                 "*.enc *.srb",
                 "Where to write the target's own encoding (text .enc unless the name ends in "
                 ".srb). Empty: not written. Through a map, exact mode only (barycentric points "
                 "do not lie on the target's edges)."),
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
                   "layers fail their certificate (e.g. changed in z) is sliced directly.</p>"
                   "<p>When directly sliced contours would take more than a quarter of the memory "
                   "still available (a large part at a very fine layer), the mesh is sliced and "
                   "its masks made a range of layers at a time, so memory stays bounded; the log "
                   "says how many ranges.</p>") +
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

// Remeshing class: MeshLab lists its own maps between meshes there (Iso Parametrization and its
// transfer between meshes), while Texture holds filters that make UV coordinates and images.
FilterSpec crossparam_spec() {
  FilterSpec f{FilterId::CrossParameterize, "Cross-Parameterize Meshes", "cross_parameterize_meshes",
               std::string(
                   "<p>Computes a map between two members of a product family whose meshes differ "
                   "in connectivity (other vertex count, triangles or order: a remeshed model, "
                   "another scan), so that <i>Transfer Slicing to Mesh</i> can reuse the source's "
                   "slicing on the target. Each source vertex gets a point on the target (face "
                   "and barycentric coordinates), written to the map file (.map text or .srb "
                   "binary; see docs/formats.md) with both meshes' fingerprints.</p>"
                   "<p>With <b>in-plane</b> on (the method's constraint), a point at height h "
                   "maps to a point at height h on the target, so each source layer maps into the "
                   "same layer of the target. Corresponding landmarks (MeshLab PickPoints .pp "
                   "files, matched by point name; a landmark snaps to the nearest surface point) "
                   "steer the correspondence; without them it is found automatically. Meshes "
                   "of different genus cannot be mapped and are refused.</p>"
                   "<p>Reports flipped triangles (0 for a bijective map), the maximum and RMS "
                   "height error of mapped vertices (mm), area and angle distortion, and the "
                   "time. Colours both meshes per vertex by corresponding patch: the same colour "
                   "marks corresponding regions, to check the map at a glance.</p>") +
                   kReference,
               Arity::MeshParameters,
               kRemeshingClass,
               true,
               {}};
  f.colors_vertices = true;
  f.params = {
      param("source_mesh", ParamType::Mesh, "Source mesh",
            "The sliced family member (whose encoding will be transferred). In a .mlx script: "
            "the 0-based index of the mesh as loaded."),
      param("target_mesh", ParamType::Mesh, "Target mesh",
            "The member with other connectivity that the source is mapped onto. In a .mlx "
            "script: the 0-based index of the mesh as loaded."),
      file_param("source_landmarks", ParamType::FileOpen, "Source landmarks", "*.pp",
                 "PickPoints file (.pp) of landmarks on the source, matched to the target's by "
                 "name. Empty (with target_landmarks empty): found automatically."),
      file_param("target_landmarks", ParamType::FileOpen, "Target landmarks", "*.pp",
                 "PickPoints file (.pp) of the corresponding landmarks on the target, with the "
                 "same names. Empty (with source_landmarks empty): found automatically."),
      number_param("in_plane", ParamType::Bool, "In-plane", 1,
                   "Keep heights: a source point at height h maps to height h on the target, so "
                   "layers map onto the same layers (the method's in-plane constraint)."),
      file_param("map_file", ParamType::FileSave, "Map file", "*.map *.srb",
                 "Where to write the map (text .map unless the name ends in .srb), for "
                 "Transfer Slicing to Mesh's map_file."),
  };
  return f;
}

}  // namespace

const std::vector<FilterSpec>& filter_specs() {
  static const std::vector<FilterSpec> specs = {slice_spec(), transfer_spec(), masks_spec(), compare_spec(),
                                                print_job_spec(), crossparam_spec()};
  return specs;
}

const FilterSpec* find_filter_spec(int id) {
  for (const FilterSpec& f : filter_specs())
    if (int(f.id) == id) return &f;
  return nullptr;
}

}  // namespace slicereuse::plugin
