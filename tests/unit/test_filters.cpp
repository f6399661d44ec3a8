// Every filter run through a fake host, without MeshLab: the specs and the examples that list
// them, the typed parameters (a mistyped or missing name, a value out of range, each refused in
// words), and the result dicts with every figure the filters log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "error_of.h"
#include "fake_host.h"
#include "filter_api.h"
#include "mask_stack.h"
#include "mesh_file_writers.h"
#include "shapes.h"
#include "shuffle_mesh.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "temp_folder.h"
#include "test_files.h"

namespace slicereuse::plugin {
namespace {

using test::error_of;
using test::make_sphere;
using test::shuffle_mesh;

TEST(Filters, NamesAreUniqueAndEveryParameterIsDeclaredOnce) {
  std::set<int> ids;
  std::set<std::string> names, python_names;
  for (const FilterSpec& f : filter_specs()) {
    EXPECT_TRUE(ids.insert(int(f.id)).second) << f.name;
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_TRUE(python_names.insert(f.python_name).second) << f.python_name;
    EXPECT_TRUE(f.run) << f.name;
    EXPECT_EQ(find_filter_spec(int(f.id)), &f);
    std::set<std::string> params;
    for (const ParamSpec& p : f.params) EXPECT_TRUE(params.insert(p.name).second) << f.name << ": " << p.name;
  }
  EXPECT_EQ(filter_specs().size(), 16u);
  EXPECT_EQ(find_filter_spec(-1), nullptr);
}

// A name the spec does not declare (a typo in a script or a test), and one it declares that the
// values lack, are refused by every filter with the parameter's name, before anything is done.
TEST(Filters, AMistypedOrMissingParameterNameIsRefusedByEveryFilter) {
  for (const FilterSpec& f : filter_specs()) {
    FakeHost host;
    ParamValues typo = defaults(f);
    typo.numbers["layer_thicknes"] = 0.1;
    EXPECT_NE(error_of([&] { f.run(typo, host); }).find("there is no parameter 'layer_thicknes'"), std::string::npos)
        << f.name;
    for (const ParamSpec& p : f.params) {
      ParamValues missing = defaults(f);
      missing.numbers.erase(p.name);
      missing.texts.erase(p.name);
      EXPECT_EQ(error_of([&] { f.run(missing, host); }), "parameter '" + p.name + "' is missing") << f.name;
    }
    EXPECT_TRUE(host.lines.empty()) << f.name;
  }
}

TEST(Filters, ValuesOutOfRangeAreRefusedOnceWithTheirRange) {
  FakeHost host;
  host.meshes.push_back(make_sphere(1, 12, 16));
  const FilterSpec& slice = spec_named("slice_mesh_with_encoding");
  EXPECT_EQ(error_of([&] { slice.run(defaults(slice, {}, {{"layer_thickness", 0}}), host); }),
            "layer_thickness must be greater than 0 mm (got 0)");
  EXPECT_EQ(error_of([&] { slice.run(defaults(slice, {}, {{"z_start", HUGE_VAL}}), host); }),
            "z_start must be a finite number (got inf)");
  EXPECT_EQ(error_of([&] { slice.run(defaults(slice, {}, {{"file_format", 2}}), host); }),
            "file_format must be one of 0 (text), 1 (binary), got 2");
  EXPECT_EQ(error_of([&] { slice.run(defaults(slice, {}, {{"preview_layers", -1}}), host); }),
            "preview_layers must be at least 0 layers (got -1)");
  const FilterSpec& masks = spec_named("export_mask_images");
  EXPECT_EQ(error_of([&] { masks.run(defaults(masks, {{"output_path", "/tmp/x"}}, {{"width_px", 65536}}), host); }),
            "width_px must be between 1 and 65535 pixels (got 65536)");
  EXPECT_EQ(error_of([&] { masks.run(defaults(masks), host); }), "output_path is empty: choose a folder, or a print file (.sl1, .ctb, ...)");
  EXPECT_TRUE(host.lines.empty());
}

class FiltersThroughAFakeHost : public test::TempFolderTest {};

// A preset gives the display and exposure, and refuses custom values given with it; the offsets
// and anti-aliasing given apply to it; "custom" (the default) takes the values given. The log
// names the printer.
TEST_F(FiltersThroughAFakeHost, APrinterPresetSetsTheDisplayAndTheGivenOffsetsAndAntialiasingApply) {
  FakeHost host;
  host.meshes.push_back(make_sphere(1, 24, 32));
  const FilterSpec& job = spec_named("make_print_job");
  const ParamSpec& printer = *std::find_if(job.params.begin(), job.params.end(),
                                           [](const ParamSpec& p) { return p.name == "printer"; });
  const auto index_of = [&](const std::string& id) {
    return double(std::find(printer.enum_values.begin(), printer.enum_values.end(), id) - printer.enum_values.begin());
  };
  ASSERT_EQ(printer.enum_values.back(), "custom");
  EXPECT_EQ(printer.default_number, index_of("custom"));
  EXPECT_EQ(error_of([&] {
              job.run(defaults(job, {{"output_path", path("sl1s")}},
                               {{"printer", index_of("prusa_sl1s_speed")}, {"width_px", 7}, {"faded_layers", 3}}),
                      host);
            }),
            "printer prusa_sl1s_speed sets the display and exposure, but width_px, faded_layers were given too: "
            "choose printer custom to give them, or leave them at their defaults");
  EXPECT_FALSE(std::filesystem::exists(path("sl1s")));
  job.run(defaults(job, {{"output_path", path("sl1s")}},
                   {{"printer", index_of("prusa_sl1s_speed")}, {"offset_x_mm", 10}, {"antialiasing", 1}}),
          host);
  EXPECT_NE(host.lines.front().find("printer prusa_sl1s_speed: 2560x1620 display of 50 x 50 um pixels, portrait, "
                                    "mirror x, images 1620x2560, anti-aliased (gamma 1)"),
            std::string::npos)
      << host.lines.front();
  MaskImage image;
  {
    MaskStack stack(path("sl1s"));
    std::vector<uint8_t> bytes;
    stack.read(stack.layers() / 2, bytes);
    decode_mask_png(bytes.data(), bytes.size(), "middle layer", image);
  }
  ASSERT_EQ(image.width, 1620);
  ASSERT_EQ(image.height, 2560);
  // The sphere (radius 1 mm = 20 px) moved 10 mm = 200 px along +x: up from the centre row, as
  // portrait images have row 0 at the largest x; grey levels on its outline.
  size_t lo = image.height, hi = 0, grey = 0;
  for (int r = 0; r < image.height; ++r)
    for (int c = 0; c < image.width; ++c) {
      const uint8_t v = image.pixels[size_t(r) * size_t(image.width) + size_t(c)];
      if (v) lo = std::min(lo, size_t(r)), hi = std::max(hi, size_t(r));
      grey += v != 0 && v != 255;
    }
  EXPECT_NEAR(0.5 * double(lo + hi + 1), 1280 - 200, 1.0);
  EXPECT_GT(grey, 0u);

  host.lines.clear();
  job.run(defaults(job, {{"output_path", path("custom")}}, {{"width_px", 70}, {"height_px", 60}}), host);
  EXPECT_NE(host.lines.front().find("printer custom: 70x60 display of 75 x 75 um pixels, landscape, images 70x60, "
                                    "binary"),
            std::string::npos)
      << host.lines.front();
}

// The family's pipeline, every filter at its spec defaults but for the files: slice a sphere,
// transfer to a moved member, masks, a print job by reuse, compare (S = 1), cross-parameterize
// onto a renumbered copy, free the cached encoding. Each result holds exactly its figures.
TEST_F(FiltersThroughAFakeHost, EveryFilterRunsAndReturnsEveryFigureItLogs) {
  FakeHost host;
  host.meshes.push_back(make_sphere(1, 24, 32));
  Mesh moved = host.meshes[0];
  for (size_t i = 0; i < moved.V.size(); i += 3) moved.V[i] = 1.1 * moved.V[i] + 0.05 * moved.V[i + 2];
  host.meshes.push_back(moved);
  host.meshes.push_back(shuffle_mesh(host.meshes[0], 7).mesh);

  const Result slice = spec_named("slice_mesh_with_encoding")
                           .run(defaults(spec_named("slice_mesh_with_encoding"),
                                         {{"contour_file", path("s.ctr")}, {"encoding_file", path("s.srb")}},
                                         {{"preview_layers", 3}}),
                                host);
  SliceOptions options;
  options.thickness = 0.1;
  const Slices direct = slice_layers(host.meshes[0], options);
  EXPECT_EQ(keys_of(slice), (std::set<std::string>{"layers", "contours", "points", "open_contours", "duplicate_faces",
                                                   "zero_area_faces", "repeated_vertex_faces", "boundary_edges",
                                                   "non_manifold_edges", "z_start", "mesh_z_min", "mesh_z_max", "read_seconds",
                                                   "slicing_seconds", "seconds"}));
  EXPECT_EQ(count(slice, "layers"), int64_t(direct.layers()));
  EXPECT_EQ(count(slice, "points"), int64_t(direct.points()));
  EXPECT_EQ(count(slice, "open_contours"), 0);
  EXPECT_EQ(std::get<double>(slice.at("mesh_z_min")), -1);
  EXPECT_EQ(host.added_layers, std::vector<std::string>{"slice preview"});

  const FilterSpec& transfer_spec = spec_named("transfer_slicing_to_mesh");
  const Result transfer =
      transfer_spec.run(defaults(transfer_spec, {{"encoding_file", path("s.srb")}, {"contour_file", path("t.ctr")}},
                                 {{"target_mesh", 1}}),
                        host);
  EXPECT_EQ(keys_of(transfer), (std::set<std::string>{"points", "layers", "transferred_layers", "resliced_layers",
                                                      "through_map", "max_plane_deviation", "dropped_contours",
                                                      "unplaced_points", "transfer_seconds", "seconds"}));
  EXPECT_EQ(count(transfer, "transferred_layers"), int64_t(direct.layers()));
  EXPECT_EQ(count(transfer, "resliced_layers"), 0);
  EXPECT_EQ(count(transfer, "dropped_contours"), 0);
  EXPECT_EQ(count(transfer, "through_map"), 0);

  const std::set<std::string> display = {"ignored_open_contours", "outside_display", "part_min_x_mm", "part_max_x_mm",
                                         "part_min_y_mm", "part_max_y_mm"};
  const FilterSpec& masks_spec = spec_named("export_mask_images");
  const Result masks =
      masks_spec.run(defaults(masks_spec, {{"contour_file", path("t.ctr")}, {"output_path", path("t_masks")}}), host);
  std::set<std::string> masks_keys = display;
  masks_keys.insert({"layers", "seconds"});
  EXPECT_EQ(keys_of(masks), masks_keys);
  EXPECT_EQ(count(masks, "outside_display"), 0);
  EXPECT_NEAR(std::get<double>(masks.at("part_max_x_mm")), 1.1 + 0.05 * 0.5, 0.06);

  const FilterSpec& job_spec = spec_named("make_print_job");
  host.current = 1;
  const ParamValues job_values =
      defaults(job_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("job.sl1")}});
  const Result job = job_spec.run(job_values, host);
  std::set<std::string> job_keys = display;
  job_keys.insert({"layers", "points", "transferred_layers", "resliced_layers", "encoding_cached", "layer_ranges",
                   "reused", "direct_reason", "output_path", "support_points", "kept", "moved", "added", "dropped",
                   "read_seconds", "slicing_seconds", "support_seconds", "masks_seconds", "seconds", "islands",
                   "overhangs", "resin_traps", "suction_cups", "touching_bounds", "trapped_mm3", "label_height_mm",
                   "cavity_mm3", "drain_holes"});
  EXPECT_EQ(keys_of(job), job_keys);
  EXPECT_EQ(std::get<double>(job.at("label_height_mm")), -1);  // no labels
  // A sphere on the plate: every layer rests on the one below, nothing holds air.
  for (const char* none : {"islands", "resin_traps", "suction_cups", "touching_bounds"}) EXPECT_EQ(count(job, none), 0);
  for (const char* none : {"support_points", "kept", "moved", "added", "dropped"}) EXPECT_EQ(count(job, none), 0);
  EXPECT_EQ(count(job, "transferred_layers"), int64_t(direct.layers()));
  EXPECT_EQ(count(job, "reused"), 1);
  EXPECT_EQ(std::get<std::string>(job.at("direct_reason")), "");
  EXPECT_EQ(std::get<std::string>(job.at("output_path")), path("job.sl1"));
  EXPECT_EQ(count(job_spec.run(job_values, host), "encoding_cached"), 1);

