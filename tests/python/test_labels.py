"""Labels cut into members' bases (#36): from the members' file stems or a labels file, the same by
reuse as by direct slicing (--verify), each entry's height; a labels file missing a member fails
that member naming it; bad arguments are refused before any work."""
import json
import subprocess

import numpy as np
import pytest
from conftest import ROOT, THICKNESS, box_triangles, write_stl
import slicereuse_pymeshlab as sr


def write_boxes(folder, names, length=30.0):
    """Boxes length x 15 x 5 mm, each a little longer than the one before (one family: the same
    12 triangles), as STL files named names; returns their paths."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for i, name in enumerate(names):
        path = folder / name
        write_stl(path, box_triangles([0, 0, 0], [length + i, 15, 5]))
        paths.append(str(path))
    return paths


def test_family_cuts_each_members_stem_alike_by_reuse_and_direct(pymeshlab, tmp_path):
    source, a, b = write_boxes(tmp_path / "parts", ["src.stl", "CASE1.stl", "CASE2.stl"])
    r = sr.family(source, [a, b], THICKNESS, tmp_path / "out", profile={"printer": "prusa_sl1s_speed"},
                  verify=True, labels="names")
    assert r["failed"] == 0, r
    for entry in r["targets"]:
        assert entry["method"] == "reuse", entry
        assert entry["min_similarity"] == 1 and entry["max_grey_difference"] == 0, entry  # reuse = direct
    # "CASE1" is 31.7 mm long at 7.5 mm: the 31 mm box (29 mm inside its margins) holds it at
    # 6.75 mm, 28.5 mm long.
    assert r["targets"][0]["label_height_mm"] == pytest.approx(7.5 * 0.9)


def test_a_labels_file_names_the_member_it_lacks(pymeshlab, tmp_path):
    source, a, b = write_boxes(tmp_path / "parts", ["src.stl", "a.stl", "b.stl"])
    labels = tmp_path / "labels.csv"
    labels.write_text("member,label\na.stl,A-0412\n")
    r = sr.family(source, [a, b], THICKNESS, tmp_path / "out", profile={"printer": "prusa_sl1s_speed"},
                  labels=str(labels))
    assert r["failed"] == 1, r
    assert r["targets"][0]["label_height_mm"] > 0, r
    assert "has no label for member 'b.stl'" in r["targets"][1]["error"], r
    assert not (tmp_path / "out" / "b.sl1s").exists()


def family_py(*args):
    return subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"), "--layer-thickness",
                           str(THICKNESS), "--printer", "prusa_sl1s_speed", *map(str, args)],
                          capture_output=True, text=True)


def test_plates_refuse_a_label_that_fits_nowhere_unless_allowed_unlabelled(tmp_path):
    source, a = write_boxes(tmp_path / "parts", ["src.stl", "CASE1.stl"])
    [small] = write_boxes(tmp_path / "parts", ["LONGNAME12345.stl"], length=8)
    run = family_py("--plates", "--direct", "--labels", "--out", tmp_path / "out", source, a, small)
    assert run.returncode == 1, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    assert "the label 'LONGNAME12345' does not fit on the base of LONGNAME12345.stl" in plate["error"], plate
    assert not (tmp_path / "out" / "plate_1.sl1s").exists()
    run = family_py("--plates", "--direct", "--labels", "--allow-unlabelled", "--out", tmp_path / "out", source, a,
                    small)
    assert run.returncode == 0, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    heights = {m["name"]: m["label_height_mm"] for m in plate["members"]}
    assert heights == {"CASE1.stl": pytest.approx(7.5 * 0.9), "LONGNAME12345.stl": 0}, plate


def test_bad_label_arguments_are_refused_before_any_work(pymeshlab, tmp_path):
    source, a = write_boxes(tmp_path / "parts", ["src.stl", "a.stl"])
    bad = family_py("--allow-unlabelled", "--out", tmp_path / "bad", source, a)
    assert bad.returncode == 2 and "--allow-unlabelled goes with --labels" in bad.stderr, bad.stderr
    with pytest.raises(ValueError, match="labels must be None, \"names\" or a labels file"):
        sr.plates(source, [a], THICKNESS, tmp_path / "none", labels=str(tmp_path / "missing.csv"))
    assert not (tmp_path / "none").exists()


def test_add_labels_shows_the_label_a_job_cuts(pymeshlab, tmp_path):
    [box] = write_boxes(tmp_path / "parts", ["CASE1.stl"])
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(box)
    shown = ms.apply_filter("add_labels", layer_thickness=THICKNESS)
    assert shown["label_height_mm"] == pytest.approx(7.5 * 0.81)  # "CASE1" on a 30 mm base (28 mm inside)
    assert ms.mesh_number() == 2 and ms.current_mesh().vertex_number() > 0  # the outline's layer
    job = ms.apply_filter("make_print_job", mesh_file=box, layer_thickness=THICKNESS, labels=True,
                          output_path=str(tmp_path / "job.sl1s"), printer="prusa_sl1s_speed")
    assert job["label_height_mm"] == shown["label_height_mm"]


def test_family_hollows_labels_and_reuses_alike(pymeshlab, tmp_path):
    """--hollow and --labels together: each member hollowed, drained and labelled (the letters 3 mm
    deep, 1 mm less than the walls), the same by reuse as by direct slicing; its cavity drains
    through one hole in its base, so the check finds no resin trap. Walls too thin for letters
    are refused first."""
    source, a = write_boxes(tmp_path / "parts", ["src.stl", "CASE1.stl"])
    for name in ("src.stl", "CASE1.stl"):  # 30 x 15 x 15 mm: room for 4 mm walls and the 2 mm closing
        write_stl(tmp_path / "parts" / name, box_triangles([0, 0, 0], [30 + (name == "CASE1.stl"), 15, 15]))
    with pytest.raises(ValueError, match="labels on hollowed members need walls over 1.5 mm thick"):
        sr.family(source, [a], THICKNESS, tmp_path / "none", labels="names", hollow=1)
    run = family_py("--hollow", 4, "--labels", "--verify", "--out", tmp_path / "out", source, a)
    assert run.returncode == 0, run.stderr
    [entry] = json.loads(run.stdout)["targets"]
    assert entry["method"] == "reuse" and entry["min_similarity"] == 1 and entry["max_grey_difference"] == 0, entry
    # The cavity: the box less 4 mm walls (23 x 7 x 7 mm), its edges rounded by the closing; one
    # drain hole opens it through the base.
    assert 0.8 * 23 * 7 * 7 < entry["cavity_mm3"] < 23 * 7 * 7, entry
    assert entry["drain_holes"] == 1 and entry["label_height_mm"] > 0, entry
    assert entry["printability"]["resin_traps"] == 0 and entry["printability"]["suction_cups"] == 0, entry


def write_tall_boxes(folder, names):
    """Boxes 30 x 15 x 12 mm, each a millimetre longer than the one before (one family), as STL
    files named names; returns their paths."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for i, name in enumerate(names):
        write_stl(folder / name, box_triangles([0, 0, 0], [30 + i, 15, 12]))
        paths.append(str(folder / name))
    return paths


