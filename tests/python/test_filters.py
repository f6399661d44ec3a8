"""The four filters through pymeshlab: parameters, result dicts, the preview layer, and bad
input raising PyMeshLabException with a message that names the problem (never a crash)."""
import struct
import zipfile

import pytest

from conftest import THICKNESS, raises_filter_error as _raises, read_text_contours
from test_plates import png_pixels


@pytest.fixture
def sliced(pymeshlab, make_family, tmp_path):
    """A MeshSet with members 0 and 1 of an arch family; member 0 sliced to text files."""
    members = make_family("arch", 3)
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(members[0]))
    source_id = ms.current_mesh_id()
    r = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS,
                        contour_file=str(tmp_path / "s.ctr"), encoding_file=str(tmp_path / "s.enc"))
    ms.load_new_mesh(str(members[1]))
    return ms, source_id, ms.current_mesh_id(), r, tmp_path, members


def test_slice_result(sliced):
    ms, _, _, r, tmp, _ = sliced
    assert set(r) == {"layers", "contours", "points", "open_contours", "z_start", "mesh_z_min",
                      "mesh_z_max", "read_seconds", "slicing_seconds", "seconds", "duplicate_faces", "zero_area_faces",
                      "repeated_vertex_faces", "boundary_edges", "non_manifold_edges"}
    assert [r[k] for k in ("duplicate_faces", "zero_area_faces", "repeated_vertex_faces",
                           "boundary_edges", "non_manifold_edges")] == [0, 0, 0, 0, 0]
    assert r["z_start"] == r["mesh_z_min"] == 0.0 and r["mesh_z_max"] > 7.9
    assert 0 <= r["slicing_seconds"] <= r["seconds"]
    assert all(isinstance(r[k], int) for k in ("layers", "contours", "points", "open_contours"))
    assert isinstance(r["seconds"], float)
    header, layers = read_text_contours(tmp / "s.ctr")
    # The float parameter 0.1 reaches the core as the double 0.1, not 0.100000001490116.
    assert header["thickness"] == ["0.1"]
    assert r["layers"] == len(layers) == 80
    assert r["contours"] == sum(len(cs) for _, cs in layers)
    assert r["points"] == sum(len(pts) for _, cs in layers for _, pts in cs)
    assert r["open_contours"] == 0
    for k, (z, contours) in enumerate(layers):
        assert z == pytest.approx((k + 0.5) * THICKNESS, abs=1e-12)
        assert all(p[2] == z for _, pts in contours for p in pts)


def _same_points(a, b):
    """Two text contour files have the same planes and, per layer, the same points (loops may
    start elsewhere and come in another order)."""
    _, layers_a = read_text_contours(a)
    _, layers_b = read_text_contours(b)
    assert len(layers_a) == len(layers_b)
    for (za, ca), (zb, cb) in zip(layers_a, layers_b):
        assert za == zb
        assert sorted(p for _, pts in ca for p in pts) == sorted(p for _, pts in cb for p in pts)


def test_transfer_result_equals_direct(sliced):
    ms, _, target, _, tmp, _ = sliced
    t = ms.apply_filter("transfer_slicing_to_mesh", encoding_file=str(tmp / "s.enc"),
                        target_mesh=target, contour_file=str(tmp / "t.ctr"),
                        target_encoding_file=str(tmp / "t.enc"))
    assert set(t) == {"points", "layers", "transferred_layers", "resliced_layers", "through_map",
                      "max_plane_deviation", "dropped_contours", "unplaced_points", "transfer_seconds",
                      "seconds"}
    assert (t["through_map"], t["dropped_contours"], t["unplaced_points"]) == (0, 0, 0)
    assert 0 <= t["transfer_seconds"] <= t["seconds"]
    # Member 1 differs from member 0 in x-y only: every layer is certified and transferred.
    assert (t["layers"], t["transferred_layers"], t["resliced_layers"]) == (80, 80, 0)
    assert t["max_plane_deviation"] == 0.0
    ms.set_current_mesh(target)
    d = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS,
                        contour_file=str(tmp / "d.ctr"))
    assert d["points"] == t["points"] and d["layers"] == t["layers"]
    _same_points(tmp / "t.ctr", tmp / "d.ctr")