  const FilterSpec& compare_spec = spec_named("compare_mask_stacks");
  const Result compare = compare_spec.run(
      defaults(compare_spec, {{"stack_a", path("t_masks")}, {"stack_b", path("job.sl1")}, {"report_file", path("c.csv")}}),
      host);
  EXPECT_EQ(keys_of(compare),
            (std::set<std::string>{"layers", "min_similarity", "worst_layer", "differing_pixels", "max_grey_difference",
                                   "max_grey_difference_layer", "over_one_level_pixels", "over_one_level_share",
                                   "over_one_level_layer", "seconds"}));
  EXPECT_EQ(std::get<double>(compare.at("min_similarity")), 1.0);
  EXPECT_EQ(count(compare, "differing_pixels"), 0);
  EXPECT_EQ(count(compare, "max_grey_difference"), 0);
  EXPECT_EQ(count(compare, "over_one_level_pixels"), 0);
  EXPECT_EQ(std::get<double>(compare.at("over_one_level_share")), 0.0);
  EXPECT_EQ(count(compare, "layers"), int64_t(direct.layers()));

  const FilterSpec& crossparam_spec = spec_named("cross_parameterize_meshes");
  const Result crossparam = crossparam_spec.run(
      defaults(crossparam_spec, {{"map_file", path("m.srb")}}, {{"source_mesh", 0}, {"target_mesh", 2}}), host);
  EXPECT_EQ(keys_of(crossparam),
            (std::set<std::string>{"patches", "genus", "flipped_triangles", "max_height_error", "rms_height_error",
                                   "area_distortion", "angle_distortion", "map_seconds", "seconds"}));
  EXPECT_EQ(count(crossparam, "flipped_triangles"), 0);
  EXPECT_EQ(host.colors.at(0).size(), 4 * host.meshes[0].V.size() / 3);
  EXPECT_EQ(host.colors.at(2).size(), 4 * host.meshes[2].V.size() / 3);