def test_family_cuts_labels_into_a_side_alike_by_reuse_and_direct(pymeshlab, tmp_path):
    source, a, b = write_tall_boxes(tmp_path / "parts", ["src.stl", "CASE1.stl", "CASE2.stl"])
    r = sr.family(source, [a, b], THICKNESS, tmp_path / "out", profile={"printer": "prusa_sl1s_speed"},
                  verify=True, labels="names", label_side="front")
    assert r["failed"] == 0, r
    for entry in r["targets"]:
        assert entry["method"] == "reuse", entry
        assert entry["min_similarity"] == 1 and entry["max_grey_difference"] == 0, entry  # reuse = direct
    # "CASE1" at 6.75 mm is 28.5 mm long, 30.5 with its 1 mm margins: the 31 mm front holds it, the
    # 12 mm height too (1 mm clear above and below).
    assert [e["label_height_mm"] for e in r["targets"]] == [pytest.approx(7.5 * 0.9)] * 2, r
    # The side's label is not the base's: the files differ.
    base = sr.family(source, [a], THICKNESS, tmp_path / "base", profile={"printer": "prusa_sl1s_speed"},
                     labels="names")
    assert base["failed"] == 0, base
    assert (tmp_path / "base" / "CASE1.sl1s").read_bytes() != (tmp_path / "out" / "CASE1.sl1s").read_bytes()