def _band_member_and_encoding(pymeshlab, make_family, encoding):
    """A MeshSet with members 0 and 1 of an arch family changed in z within one band of
    heights, member 0 sliced to `encoding`; returns it and member 1's id (current)."""
    m0, m1 = make_family("arch", 2, z_change="band")
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(m0))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, contour_file="",
                    encoding_file=str(encoding))
    ms.load_new_mesh(str(m1))
    return ms, ms.current_mesh_id()


def test_transfer_to_band_member_mixes_transfer_and_reslicing(pymeshlab, make_family, tmp_path):
    """A member changed in z within one band of heights: the band's layers are re-sliced, the
    rest transferred, and the result equals slicing the member directly (points; masks S = 1)."""
    ms, target = _band_member_and_encoding(pymeshlab, make_family, tmp_path / "s.enc")
    t = ms.apply_filter("transfer_slicing_to_mesh", encoding_file=str(tmp_path / "s.enc"),
                        target_mesh=target, contour_file=str(tmp_path / "t.ctr"))
    assert t["layers"] == t["transferred_layers"] + t["resliced_layers"] == 80
    assert t["resliced_layers"] > 0 and t["transferred_layers"] > 2 * t["resliced_layers"], t
    d = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS,
                        contour_file=str(tmp_path / "d.ctr"), encoding_file="")
    assert d["points"] == t["points"]
    _same_points(tmp_path / "t.ctr", tmp_path / "d.ctr")
    for name in ("t", "d"):
        ms.apply_filter("export_mask_images", contour_file=str(tmp_path / f"{name}.ctr"),
                        output_path=str(tmp_path / f"masks_{name}"))
    c = ms.apply_filter("compare_mask_stacks", stack_a=str(tmp_path / "masks_t"),
                        stack_b=str(tmp_path / "masks_d"))
    assert (c["layers"], c["min_similarity"], c["differing_pixels"]) == (80, 1.0, 0)


def test_barycentric_mode_reports_deviation(pymeshlab, sliced, make_family):
    # x-y member: the area coordinates keep every point on its plane (up to rounding).
    ms, _, target, _, tmp, _ = sliced
    t = ms.apply_filter("transfer_slicing_to_mesh", encoding_file=str(tmp / "s.enc"),
                        target_mesh=target, mode="barycentric", contour_file=str(tmp / "b.ctr"))
    assert t["points"] > 0 and t["max_plane_deviation"] < 1e-9
    _, layers = read_text_contours(tmp / "b.ctr")
    assert max(abs(p[2] - z) for z, cs in layers for _, pts in cs for p in pts) < 1e-9
    # Band member: points leave their planes inside the band, by the reported amount.
    ms, band = _band_member_and_encoding(pymeshlab, make_family, tmp / "band.enc")
    t = ms.apply_filter("transfer_slicing_to_mesh", encoding_file=str(tmp / "band.enc"),
                        target_mesh=band, mode="barycentric",
                        contour_file=str(tmp / "band.ctr"))
    _, layers = read_text_contours(tmp / "band.ctr")
    worst = max(abs(p[2] - z) for z, cs in layers for _, pts in cs for p in pts)
    assert t["max_plane_deviation"] > 1e-3
    assert worst == pytest.approx(t["max_plane_deviation"], abs=1e-12)  # the file has 17 digits


def test_a_printer_preset_by_name_makes_its_print_file(sliced, pymeshlab):
    # pymeshlab takes the printer by its id; the SL1S preset writes portrait 1620 x 2560 images
    # and its printer model, anti-aliased on request; a custom value with a preset is refused.
    ms, _, _, _, tmp, _ = sliced
    ms.apply_filter("export_mask_images", contour_file=str(tmp / "s.ctr"), output_path=str(tmp / "p.sl1s"),
                    printer="prusa_sl1s_speed", antialiasing=True)
    with zipfile.ZipFile(tmp / "p.sl1s") as z:
        assert "printerModel = SL1S\n" in z.read("config.ini").decode()
        png = z.read("p00000.png")
    width, height = struct.unpack(">II", png[16:24])
    assert (width, height, png[24], png[25]) == (1620, 2560, 8, 0)  # 8-bit grey
    first = png_pixels(png)
    assert first.shape == (2560, 1620) and (first == 255).sum() > 1000, "the part's first layer is lit"
    assert ((first > 0) & (first < 255)).sum() > 100, "anti-aliased edges"
    _raises(pymeshlab, ms, "export_mask_images",
            "printer prusa_sl1s_speed sets the display and exposure, but width_px were given too",
            contour_file=str(tmp / "s.ctr"), output_path=str(tmp / "q.sl1s"), printer="prusa_sl1s_speed",
            width_px=100)
    assert not (tmp / "q.sl1s").exists()