  // What the cache holds is the encoding file's arrays and their edge ends.
  const Slices encoding = read_encoding_file(path("s.srb"));
  const size_t expected = encoding.layer_z.size() * 8 + (encoding.layer_begin.size() + encoding.contour_begin.size()) * 8 +
                          encoding.contour_open.size() + encoding.face.size() * 4 + encoding.edge.size() +
                          encoding.t.size() * 8 + encoded_edge_ends(encoding, host.meshes[1]).size() * 4;
  const FilterSpec& free_spec = spec_named("free_cached_memory");
  const Result freed = free_spec.run(defaults(free_spec), host);
  EXPECT_EQ(keys_of(freed), (std::set<std::string>{"freed_bytes", "encoding_bytes"}));
  EXPECT_EQ(count(freed, "encoding_bytes"), int64_t(expected));
  EXPECT_GE(count(freed, "freed_bytes"), count(freed, "encoding_bytes"));
  EXPECT_EQ(count(free_spec.run(defaults(free_spec), host), "encoding_bytes"), 0);
  EXPECT_EQ(count(job_spec.run(job_values, host), "encoding_cached"), 0);
}

// Make Plate Job through the fake host: the shown meshes (the hidden renumbered copy, whose faces
// differ, is left out) on one plate by reuse, its layout picture and placements file; then the
// same plate from that placements file by direct slicing gives the same masks.
// Labels from the members' names or a labels file, each member's height in the result; a labels
// file without a member's row fails the job before any plate is written.
TEST_F(FiltersThroughAFakeHost, MakePlateJobCutsLabelsFromNamesOrALabelsFile) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 30, 15, 5, 4));
  host.meshes.push_back(test::make_box(0, 0, 0, 30, 15, 5, 4));
  const FilterSpec& spec = spec_named("make_plate_job");
  const std::map<std::string, double> numbers{{"layer_thickness", 0.1}, {"labels", 1}};
  const Result named = spec.run(defaults(spec, {{"output_path", path("named.sl1")}}, numbers), host);
  // "MESH0" and "MESH1" are 5 letters, as "CASE1": 6.075 mm high on the 30 mm base.
  EXPECT_DOUBLE_EQ(std::get<double>(named.at("label_height_mm_mesh0")), 7.5 * 0.9 * 0.9);
  EXPECT_DOUBLE_EQ(std::get<double>(named.at("label_height_mm_mesh1")), 7.5 * 0.9 * 0.9);
  {
    std::ofstream csv(path("one.csv"));
    csv << "member,label\nmesh0,CASE-1\n";
  }
  const std::string message = error_of([&] {
    spec.run(defaults(spec, {{"output_path", path("file.sl1")}, {"labels_file", path("one.csv")}}, numbers), host);
  });
  EXPECT_NE(message.find("has no label for member 'mesh1'"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(path("file_1.sl1")));
  {
    std::ofstream csv(path("two.csv"));
    csv << "mesh1.stl, A1\nmesh0.stl ,CASE-1\n";
  }
  const Result filed =
      spec.run(defaults(spec, {{"output_path", path("file.sl1")}, {"labels_file", path("two.csv")}}, numbers), host);
  EXPECT_DOUBLE_EQ(std::get<double>(filed.at("label_height_mm_mesh1")), 7.5);  // "A1" fits whole
  EXPECT_GT(std::get<double>(filed.at("label_height_mm_mesh0")), 0);
  EXPECT_TRUE(std::filesystem::exists(path("file_1.sl1")));
}