def test_plates_refuse_a_side_label_that_fits_nowhere_unless_allowed_unlabelled(tmp_path):
    source, a = write_tall_boxes(tmp_path / "parts", ["src.stl", "CASE1.stl"])
    narrow = tmp_path / "parts" / "NARROW.stl"
    write_stl(narrow, box_triangles([0, 0, 0], [31, 6, 12]))  # its left side is 6 mm wide
    run = family_py("--plates", "--direct", "--labels", "--label-side", "left", "--out", tmp_path / "out", source, a,
                    narrow)
    assert run.returncode == 1, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    assert "the label 'NARROW' fits nowhere on the left side of NARROW.stl" in plate["error"], plate
    run = family_py("--plates", "--direct", "--labels", "--label-side", "left", "--allow-unlabelled", "--out",
                    tmp_path / "out", source, a, narrow)
    assert run.returncode == 0, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    heights = {m["name"]: m["label_height_mm"] for m in plate["members"]}
    assert heights["NARROW.stl"] == 0 and heights["CASE1.stl"] > 0, plate


def test_bad_label_side_arguments_are_refused_before_any_work(pymeshlab, tmp_path):
    source, a = write_tall_boxes(tmp_path / "parts", ["src.stl", "a.stl"])
    bad = family_py("--label-side", "front", "--out", tmp_path / "bad", source, a)
    assert bad.returncode == 2 and "--label-side goes with --labels" in bad.stderr, bad.stderr
    bad = family_py("--labels", "--label-side", "top", "--out", tmp_path / "bad", source, a)
    assert bad.returncode == 2 and "invalid choice: 'top'" in bad.stderr, bad.stderr
    with pytest.raises(ValueError, match="label_side must be one of base, front, back, left, right, not 'top'"):
        sr.family(source, [a], THICKNESS, tmp_path / "none", labels="names", label_side="top")
    with pytest.raises(ValueError, match="label_side='back' goes with labels"):
        sr.plates(source, [a], THICKNESS, tmp_path / "none", label_side="back")
    assert not (tmp_path / "bad").exists() and not (tmp_path / "none").exists()


def test_add_labels_shows_a_side_label_where_a_job_cuts_it(pymeshlab, tmp_path):
    [box] = write_tall_boxes(tmp_path / "parts", ["CASE1.stl"])
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(box)
    shown = ms.apply_filter("add_labels", layer_thickness=THICKNESS, label_side=sr.LABEL_SIDES.index("right"))
    # "CASE1" on the 15 mm right side: 2.905 mm high (12.3 mm long, 14.3 with its margins), centred.
    assert shown["label_height_mm"] == pytest.approx(7.5 * 0.9 ** 9), shown
    assert (shown["x_mm"], shown["y_mm"], shown["angle_deg"]) == (pytest.approx(30), pytest.approx(7.5), 0), shown
    job = ms.apply_filter("make_print_job", mesh_file=box, layer_thickness=THICKNESS, labels=True,
                          label_side=sr.LABEL_SIDES.index("right"), output_path=str(tmp_path / "job.sl1s"),
                          printer="prusa_sl1s_speed")
    assert job["label_height_mm"] == shown["label_height_mm"]