def test_an_elegoo_goo_file_holds_the_same_masks(sliced):
    # Export Mask Images into .goo: the format's version, magic and ending; Compare Mask Stacks
    # reads it against the .sl1 of the same layers: every mask equal.
    ms, _, _, r, tmp, _ = sliced
    profile = dict(width_px=256, height_px=192, pixel_size_x_um=300, pixel_size_y_um=300, antialiasing=True)
    m = ms.apply_filter("export_mask_images", contour_file=str(tmp / "s.ctr"), output_path=str(tmp / "p.goo"),
                        **profile)
    assert m["layers"] == r["layers"]
    data = (tmp / "p.goo").read_bytes()
    assert data[:12] == b"V3.0\x07\x00\x00\x00DLP\x00"
    assert data[-11:] == b"\x00\x00\x00\x07\x00\x00\x00DLP\x00"
    assert struct.unpack(">IHH", data[195310:195318]) == (r["layers"], 256, 192)
    ms.apply_filter("export_mask_images", contour_file=str(tmp / "s.ctr"), output_path=str(tmp / "p.sl1"),
                    **profile)
    c = ms.apply_filter("compare_mask_stacks", stack_a=str(tmp / "p.goo"), stack_b=str(tmp / "p.sl1"))
    assert c["layers"] == r["layers"] and c["min_similarity"] == 1.0 and c["differing_pixels"] == 0


def test_masks_and_compare_results(sliced):
    ms, source, target, r, tmp, _ = sliced
    profile = dict(width_px=256, height_px=192, pixel_size_x_um=300, pixel_size_y_um=300)
    m = ms.apply_filter("export_mask_images", contour_file=str(tmp / "s.ctr"),
                        output_path=str(tmp / "masks"), **profile)
    assert set(m) == {"layers", "ignored_open_contours", "outside_display", "part_min_x_mm",
                      "part_max_x_mm", "part_min_y_mm", "part_max_y_mm", "seconds"}
    assert m["outside_display"] == 0
    assert m["part_min_x_mm"] < m["part_max_x_mm"] and m["part_min_y_mm"] < m["part_max_y_mm"]
    assert m["layers"] == r["layers"] and m["ignored_open_contours"] == 0
    assert len(list((tmp / "masks").glob("*.png"))) == r["layers"]
    # An independently produced stack of the same member: sliced again to a binary file and
    # written as an .sl1 archive; every mask equal.
    ms.set_current_mesh(source)
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, file_format=1,
                    contour_file=str(tmp / "again.srb"), encoding_file="")
    ms.apply_filter("export_mask_images", contour_file=str(tmp / "again.srb"),
                    output_path=str(tmp / "again.sl1"), **profile)
    c = ms.apply_filter("compare_mask_stacks", stack_a=str(tmp / "masks"), stack_b=str(tmp / "again.sl1"),
                        report_file=str(tmp / "compare.csv"))
    assert set(c) == {"layers", "min_similarity", "worst_layer", "differing_pixels", "max_grey_difference",
                      "max_grey_difference_layer", "over_one_level_pixels", "over_one_level_share",
                      "over_one_level_layer", "seconds"}
    assert c["layers"] == r["layers"] and c["min_similarity"] == 1.0 and c["differing_pixels"] == 0
    assert (c["max_grey_difference"], c["over_one_level_pixels"], c["over_one_level_share"]) == (0, 0, 0.0)
    rows = (tmp / "compare.csv").read_text().splitlines()
    assert rows[0] == "layer,similarity,differing_pixels,max_grey_difference,over_one_level_pixels"
    assert rows[1:] == [f"{k},1,0,0,0" for k in range(r["layers"])]
    # Member 1's masks differ: the comparison sees it.
    ms.set_current_mesh(target)
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS,
                    contour_file=str(tmp / "m1.ctr"), encoding_file="")
    ms.apply_filter("export_mask_images", contour_file=str(tmp / "m1.ctr"),
                    output_path=str(tmp / "masks_m1"), **profile)
    c = ms.apply_filter("compare_mask_stacks", stack_a=str(tmp / "masks"), stack_b=str(tmp / "masks_m1"),
                        report_file=str(tmp / "m1.csv"))
    assert c["min_similarity"] < 1.0 and c["differing_pixels"] > 0
    assert 0 <= c["worst_layer"] < r["layers"]
    # Binary masks: every differing pixel is 0 against 255, so the grey figures follow S's.
    assert c["max_grey_difference"] == 255 and c["over_one_level_pixels"] == c["differing_pixels"]
    assert c["over_one_level_layer"] == c["worst_layer"]
    assert c["over_one_level_share"] == c["differing_pixels"] / (r["layers"] * 256 * 192)
    rows = [[float(x) for x in row.split(",")] for row in (tmp / "m1.csv").read_text().splitlines()[1:]]
    assert sum(row[2] for row in rows) == c["differing_pixels"]
    assert all(row[3] == (255 if row[2] else 0) and row[4] == row[2] for row in rows)
    assert c["max_grey_difference_layer"] == next(k for k, row in enumerate(rows) if row[2])