// Add Labels places the label as the jobs do (the same height and place as a print job's) and
// shows its outline on the base; a mesh too thin for the depth is refused in words.
TEST_F(FiltersThroughAFakeHost, AddLabelsShowsWhereAPrintJobCutsTheLabel) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 30, 15, 5, 4));
  const FilterSpec& spec = spec_named("add_labels");
  const Result shown = spec.run(defaults(spec, {}, {{"layer_thickness", 0.1}}), host);
  // "mesh0" is 5 letters, as "CASE1": 6.075 mm high on the 30 mm base, in its middle.
  EXPECT_DOUBLE_EQ(std::get<double>(shown.at("label_height_mm")), 7.5 * 0.9 * 0.9);
  EXPECT_NEAR(std::get<double>(shown.at("x_mm")), 15, 0.2);
  EXPECT_NEAR(std::get<double>(shown.at("y_mm")), 7.5, 0.2);
  EXPECT_EQ(std::get<double>(shown.at("angle_deg")), 0);
  ASSERT_EQ(host.polyline_layers.count("label mesh0"), 1u);
  const std::vector<double>& xyz = host.polyline_layers.at("label mesh0");
  ASSERT_FALSE(xyz.empty());
  for (size_t i = 2; i < xyz.size(); i += 3) EXPECT_EQ(xyz[i], 0);  // on the base
  const FilterSpec& job = spec_named("make_print_job");
  const Result printed = job.run(defaults(job, {{"output_path", path("job.sl1")}},
                                          {{"layer_thickness", 0.1}, {"labels", 1}}),
                                 host);
  EXPECT_EQ(std::get<double>(printed.at("label_height_mm")), std::get<double>(shown.at("label_height_mm")));
  host.meshes[0] = test::make_box(0, 0, 0, 30, 15, 2, 4);
  EXPECT_NE(error_of([&] { spec.run(defaults(spec, {{"label", "C-1"}}, {{"layer_thickness", 0.1}}), host); })
                .find("the label 'C-1' does not fit mesh0: mesh0 is 2 mm tall, and a label 3 mm deep needs 4 mm"),
            std::string::npos);
}

// label_side: Add Labels shows the label upright on the chosen side, its outline in that side's
// plane within its box's heights, where Make Print Job and Make Plate Job cut it; a label that
// fits on no side is refused in words.
TEST_F(FiltersThroughAFakeHost, AddLabelsShowsALabelOnASideWhereTheJobsCutIt) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 30, 15, 12, 4));
  const FilterSpec& spec = spec_named("add_labels");
  const std::map<std::string, double> back{{"layer_thickness", 0.1}, {"label_side", 2}};
  const Result shown = spec.run(defaults(spec, {}, back), host);
  // "mesh0" is 5 letters, as "CASE1": 6.075 mm high (25.7 mm long, 27.7 with its margins) on the
  // 30 mm back; its box from 3 mm up, the bottom nearest the middle of the 12 mm side.
  EXPECT_DOUBLE_EQ(std::get<double>(shown.at("label_height_mm")), 7.5 * 0.9 * 0.9);
  EXPECT_NEAR(std::get<double>(shown.at("x_mm")), 15, 1e-6);
  EXPECT_NEAR(std::get<double>(shown.at("y_mm")), 15, 1e-6);
  EXPECT_NEAR(std::get<double>(shown.at("z_mm")), 3 + 0.5 * 6.075, 1e-9);
  EXPECT_EQ(std::get<double>(shown.at("angle_deg")), 0);
  const std::vector<double>& xyz = host.polyline_layers.at("label mesh0");
  ASSERT_FALSE(xyz.empty());
  for (size_t i = 0; i < xyz.size(); i += 3) {
    EXPECT_NEAR(xyz[i + 1], 15, 1e-6);  // on the back's plane
    EXPECT_GE(xyz[i + 2], 3 - 1e-6);
    EXPECT_LE(xyz[i + 2], 3 + 6.075 + 1e-6);
  }
  const FilterSpec& job = spec_named("make_print_job");
  std::map<std::string, double> labelled = back;
  labelled["labels"] = 1;
  const Result printed = job.run(defaults(job, {{"output_path", path("job.sl1")}}, labelled), host);
  EXPECT_EQ(std::get<double>(printed.at("label_height_mm")), std::get<double>(shown.at("label_height_mm")));
  const FilterSpec& plate = spec_named("make_plate_job");
  const Result plated = plate.run(defaults(plate, {{"output_path", path("plate.sl1")}}, labelled), host);
  EXPECT_EQ(std::get<double>(plated.at("label_height_mm_mesh0")), std::get<double>(shown.at("label_height_mm")));
  host.meshes[0] = test::make_box(0, 0, 0, 6, 15, 12, 4);
  EXPECT_NE(error_of([&] { spec.run(defaults(spec, {}, back), host); })
                .find("the label 'mesh0' fits nowhere on the back side of mesh0: even 2.5 mm high"),
            std::string::npos);
}

TEST_F(FiltersThroughAFakeHost, MakePlateJobPutsTheShownMeshesOnPlatesAndReadsItsPlacementsBack) {
  FakeHost host;
  host.meshes.push_back(make_sphere(1, 24, 32));
  Mesh moved = host.meshes[0];
  for (size_t i = 0; i < moved.V.size(); i += 3) moved.V[i] = 1.1 * moved.V[i] + 0.05 * moved.V[i + 2];
  host.meshes.push_back(moved);
  host.meshes.push_back(shuffle_mesh(host.meshes[0], 7).mesh);
  host.hidden = {2};
  const FilterSpec& slice_spec = spec_named("slice_mesh_with_encoding");
  slice_spec.run(defaults(slice_spec, {{"encoding_file", path("s.srb")}}), host);

  const FilterSpec& plate_spec = spec_named("make_plate_job");
  const Result plate = plate_spec.run(
      defaults(plate_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("plate.sl1")},
                            {"placements_output", path("plates.json")}}),
      host);
  EXPECT_EQ(keys_of(plate), (std::set<std::string>{"plates", "members", "layers", "points", "transferred_layers",
                                                   "resliced_layers", "direct_members", "encoding_cached",
                                                   "arrange_seconds", "read_seconds", "slicing_seconds",
                                                   "support_seconds", "seconds", "area_used_1", "output_1",
                                                   "layout_1", "cavity_mm3", "drain_holes", "islands", "overhangs", "resin_traps", "suction_cups",
                                                   "touching_bounds", "trapped_mm3", "islands_mesh0", "overhangs_mesh0",
                                                   "resin_traps_mesh0", "suction_cups_mesh0", "touching_bounds_mesh0",
                                                   "islands_mesh1", "overhangs_mesh1", "resin_traps_mesh1",
                                                   "suction_cups_mesh1", "touching_bounds_mesh1"}));
  EXPECT_EQ(std::get<std::string>(plate.at("output_1")), path("plate_1.sl1"));
  EXPECT_EQ(std::get<std::string>(plate.at("layout_1")), path("plate_1_layout.png"));
  EXPECT_EQ(count(plate, "direct_members"), 0);
  EXPECT_EQ(count(plate, "plates"), 1);
  EXPECT_EQ(count(plate, "members"), 2);
  SliceOptions options;
  options.thickness = 0.1;
  const size_t layers = slice_layers(host.meshes[0], options).layers();
  EXPECT_EQ(count(plate, "layers"), int64_t(layers));
  EXPECT_EQ(count(plate, "transferred_layers"), int64_t(2 * layers));
  EXPECT_EQ(count(plate, "resliced_layers"), 0);
  EXPECT_TRUE(std::filesystem::is_regular_file(path("plate_1.sl1")));
  std::ifstream layout(path("plate_1_layout.png"), std::ios::binary);
  std::vector<uint8_t> png((std::istreambuf_iterator<char>(layout)), std::istreambuf_iterator<char>());
  MaskImage picture;
  decode_mask_png(png.data(), png.size(), "layout", picture);
  EXPECT_EQ(picture.width, 768);  // the method's 76.8 x 57.6 mm display at 0.1 mm
  EXPECT_EQ(picture.height, 576);

  // The placements written, used instead of arranging, with direct slicing: the same masks.
  const Result again = plate_spec.run(
      defaults(plate_spec, {{"placements_file", path("plates.json")}, {"output_path", path("direct.sl1")}}), host);
  EXPECT_EQ(count(again, "transferred_layers"), 0);
  const FilterSpec& compare_spec = spec_named("compare_mask_stacks");
  const Result compare = compare_spec.run(
      defaults(compare_spec, {{"stack_a", path("plate_1.sl1")}, {"stack_b", path("direct_1.sl1")}}), host);
  EXPECT_EQ(std::get<double>(compare.at("min_similarity")), 1.0);
  EXPECT_EQ(count(compare, "max_grey_difference"), 0);

  // Arrange on Plates writes the same placements and layout without slicing; Make Plate Job's
  // plate 1 of them, with only that plate's members loaded, is the same print file.
  const FilterSpec& arrange_spec = spec_named("arrange_on_plates");
  const Result arranged = arrange_spec.run(
      defaults(arrange_spec, {{"placements_output", path("arranged.json")}, {"output_path", path("arranged.sl1")}}),
      host);
  EXPECT_EQ(keys_of(arranged), (std::set<std::string>{"plates", "members", "z_min", "arrange_seconds", "read_seconds",
                                                      "seconds", "area_used_1"}));
  EXPECT_EQ(count(arranged, "members"), 2);
  EXPECT_EQ(std::get<double>(arranged.at("area_used_1")), std::get<double>(plate.at("area_used_1")));
  EXPECT_EQ(test::slurp(path("arranged_1_layout.png")), test::slurp(path("plate_1_layout.png")));
  EXPECT_FALSE(std::filesystem::exists(path("arranged_1.sl1")));
  const Result one = plate_spec.run(defaults(plate_spec,
                                             {{"encoding_file", path("s.srb")},
                                              {"placements_file", path("arranged.json")},
                                              {"output_path", path("one.sl1")}},
                                             {{"plate", 1}}),
                                    host);
  EXPECT_EQ(count(one, "plates"), 1);
  const Result same = compare_spec.run(
      defaults(compare_spec, {{"stack_a", path("plate_1.sl1")}, {"stack_b", path("one_1.sl1")}}), host);
  EXPECT_EQ(std::get<double>(same.at("min_similarity")), 1.0);
  EXPECT_EQ(count(same, "max_grey_difference"), 0);
  EXPECT_EQ(test::error_of([&] {
              plate_spec.run(defaults(plate_spec, {{"placements_file", path("arranged.json")},
                                                   {"output_path", path("two.sl1")}}, {{"plate", 2}}),
                             host);
            }),
            "the placements have 1 plate: there is no plate 2");
  EXPECT_NE(test::error_of([&] {
              plate_spec.run(defaults(plate_spec, {{"output_path", path("lone.sl1")}}, {{"plate", 1}}), host);
            }).find("give placements_file"),
            std::string::npos);

  // Every mesh, the renumbered copy included: it is no member of the encoding's family, so it is
  // sliced directly and the result says why; strict, the plate is refused naming it.
  const Result all = plate_spec.run(
      defaults(plate_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("all.sl1")}}, {{"visible_only", 0}}),
      host);
  EXPECT_EQ(count(all, "members"), 3);
  EXPECT_EQ(count(all, "direct_members"), 1);
  const std::string name = "mesh2";  // FakeHost's name of mesh 2
  ASSERT_TRUE(all.count("direct_reason_" + name)) << name;
  EXPECT_EQ(count(all, "sliced_directly_" + name), 1);
  EXPECT_EQ(std::get<std::string>(all.at("direct_reason_" + name))
                .rfind("its faces differ from those of the mesh the encoding was made from", 0),
            0u);
  EXPECT_EQ(count(all, "transferred_layers"), int64_t(2 * layers));
  EXPECT_EQ(count(all, "resliced_layers"), int64_t(layers));
  EXPECT_EQ(test::error_of([&] {
              plate_spec.run(defaults(plate_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("strict.sl1")}},
                                      {{"visible_only", 0}, {"strict", 1}}),
                             host);
            }).rfind(name + " cannot be made by reuse: its faces differ", 0),
            0u);
  EXPECT_FALSE(std::filesystem::exists(path("strict_1.sl1")));
  host.hidden = {0, 1, 2};
  EXPECT_NE(test::error_of([&] { plate_spec.run(defaults(plate_spec, {{"output_path", path("none.sl1")}}), host); })
                .find("no shown mesh with faces"),
            std::string::npos);
}