def test_preview_layer_is_an_edge_mesh_and_not_current(sliced):
    ms, source, _, _, _, _ = sliced
    ms.set_current_mesh(source)
    before = ms.mesh_number()
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, preview_layers=4)
    assert ms.mesh_number() == before + 1
    assert ms.current_mesh_id() == source
    preview = ms.mesh(before)  # ids count up from 0 in a MeshSet without deletions
    assert preview.face_number() == 0 and preview.edge_number() > 0
    assert preview.edge_number() == preview.vertex_number()  # closed loops only


@pytest.mark.parametrize("thickness", [0.0, -0.5])
def test_thickness_must_be_positive(pymeshlab, sliced, thickness):
    ms, _, _, _, tmp, _ = sliced
    _raises(pymeshlab, ms, "slice_mesh_with_encoding", "layer_thickness must be greater than 0",
            layer_thickness=thickness, contour_file=str(tmp / "x.ctr"))
    assert not (tmp / "x.ctr").exists()


def test_display_size_limit_is_the_core_one(pymeshlab, sliced):
    ms, _, _, _, tmp, _ = sliced
    _raises(pymeshlab, ms, "export_mask_images", "width_px must be between 1 and 65535 pixels (got 65536)",
            contour_file=str(tmp / "s.ctr"), output_path=str(tmp / "m"), width_px=65536)
    assert not (tmp / "m").exists()


def test_encoding_of_another_mesh_is_refused(pymeshlab, sliced, make_family):
    ms, source, _, _, tmp, _ = sliced
    ms.load_new_mesh(str(make_family("torus", 2)[1]))
    _raises(pymeshlab, ms, "transfer_slicing_to_mesh",
            ("Transfer Slicing to Mesh: the target mesh's faces differ from those of the mesh the encoding was made "
             f"from (encoding: {ms.mesh(source).face_number()} faces, hash ",
             f"; target: {ms.current_mesh().face_number()} faces, hash ", "); a target with other connectivity needs a "
             "cross-parameterization map (map file from Cross-Parameterize Meshes)"),
            encoding_file=str(tmp / "s.enc"), target_mesh=ms.current_mesh_id(),
            contour_file=str(tmp / "x.ctr"))
    assert not (tmp / "x.ctr").exists()