// The jobs' member files (a batch's way): the source sliced from its file with no mesh loaded at
// all, then a member's plate and print job read from its file give the masks the same member
// gives loaded as a layer, named by its file name; a missing file is refused naming it.
TEST_F(FiltersThroughAFakeHost, JobsReadMemberFilesAsTheLoadedMeshes) {
  FakeHost host;
  const Mesh source = make_sphere(1, 24, 32);
  Mesh member = source;
  for (size_t i = 0; i < member.V.size(); i += 3) member.V[i] = 1.1 * member.V[i] + 0.05 * member.V[i + 2];
  // OBJ holds every double exactly (the shortest text), so the files are the meshes bit for bit.
  test::write_mesh_file(path("source.obj"), source, test::MeshFileKind::Obj);
  test::write_mesh_file(path("member.obj"), member, test::MeshFileKind::Obj);
  const FilterSpec& slice_spec = spec_named("slice_mesh_with_encoding");
  const Result sliced = slice_spec.run(
      defaults(slice_spec, {{"mesh_file", path("source.obj")}, {"encoding_file", path("s.srb")}}), host);
  EXPECT_GT(std::get<double>(sliced.at("read_seconds")), 0);

  host.meshes = {member};
  const FilterSpec& plate_spec = spec_named("make_plate_job");
  const FilterSpec& compare_spec = spec_named("compare_mask_stacks");
  const auto same_masks = [&](const std::string& a, const std::string& b) {
    const Result c = compare_spec.run(defaults(compare_spec, {{"stack_a", a}, {"stack_b", b}}), host);
    EXPECT_EQ(std::get<double>(c.at("min_similarity")), 1.0) << a;
    EXPECT_EQ(count(c, "max_grey_difference"), 0) << a;
  };
  const Result layers = plate_spec.run(
      defaults(plate_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("layers.sl1")}}), host);
  const Result read = plate_spec.run(defaults(plate_spec, {{"encoding_file", path("s.srb")},
                                                           {"member_files", " ; " + path("member.obj") + " ;"},
                                                           {"output_path", path("read.sl1")},
                                                           {"placements_output", path("read.json")}}),
                                     host);
  EXPECT_EQ(std::get<double>(layers.at("read_seconds")), 0);
  EXPECT_GT(std::get<double>(read.at("read_seconds")), 0);
  EXPECT_EQ(count(read, "members"), 1);
  EXPECT_EQ(count(read, "transferred_layers"), count(layers, "transferred_layers"));
  EXPECT_EQ(count(read, "resliced_layers"), 0);
  same_masks(path("layers_1.sl1"), path("read_1.sl1"));
  EXPECT_NE(test::slurp(path("read.json")).find("\"name\": \"member.obj\""), std::string::npos);

  const FilterSpec& job_spec = spec_named("make_print_job");
  const Result current =
      job_spec.run(defaults(job_spec, {{"encoding_file", path("s.srb")}, {"output_path", path("current.sl1")}}), host);
  host.meshes.clear();
  const Result file = job_spec.run(defaults(job_spec, {{"mesh_file", path("member.obj")},
                                                       {"encoding_file", path("s.srb")},
                                                       {"output_path", path("file.sl1")}}),
                                   host);
  EXPECT_EQ(count(current, "reused"), 1);
  EXPECT_EQ(count(file, "reused"), 1);
  same_masks(path("current.sl1"), path("file.sl1"));

  EXPECT_EQ(test::error_of([&] { job_spec.run(defaults(job_spec, {{"output_path", path("none.sl1")}}), host); }),
            "there is no current mesh: open a mesh first");
  const std::string missing = test::error_of([&] {
    plate_spec.run(defaults(plate_spec, {{"member_files", path("member.obj") + ";" + path("gone.stl")},
                                         {"output_path", path("gone.sl1")}}),
                   host);
  });
  EXPECT_NE(missing.find(path("gone.stl")), std::string::npos) << missing;
  EXPECT_FALSE(std::filesystem::exists(path("gone_1.sl1")));
}

// A custom printer chooses the print file's version (file_version): .ctb 3 or 4; Chitu's
// encrypted version 5 is refused in words, with nothing written.
// The jobs check their masks: a cup open at the top is a suction cup of its member, counted;
// required printable, the job fails naming it and writes nothing; unchecked, the counts are -1.
TEST_F(FiltersThroughAFakeHost, JobsCountFindingsPerMemberAndRefuseThemWhenRequired) {
  FakeHost host;
  host.meshes = {test::make_cup(-5, -5, 0, 5, 5, 6, 2), test::make_box(-5, -5, 0, 5, 5, 3)};
  const FilterSpec& plate_spec = spec_named("make_plate_job");
  const Result plate = plate_spec.run(defaults(plate_spec, {{"output_path", path("plate.goo")}}), host);
  EXPECT_EQ(count(plate, "suction_cups"), 1);
  EXPECT_EQ(count(plate, "suction_cups_mesh0"), 1);
  EXPECT_EQ(count(plate, "suction_cups_mesh1"), 0);
  EXPECT_EQ(count(plate, "islands"), 0);
  EXPECT_EQ(count(plate, "resin_traps"), 0);

  const std::string refused = test::error_of([&] {
    plate_spec.run(defaults(plate_spec, {{"output_path", path("refused.goo")}}, {{"require_printable", 1}}), host);
  });
  EXPECT_NE(refused.find("not printable, so not written: suction cup in mesh0, layers"), std::string::npos) << refused;
  EXPECT_FALSE(std::filesystem::exists(path("refused_1.goo")));

  const FilterSpec& job_spec = spec_named("make_print_job");
  host.current = 1;
  const Result solid = job_spec.run(defaults(job_spec, {{"output_path", path("solid.goo")}}, {{"require_printable", 1}}), host);
  EXPECT_EQ(count(solid, "suction_cups"), 0);
  EXPECT_TRUE(std::filesystem::exists(path("solid.goo")));
  const Result unchecked =
      job_spec.run(defaults(job_spec, {{"output_path", path("u.goo")}}, {{"check_printability", 0}}), host);
  EXPECT_EQ(count(unchecked, "islands"), -1);
  EXPECT_EQ(std::get<double>(unchecked.at("trapped_mm3")), -1.0);
}

// hollow_wall_mm hollows each member of a plate or print job: a solid box 10 x 10 x 6 mm with
// walls of 1 mm (no closing) holds a cavity of 8 x 8 x 4 mm, sealed, so one resin trap of its
// volume; walls thicker than the part leave it solid, and the log says so.
TEST_F(FiltersThroughAFakeHost, JobsHollowTheirMembers) {
  FakeHost host;
  host.meshes = {test::make_box(-5, -5, 0, 5, 5, 6), test::make_box(8, -5, 0, 18, 5, 2)};
  const FilterSpec& plate_spec = spec_named("make_plate_job");
  const Result plate = plate_spec.run(defaults(plate_spec, {{"output_path", path("plate.goo")}},
                                              {{"hollow_wall_mm", 1}, {"hollow_closing_mm", 0}, {"drain_hole_mm", 0}}),
                                     host);
  EXPECT_NEAR(std::get<double>(plate.at("cavity_mm3_mesh0")), 8 * 8 * 4, 1e-6);
  EXPECT_EQ(std::get<double>(plate.at("cavity_mm3_mesh1")), 0);
  EXPECT_NEAR(std::get<double>(plate.at("cavity_mm3")), 8 * 8 * 4, 1e-6);
  EXPECT_EQ(count(plate, "resin_traps"), 1);
  EXPECT_EQ(count(plate, "resin_traps_mesh0"), 1);
  EXPECT_NE(std::find(host.lines.begin(), host.lines.end(),
                      "Make Plate Job: plate 1: mesh1 stays solid: no cavity with walls of 1 mm, since no ball of 1 mm "
                      "radius fits inside it"),
            host.lines.end());

  const FilterSpec& job_spec = spec_named("make_print_job");
  const Result hollow = job_spec.run(defaults(job_spec, {{"output_path", path("job.goo")}},
                                              {{"hollow_wall_mm", 1}, {"hollow_closing_mm", 0}, {"drain_hole_mm", 0}}),
                                     host);
  EXPECT_NEAR(std::get<double>(hollow.at("cavity_mm3")), 8 * 8 * 4, 1e-6);
  EXPECT_EQ(count(hollow, "resin_traps"), 1);
  // With the default drain hole (4 mm) under the cavity, nothing is sealed.
  const Result drained =
      job_spec.run(defaults(job_spec, {{"output_path", path("drained.goo")}}, {{"hollow_wall_mm", 1}, {"hollow_closing_mm", 0}}),
                   host);
  EXPECT_EQ(count(drained, "drain_holes"), 1);
  EXPECT_EQ(count(drained, "resin_traps"), 0);
  EXPECT_NEAR(std::get<double>(drained.at("cavity_mm3")), 8 * 8 * 4, 1e-6);
  const Result solid = job_spec.run(defaults(job_spec, {{"output_path", path("solid.goo")}}), host);
  EXPECT_EQ(std::get<double>(solid.at("cavity_mm3")), 0);
  EXPECT_EQ(count(solid, "resin_traps"), 0);
}

TEST_F(FiltersThroughAFakeHost, ACustomPrinterChoosesTheCtbVersionAndTheEncryptedOneIsRefused) {
  FakeHost host;
  host.meshes.push_back(make_sphere(3, 48, 64));
  const FilterSpec& job = spec_named("make_print_job");
  const auto version = [&](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    uint8_t b[8] = {};
    in.read(reinterpret_cast<char*>(b), 8);
    return uint32_t(b[4]) | uint32_t(b[5]) << 8 | uint32_t(b[6]) << 16 | uint32_t(b[7]) << 24;
  };
  for (const int v : {0, 3, 4}) {
    const std::string file = path("v" + std::to_string(v) + ".ctb");
    job.run(defaults(job, {{"output_path", file}}, {{"layer_thickness", 0.5}, {"file_version", v}}), host);
    EXPECT_EQ(version(file), v == 0 ? 4u : uint32_t(v));
  }
  EXPECT_EQ(error_of([&] {
              job.run(defaults(job, {{"output_path", path("v5.ctb")}}, {{"layer_thickness", 0.5}, {"file_version", 5}}),
                      host);
            }),
            "cannot write '" + path("v5.ctb") +
                "': .ctb version 5 is the encrypted CTB of newer Chitu boards, whose closed scheme is not written: "
                "choose file version 3 or 4");
  EXPECT_FALSE(std::filesystem::exists(path("v5.ctb")));
}