def test_missing_files_are_named(pymeshlab, sliced):
    ms, _, target, _, tmp, _ = sliced
    _raises(pymeshlab, ms, "transfer_slicing_to_mesh",
            f"Transfer Slicing to Mesh: cannot open '{tmp / 'missing.enc'}': No such file or directory",
            encoding_file=str(tmp / "missing.enc"), target_mesh=target)
    _raises(pymeshlab, ms, "export_mask_images",
            f"Export Mask Images: cannot open '{tmp / 'missing.ctr'}': No such file or directory",
            contour_file=str(tmp / "missing.ctr"), output_path=str(tmp / "m"))
    _raises(pymeshlab, ms, "compare_mask_stacks",
            f"Compare Mask Stacks: mask stack '{tmp / 'nothing'}' does not exist",
            stack_a=str(tmp / "nothing"), stack_b=str(tmp / "nothing"))
    folder = tmp / "no" / "such" / "dir"
    _raises(pymeshlab, ms, "slice_mesh_with_encoding",
            f"Slice Mesh with Encoding: contour_file: cannot write '{folder / 'x.ctr'}': folder '{folder}': "
            "No such file or directory",
            layer_thickness=THICKNESS, contour_file=str(folder / "x.ctr"))


def test_bad_mesh_id_and_contour_file_as_encoding(pymeshlab, sliced):
    ms, _, target, _, tmp, _ = sliced
    _raises(pymeshlab, ms, "transfer_slicing_to_mesh",
            "Transfer Slicing to Mesh: there is no mesh with id 99 (2 meshes are loaded)",
            encoding_file=str(tmp / "s.enc"), target_mesh=99)
    _raises(pymeshlab, ms, "transfer_slicing_to_mesh",
            f"Transfer Slicing to Mesh: '{tmp / 's.ctr'}', line 1: this is a contour file, expected an encoding file",
            encoding_file=str(tmp / "s.ctr"), target_mesh=target)


def test_interpreter_survives_errors(pymeshlab, sliced):
    ms, source, _, _, tmp, _ = sliced
    for _ in range(3):
        with pytest.raises(pymeshlab.PyMeshLabException):
            ms.apply_filter("slice_mesh_with_encoding", layer_thickness=-1)
    ms.set_current_mesh(source)
    assert ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS)["layers"] == 80


def test_no_current_mesh(pymeshlab):
    # A filter that also reads a mesh file (mesh_file) says it needs a mesh in its own words.
    _raises(pymeshlab, pymeshlab.MeshSet(), "slice_mesh_with_encoding",
            "Slice Mesh with Encoding: there is no current mesh: open a mesh first",
            layer_thickness=THICKNESS)


def test_truncated_or_corrupted_encoding_is_refused(pymeshlab, sliced):
    ms, source, target, r, tmp, _ = sliced
    ms.set_current_mesh(source)
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, file_format=1,
                    contour_file="", encoding_file=str(tmp / "s.srb"))
    data = (tmp / "s.srb").read_bytes()
    (tmp / "cut.srb").write_bytes(data[: len(data) // 2])
    flipped = bytearray(data)
    flipped[len(data) - 100] ^= 0x40  # inside the last section (t): caught by its checksum
    (tmp / "flip.srb").write_bytes(bytes(flipped))
    text = (tmp / "s.enc").read_text().splitlines(keepends=True)
    (tmp / "cut.enc").write_text("".join(text[: len(text) // 2]))
    said = {"cut.srb": (f"section 6 (t) ends at byte {len(data)}, beyond the end of the file ({len(data) // 2} "
                        "bytes): truncated file",),
            "flip.srb": ("section t: checksum mismatch, the file is corrupted",),
            "cut.enc": (f"the header announces {r['layers']} layers and {r['contours']} contours, the file has ",
                        "(truncated file?)")}
    for bad, (head, *rest) in said.items():
        _raises(pymeshlab, ms, "transfer_slicing_to_mesh", (f"Transfer Slicing to Mesh: '{tmp / bad}': {head}", *rest),
                encoding_file=str(tmp / bad), target_mesh=target, contour_file=str(tmp / "x.ctr"))
    assert not (tmp / "x.ctr").exists()


def test_unwritable_transfer_output_leaves_nothing(pymeshlab, sliced):
    ms, _, target, _, tmp, _ = sliced
    folder = tmp / "no" / "dir"
    _raises(pymeshlab, ms, "transfer_slicing_to_mesh",
            f"Transfer Slicing to Mesh: target_encoding_file: cannot write '{folder / 't.enc'}': folder '{folder}': "
            "No such file or directory",
            encoding_file=str(tmp / "s.enc"), target_mesh=target, contour_file=str(tmp / "t.ctr"),
            target_encoding_file=str(folder / "t.enc"))
    assert not (tmp / "t.ctr").exists()