// Elephant-foot compensation (elephant_foot, -1: the printer's own) shrinks the faded layers'
// masks (the custom printer's 10: layers 0 to 8, faded_layers.h), each by less than the one
// below, the same in Make Print Job and in Export Mask Images of the same layers.
TEST_F(FiltersThroughAFakeHost, ElephantFootShrinksTheFadedMasksInEveryPrintFile) {
  FakeHost host;
  host.meshes.push_back(make_sphere(3, 48, 64));
  const FilterSpec& slice = spec_named("slice_mesh_with_encoding");
  slice.run(defaults(slice, {{"contour_file", path("s.ctr")}, {"encoding_file", ""}}, {{"layer_thickness", 0.5}}),
            host);
  const FilterSpec& job = spec_named("make_print_job");
  const FilterSpec& masks = spec_named("export_mask_images");
  auto lit = [&](const std::string& folder) {
    std::vector<size_t> counts;
    MaskStack stack(folder);
    std::vector<uint8_t> bytes;
    MaskImage image;
    for (size_t k = 0; k < stack.layers(); ++k) {
      stack.read(k, bytes);
      decode_mask_png(bytes.data(), bytes.size(), "layer", image);
      counts.push_back(size_t(std::count(image.pixels.begin(), image.pixels.end(), 255)));
    }
    return counts;
  };
  for (const double foot : {0.0, 0.3}) {
    const std::string tag = foot > 0 ? "foot" : "none";
    job.run(defaults(job, {{"output_path", path("job_" + tag)}}, {{"layer_thickness", 0.5}, {"elephant_foot", foot}}),
            host);
    masks.run(defaults(masks, {{"contour_file", path("s.ctr")}, {"output_path", path("masks_" + tag)}},
                       {{"elephant_foot", foot}}),
              host);
  }
  const std::vector<size_t> none = lit(path("job_none")), foot = lit(path("job_foot"));
  ASSERT_EQ(none.size(), 12u);
  EXPECT_EQ(lit(path("masks_none")), none);
  EXPECT_EQ(lit(path("masks_foot")), foot);
  ASSERT_EQ(PrinterProfile().faded_layers, 10);
  for (size_t k = 0; k < 9; ++k) EXPECT_LT(foot[k], none[k]) << k;
  for (size_t k = 9; k < none.size(); ++k) EXPECT_EQ(foot[k], none[k]) << k;
}

// docs/formats.md's "Filter result line" table names every key each filter's spec declares (a
// per-plate or per-member key by its prefix, e.g. `area_used_1` for "area_used_*").
TEST(Filters, TheFormatsDocumentNamesEveryResultKey) {
  std::ifstream in(std::string(SLICEREUSE_EXAMPLES_DIR) + "/../docs/formats.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  for (const FilterSpec& f : filter_specs()) {
    const size_t row = doc.find("| `" + f.python_name + "` |");
    ASSERT_NE(row, std::string::npos) << f.python_name << " has no row";
    const std::string line = doc.substr(row, doc.find('\n', row) - row);
    ASSERT_FALSE(f.results.empty()) << f.python_name;
    for (const std::string& key : f.results) {
      const bool pattern = key.size() > 2 && key.compare(key.size() - 2, 2, "_*") == 0;
      const std::string named = "`" + (pattern ? key.substr(0, key.size() - 1) : key + "`");
      EXPECT_NE(line.find(named), std::string::npos) << f.python_name << " result " << key;
    }
  }
}

// examples/*.mlx: every filter is in one, and wherever a script names a filter it lists every
// parameter of the spec, in order, with its type (meshlabserver 2020.09 aborts on a missing one).
TEST(Filters, EveryFilterHasAnExampleListingEveryParameterInOrder) {
  const std::map<ParamType, std::string> rich = {
      {ParamType::Float, "RichFloat"},       {ParamType::Int, "RichInt"},          {ParamType::Bool, "RichBool"},
      {ParamType::Enum, "RichEnum"},         {ParamType::String, "RichString"},    {ParamType::FileOpen, "RichOpenFile"},
      {ParamType::FileSave, "RichSaveFile"}, {ParamType::Mesh, "RichMesh"}};
  // filter name -> for each use, "type name" per Param
  std::map<std::string, std::vector<std::vector<std::string>>> listed;
  for (const auto& entry : std::filesystem::directory_iterator(SLICEREUSE_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".mlx") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    static const std::regex filter(R"re(<filter name="([^"]+)">([\s\S]*?)</filter>)re");
    static const std::regex param(R"re(<Param type="(\w+)" name="(\w+)")re");
    for (std::sregex_iterator f(s.begin(), s.end(), filter), end; f != end; ++f) {
      std::vector<std::string>& params = listed[(*f)[1]].emplace_back();
      const std::string body = (*f)[2];
      for (std::sregex_iterator p(body.begin(), body.end(), param); p != end; ++p)
        params.push_back((*p)[1].str() + " " + (*p)[2].str());
    }
  }
  for (const FilterSpec& f : filter_specs()) {
    std::vector<std::string> expected;
    for (const ParamSpec& p : f.params) expected.push_back(rich.at(p.type) + " " + p.name);
    ASSERT_TRUE(listed.count(f.name)) << "no example .mlx for " << f.name;
    for (const std::vector<std::string>& use : listed[f.name]) EXPECT_EQ(use, expected) << f.name;
  }
}

}  // namespace
}  // namespace slicereuse::plugin
